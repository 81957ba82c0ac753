#pragma once
// Private to the library: the part of a box mesh that each rank of a DistributedSpace makes
// for itself, with no global mesh anywhere. Rank r takes block r of a BoxDecomposition. A node
// of the P_k space is named by its point on the lattice of spacing h/k; it is owned by the
// lowest-numbered block whose closed region holds it (a node on a block face is a node of
// both blocks, the subdivision being conforming) and numbered by its owner, owned nodes in
// the order of the owner's space and ranks in order. The other ranks learn the ids through
// a Tpetra Import over the lattice points.
#include "assembly/MeshPart.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/BoxMesh.hpp"

namespace signorini::detail {

// Collective; `blocks` has one block per rank of comm.
PartWithSpace makeBoxMeshPart(const RCP<const Comm>& comm, const BoxGrid& box, const BoxDecomposition& blocks,
                              int degree);

}  // namespace signorini::detail
