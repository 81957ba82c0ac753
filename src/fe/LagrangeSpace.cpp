#include "fe/LagrangeSpace.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Up to three sorted entries, padded with -1. With degree <= 3 a node's lattice point has
// at most three nonzero a_i, and a facet at most three vertices.
using Key = std::array<long long, 3>;

// Open-addressing hash map Key -> long long with linear probing: millions of nodes need a
// flat table, not a node-based map.
class KeyTable {
 public:
  explicit KeyTable(std::size_t expectedSize) {
    std::size_t capacity = 16;
    while (capacity < 2 * expectedSize) capacity *= 2;
    rehash(capacity);
  }

  // The value stored for key; stores `value` first if the key is new.
  long long findOrInsert(const Key& key, long long value) {
    std::size_t slot = hash(key) & mask_;
    while (keys_[slot][0] != -1) {
      if (keys_[slot] == key) return values_[slot];
      slot = (slot + 1) & mask_;
    }
    keys_[slot] = key;
    values_[slot] = value;
    if (2 * ++size_ > keys_.size()) rehash(2 * keys_.size());
    return value;
  }

  // The value stored for key, -1 if absent.
  long long find(const Key& key) const {
    for (std::size_t slot = hash(key) & mask_; keys_[slot][0] != -1; slot = (slot + 1) & mask_)
      if (keys_[slot] == key) return values_[slot];
    return -1;
  }

 private:
  static std::size_t hash(const Key& key) {
    std::uint64_t h = 0;
    for (long long entry : key) {  // splitmix64 finaliser over each entry
      h ^= static_cast<std::uint64_t>(entry) + 0x9e3779b97f4a7c15ULL;
      h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
      h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
  }

  void rehash(std::size_t capacity) {
    std::vector<Key> oldKeys(capacity, Key{-1, -1, -1});
    std::vector<long long> oldValues(capacity);
    oldKeys.swap(keys_);
    oldValues.swap(values_);
    mask_ = capacity - 1;
    for (std::size_t i = 0; i < oldKeys.size(); ++i) {
      if (oldKeys[i][0] == -1) continue;
      std::size_t slot = hash(oldKeys[i]) & mask_;
      while (keys_[slot][0] != -1) slot = (slot + 1) & mask_;
      keys_[slot] = oldKeys[i];
      values_[slot] = oldValues[i];
    }
  }

  std::vector<Key> keys_;
  std::vector<long long> values_;
  std::size_t size_ = 0;
  std::size_t mask_ = 0;
};

// Sorts the first `size` entries (insertion sort: at most three of them).
Key sortedKey(Key key, int size) {
  for (int i = 1; i < size; ++i)
    for (int j = i; j > 0 && key[j - 1] > key[j]; --j) std::swap(key[j - 1], key[j]);
  return key;
}

// The boundary facets by their sorted vertices, every vertex of one marked in onBoundary.
KeyTable boundaryFacetIndex(const SimplexMesh& mesh, std::vector<char>& onBoundary) {
  const int d = mesh.dim;
  KeyTable facetIndex(mesh.numFacets());
  for (long long facet = 0; facet < mesh.numFacets(); ++facet) {
    Key key = {-1, -1, -1};
    for (int v = 0; v < d; ++v) {
      key[v] = mesh.facets[d * facet + v];
      if (key[v] < 0 || key[v] >= mesh.numVertices())
        throw InputError("mesh: facet " + std::to_string(facet) + " references a missing vertex");
      onBoundary[key[v]] = 1;
    }
    if (facetIndex.findOrInsert(sortedKey(key, d), facet) != facet)
      throw InputError("mesh: boundary facet " + std::to_string(facet) + " is listed twice");
  }
  return facetIndex;
}

// The boundary facets among the faces of `cell` (those whose vertices all lie on boundary
// facets and which are listed) get the cell and their local index.
void attachBoundaryFacets(const SimplexMesh& mesh, long long cell, const std::vector<char>& onBoundary,
                          KeyTable& facetIndex, std::vector<std::pair<long long, int>>& facetCells) {
  const int d = mesh.dim;
  const long long* vertex = mesh.cells.data() + (d + 1) * cell;
  int boundaryVertices = 0;
  for (int v = 0; v <= d; ++v) {
    if (vertex[v] < 0 || vertex[v] >= mesh.numVertices())
      throw InputError("mesh: cell " + std::to_string(cell) + " references a missing vertex");
    boundaryVertices += onBoundary[vertex[v]];
  }
  for (int f = 0; boundaryVertices >= d && f <= d; ++f) {
    if (boundaryVertices - onBoundary[vertex[f]] < d) continue;  // facet f has an interior vertex
    Key key = {-1, -1, -1};
    for (int v = 0, n = 0; v <= d; ++v)
      if (v != f) key[n++] = vertex[v];
    const long long facet = facetIndex.find(sortedKey(key, d));
    if (facet < 0) continue;
    if (facetCells[facet].first != -1)
      throw InputError("mesh: boundary facet " + std::to_string(facet) + " is shared by two cells");
    facetCells[facet] = {cell, f};
  }
}

// The nodes of a P_k cell, into `nodes`. A node (lattice point a) is identified by the
// vertices it lies between and its lattice weights on them: new ones are numbered from
// numNodes on, their coordinates appended to nodeCoordinates unless given.
void numberCellNodes(const SimplexMesh& mesh, const LagrangeBasis& basis, long long cell, KeyTable& nodeIndex,
                     long long* nodes, long long& numNodes, std::vector<double>* nodeCoordinates) {
  const int d = mesh.dim, degree = basis.degree(), nodesPerCell = basis.size();
  const long long* vertex = mesh.cells.data() + (d + 1) * cell;
  for (int local = 0; local < nodesPerCell; ++local) {
    const auto& a = basis.latticeIndices()[local];
    if (local <= d) {  // the vertices, first in the local order
      nodes[local] = vertex[local];
      continue;
    }
    Key key = {-1, -1, -1};
    int size = 0;
    for (int i = 0; i <= d; ++i)
      if (a[i] > 0) key[size++] = vertex[i] << 2 | a[i];  // a_i <= 3 fits two bits
    key = sortedKey(key, size);
    nodes[local] = nodeIndex.findOrInsert(key, numNodes);
    if (nodes[local] != numNodes) continue;
    ++numNodes;
    if (!nodeCoordinates) continue;
    // Summed in key order (by vertex id), not cell order: the value is the node's own,
    // the same whichever cell meets it first and in any part numbered in global order.
    for (int j = 0; j < d; ++j) {
      double x = 0.0;
      for (int i = 0; i < size; ++i) x += (key[i] & 3) * mesh.vertices[d * (key[i] >> 2) + j];
      nodeCoordinates->push_back(x / degree);
    }
  }
}

}  // namespace

