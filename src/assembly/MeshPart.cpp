#include "assembly/MeshPart.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <type_traits>

#include <Teuchos_CommHelpers.hpp>

#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

// Flat byte buffer of length-prefixed arrays of plain values.
class Packer {
 public:
  template <class T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    putBytes(values.size(), values.data(), values.size() * sizeof(T));
  }
  void put(const std::string& text) { putBytes(text.size(), text.data(), text.size()); }
  std::vector<char>& bytes() { return bytes_; }

 private:
  void putBytes(std::size_t count, const void* data, std::size_t size) {
    const long long n = static_cast<long long>(count);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof n + size);
    std::memcpy(&bytes_[at], &n, sizeof n);
    if (size > 0) std::memcpy(&bytes_[at + sizeof n], data, size);
  }
  std::vector<char> bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  void get(std::vector<T>& values) {
    values.resize(count());
    getBytes(values.data(), values.size() * sizeof(T));
  }
  void get(std::string& text) {
    text.resize(count());
    getBytes(&text[0], text.size());
  }

 private:
  std::size_t count() {
    long long n = 0;
    getBytes(&n, sizeof n);
    return static_cast<std::size_t>(n);
  }
  void getBytes(void* data, std::size_t size) {
    if (at_ + size > bytes_.size()) throw Error("mesh part: truncated message");
    if (size > 0) std::memcpy(data, &bytes_[at_], size);
    at_ += size;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

// MPI counts are ints: large buffers go in pieces.
constexpr long long kChunk = 1 << 30;

// The arrays of a part, in message order: one list for sender and receiver.
template <class Part, class Visit>
void forEachArray(Part& part, Visit&& visit) {
  visit(part.mesh.vertices);
  visit(part.mesh.cells);
  visit(part.mesh.facets);
  visit(part.mesh.facetTags);
  visit(part.mesh.cellTags);
  visit(part.globalCells);
  visit(part.nodeIds);
  visit(part.nodeOwners);
  visit(part.nodeCoordinates);
  visit(part.boundaryTags);
  visit(part.boundaryStart);
  visit(part.boundaryNodes);
  visit(part.cellEdges);
  visit(part.cellFaces);
  visit(part.edgeOwners);
  visit(part.faceOwners);
  visit(part.nearFacets);
  visit(part.nearFacetTags);
  visit(part.entityCounts);
  visit(part.nearGeometryFacets);
  visit(part.nearGeometryEdges);
  visit(part.nearGeometryFacetEntities);
  visit(part.nearGeometryEdgeEntities);
}

}  // namespace

// Each rank asks the owners of its other nodes for their ids, by key: only the shared nodes'
// keys travel, where maps over all keys would need Tpetra's distributed directory, an
// all-to-all exchange of every key.
std::vector<GlobalOrdinal> ownerOrderedIds(const RCP<const Comm>& comm, const std::vector<GlobalOrdinal>& keys,
                                           const std::vector<int>& owners, long long& numGlobalNodes,
                                           const std::vector<long long>& order) {
  const int rank = comm->getRank();
  std::vector<GlobalOrdinal> result(keys.size(), -1);
  long long numOwned = 0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::size_t n = order.empty() ? i : static_cast<std::size_t>(order[i]);
    if (owners[n] == rank) result[n] = numOwned++;
  }
  long long upTo = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, 1, &numOwned, &upTo);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &numOwned, &numGlobalNodes);
  std::vector<std::pair<GlobalOrdinal, GlobalOrdinal>> idOfOwnedKey;  // (key, id), by key
  idOfOwnedKey.reserve(numOwned);
  std::vector<std::vector<long long>> asked(comm->getSize());
  for (std::size_t n = 0; n < keys.size(); ++n) {
    if (owners[n] == rank) {
      result[n] += upTo - numOwned;
      idOfOwnedKey.emplace_back(keys[n], result[n]);
    } else {
      asked[owners[n]].push_back(keys[n]);
    }
  }
  std::sort(idOfOwnedKey.begin(), idOfOwnedKey.end());

  std::vector<std::vector<long long>> answers = exchangeWithRanks(*comm, asked);
  bool known = true;
  for (std::vector<long long>& block : answers)
    for (long long& key : block) {
      const auto it = std::lower_bound(idOfOwnedKey.begin(), idOfOwnedKey.end(), std::make_pair(key, GlobalOrdinal(-1)));
      const bool found = it != idOfOwnedKey.end() && it->first == key;
      known = known && found;
      key = found ? it->second : -1;
    }
  if (!onEveryRank(*comm, known)) throw Error("mesh part: a rank asked for a node its owner does not hold");
  answers = exchangeWithRanks(*comm, answers);
  std::vector<std::size_t> next(comm->getSize(), 0);
  for (std::size_t n = 0; n < keys.size(); ++n)
    if (owners[n] != rank) result[n] = answers[owners[n]][next[owners[n]]++];
  return result;
}

void sendMeshPart(const Comm& comm, const MeshPart& part, int destination) {
  Packer p;
  p.put(std::vector<int>{part.mesh.dim});
  for (const auto* named : {&part.mesh.boundaryTags, &part.mesh.bodyTags}) {
    std::vector<int> tags;
    for (const auto& [name, tag] : *named) {
      p.put(name);
      tags.push_back(tag);
    }
    p.put(tags);
  }
  forEachArray(part, [&](const auto& values) { p.put(values); });
  const std::vector<char>& bytes = p.bytes();
  const long long sizes[3] = {static_cast<long long>(bytes.size()),
                              static_cast<long long>(part.mesh.boundaryTags.size()),
                              static_cast<long long>(part.mesh.bodyTags.size())};
  Teuchos::send(comm, 3, sizes, destination);
  for (long long at = 0; at < sizes[0]; at += kChunk)
    Teuchos::send(comm, static_cast<int>(std::min(kChunk, sizes[0] - at)), bytes.data() + at, destination);
}

MeshPart receiveMeshPart(const Comm& comm, int source) {
  long long sizes[3] = {0, 0, 0};
  Teuchos::receive(comm, source, 3, sizes);
  std::vector<char> bytes(sizes[0]);
  for (long long at = 0; at < sizes[0]; at += kChunk)
    Teuchos::receive(comm, source, static_cast<int>(std::min(kChunk, sizes[0] - at)), bytes.data() + at);

  MeshPart part;
  Unpacker u(bytes);
  std::vector<int> dim;
  u.get(dim);
  if (dim.size() != 1) throw Error("mesh part: malformed message");
  part.mesh.dim = dim[0];
  for (int k = 0; k < 2; ++k) {
    std::vector<std::string> names(sizes[1 + k]);
    for (std::string& name : names) u.get(name);
    std::vector<int> tags;
    u.get(tags);
    if (tags.size() != names.size()) throw Error("mesh part: malformed message");
    auto& named = k == 0 ? part.mesh.boundaryTags : part.mesh.bodyTags;
    for (std::size_t i = 0; i < names.size(); ++i) named[names[i]] = tags[i];
  }
  forEachArray(part, [&](auto& values) { u.get(values); });
  return part;
}

}  // namespace signorini::detail
