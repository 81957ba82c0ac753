#pragma once
// The key of a mesh entity of at most three vertices (a vertex, an edge, a face) by its vertex
// ids or node tags: the ids in ascending order, padded with -1. Every cell that lists the
// entity's vertices, in any order, gives it the same key.
#include <array>

namespace signorini::detail {

using SortedVertexKey = std::array<long long, 3>;

inline SortedVertexKey sortedVertexKey(const long long* ids, int count) {
  SortedVertexKey key{-1, -1, -1};
  for (int i = 0; i < count; ++i) {  // insertion: at most three ids
    int j = i;
    for (; j > 0 && key[j - 1] > ids[i]; --j) key[j] = key[j - 1];
    key[j] = ids[i];
  }
  return key;
}

}  // namespace signorini::detail
