#pragma once
// Private to the library: the part of a box mesh that each rank of a DistributedSpace makes
// for itself, with no global mesh anywhere. Rank r takes block r of a BoxDecomposition. A node
// of the P_k space is named by its point on the lattice of spacing h/k; it is owned by the
// lowest-numbered block whose closed region holds it (a node on a block face is a node of
// both blocks, the subdivision being conforming) and numbered by its owner, owned nodes in
// the order of the owner's space and ranks in order. The other ranks learn the ids through
// a Tpetra Import over the lattice points.
#include <memory>

#include "assembly/MeshPart.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/BoxMesh.hpp"
#include "fe/LagrangeSpace.hpp"

namespace signorini::detail {

struct DistributedBoxPart {
  MeshPart part;  // without its mesh and node coordinates: `mesh` and `space` hold them
  std::shared_ptr<const SimplexMesh> mesh;
  std::unique_ptr<LagrangeSpace> space;  // the P_k space on `mesh`, which numbered the part's nodes
  long long numGlobalNodes = 0, numGlobalCells = 0;
};

// Collective; `blocks` has one block per rank of comm.
DistributedBoxPart makeBoxMeshPart(const RCP<const Comm>& comm, const BoxGrid& box, const BoxDecomposition& blocks,
                                   int degree);

}  // namespace signorini::detail