LagrangeSpace::LagrangeSpace(const SimplexMesh& mesh, int degree) : mesh_(&mesh), basis_(mesh.dim, degree) {
  build(nullptr);
}

LagrangeSpace::LagrangeSpace(const SimplexMesh& mesh, int degree, const std::vector<double>& nonVertexCoordinates)
    : mesh_(&mesh), basis_(mesh.dim, degree) {
  build(&nonVertexCoordinates);
}

void LagrangeSpace::build(const std::vector<double>* nonVertexCoordinates) {
  const SimplexMesh& mesh = *mesh_;
  const int d = mesh.dim, degree = basis_.degree();
  const long long numVertices = mesh.numVertices(), numCells = mesh.numCells(), numFacets = mesh.numFacets();
  if (mesh.vertices.size() % d != 0 || mesh.cells.size() % (d + 1) != 0 || mesh.facets.size() % d != 0 ||
      mesh.facetTags.size() != static_cast<std::size_t>(numFacets))
    throw InputError("mesh: array sizes do not fit dimension " + std::to_string(d));

  // Boundary facets are found as cell faces whose vertices all lie on boundary facets.
  std::vector<char> onBoundary(numVertices, 0);
  KeyTable facetIndex = boundaryFacetIndex(mesh, onBoundary);
  facetCells_.assign(numFacets, {-1, -1});
  if (degree > 1) nodeCoordinates_ = mesh.vertices;
  numNodes_ = numVertices;
  KeyTable nodeIndex(degree > 1 ? numCells : 0);
  if (degree > 1) cellNodes_.resize(static_cast<std::size_t>(basis_.size()) * numCells);
  for (long long cell = 0; cell < numCells; ++cell) {
    attachBoundaryFacets(mesh, cell, onBoundary, facetIndex, facetCells_);
    if (degree > 1)
      numberCellNodes(mesh, basis_, cell, nodeIndex, &cellNodes_[static_cast<std::size_t>(basis_.size()) * cell],
                      numNodes_, nonVertexCoordinates ? nullptr : &nodeCoordinates_);
  }

  if (nonVertexCoordinates) {
    if (nonVertexCoordinates->size() != static_cast<std::size_t>(d * (numNodes_ - numVertices)))
      throw InputError("P" + std::to_string(degree) + " space: " + std::to_string(nonVertexCoordinates->size()) +
                       " coordinates given for " + std::to_string(numNodes_ - numVertices) + " nodes past the vertices");
    nodeCoordinates_.insert(nodeCoordinates_.end(), nonVertexCoordinates->begin(), nonVertexCoordinates->end());
  }
  for (long long facet = 0; facet < numFacets; ++facet)
    if (facetCells_[facet].first == -1)
      throw InputError("mesh: boundary facet " + std::to_string(facet) + " is not a face of any cell");
}

std::vector<long long> LagrangeSpace::boundaryNodes(int tag) const {
  const auto& lattice = basis_.latticeIndices();
  std::vector<long long> nodes;
  for (const auto& [cell, f] : boundaryFacets(tag)) {
    const long long* cellNode = cellNodes(cell);
    for (int local = 0; local < nodesPerCell(); ++local)
      if (lattice[local][f] == 0) nodes.push_back(cellNode[local]);  // on the facet opposite vertex f
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<std::pair<long long, int>> LagrangeSpace::boundaryFacets(int tag) const {
  std::vector<std::pair<long long, int>> result;
  for (std::size_t facet = 0; facet < facetCells_.size(); ++facet)
    if (mesh_->facetTags[facet] == tag) result.push_back(facetCells_[facet]);
  return result;
}

std::size_t LagrangeSpace::bytes() const {
  return cellNodes_.capacity() * sizeof(long long) + nodeCoordinates_.capacity() * sizeof(double) +
         facetCells_.capacity() * sizeof(facetCells_[0]);
}

}  // namespace signorini
