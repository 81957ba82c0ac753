#pragma once
// Private to the library: the serial phase of a DistributedSpace, on rank 0 only. The global
// P_k space, the METIS partition of the cells, the node owners and the contiguous
// renumbering, and the cutting of all that into one MeshPart per rank.
#include <cstddef>
#include <vector>

#include "assembly/MeshPart.hpp"
#include "fe/LagrangeSpace.hpp"
#include "fe/SimplexMesh.hpp"

namespace signorini::detail {

class GlobalPartition {
 public:
  // Keeps a reference to the mesh, which must outlive it. Throws InputError for an
  // inconsistent mesh or a bad degree, Error if METIS fails.
  GlobalPartition(const SimplexMesh& mesh, int degree, int numParts);

  long long numNodes() const { return space_.numNodes(); }
  long long numCells() const { return mesh_.numCells(); }

  int cellPart(long long cell) const { return cellPart_[cell]; }
  GlobalOrdinal nodeId(long long node) const { return newId_[node]; }

  // The part of one rank: its cells, and the node data of the space built on them.
  MeshPart part(int rank);

  // Heap bytes of the global space and of the partition arrays (not the mesh's).
  std::size_t bytes() const;

 private:
  const SimplexMesh& mesh_;
  LagrangeSpace space_;
  std::vector<int> cellPart_, nodeOwner_;
  std::vector<GlobalOrdinal> newId_;
  // Cells and boundary facets of each part, in global order (CSR over parts); a facet goes
  // with the cell it is a face of.
  std::vector<long long> cellStart_, partCells_, facetStart_, partFacets_;
  // Global boundary nodes of each tag, sorted.
  std::vector<int> tags_;
  std::vector<std::vector<long long>> tagNodes_;
  std::vector<long long> localNode_;  // scratch for part(): part-local id of a global node, or -1
};

}  // namespace signorini::detail
