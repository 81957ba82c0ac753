#pragma once
// A hash of a short sequence of integers (node tags, ids): SplitMix64's mixing folded over
// them, good in its low bits too, so that it can be taken modulo a rank count.
#include <cstdint>

namespace signorini {

template <class Iterator>
std::uint64_t splitMixHash(Iterator first, Iterator last) {
  std::uint64_t h = 0;
  for (; first != last; ++first) {
    h ^= static_cast<std::uint64_t>(*first) + 0x9e3779b97f4a7c15ULL;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return h;
}

}  // namespace signorini
