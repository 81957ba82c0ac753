#pragma once
/// \file
/// The contact QP as Matrix Market files (doc/qp-format.md): what `signorini --export-qp`
/// writes and `signorini --qp` solves, for handing a problem between Signorini and other
/// codes. Files: Q.mtx, b.mtx, A.mtx, d.mtx and coords.mtx, DOFs interlaced by node.
#include <string>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

/// Writes Q (which must be assembled: assembledStiffness()), b, A, d and the node coordinates
/// (multigrid.coordinates) into `directory` (created if missing). Collective; rank 0 writes.
/// Throws InputError if Q is not assembled or the coordinates are missing, OutputError if a
/// file cannot be written.
void writeQP(const ContactQP& qp, const MultigridInput& multigrid, const std::string& directory);

/// A QP read from files, with what its preconditioners may use of them.
struct QPFromFiles {
  ContactQP qp;
  MultigridInput multigrid;  ///< block size, coordinates and, with cells.mtx, the grid
};

/// Reads a QP written as writeQP() writes it. The unknowns are distributed by whole nodes,
/// an equal share of them on every rank, so that a node's DOFs stay together (as MueLu and
/// the rigid body modes need), and each constraint goes to the rank of its row's first
/// unknown (a nodal constraint then lives with its node); the block size is the
/// number of columns of coords.mtx. With an optional cells.mtx (P1 cells of the mesh, node
/// numbers of their vertices) for a P2/P3 space, MultigridInput::grid is their SimplexGrid.
/// Collective. Throws InputError naming the file and what is wrong (missing, not Matrix
/// Market, sizes that disagree, cells naming nodes that do not exist).
QPFromFiles readQP(const std::string& directory, const RCP<const Comm>& comm);

}  // namespace signorini
