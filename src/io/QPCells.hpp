#pragma once
// Private to the library: the cells.mtx of a QP directory (doc/qp-format.md), the P1 cells of
// the mesh a P2/P3 problem was assembled on, which readQP makes the multigrid's grid of.
#include <string>

#include "assembly/DistributedSpace.hpp"

namespace signorini::detail {

// Writes every rank's cells (their vertices' renumbered node ids, the numbering of the QP's
// unknowns) into directory/cells.mtx. Collective; rank 0 writes.
void writeCells(const DistributedSpace& space, const std::string& directory);

}  // namespace signorini::detail
