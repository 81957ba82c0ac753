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

/// Which rank readQP() gives each node: `AsWritten`, equal shares in the files' node order;
/// `Metis`, METIS' parts of Q's node graph (nodes keep their numbers, each rank holds the nodes
/// of its part); `Auto`, METIS' parts where they cut at most half the node couplings the
/// equal shares cut (a code that numbers its nodes cell by cell), else the equal shares.
enum class QPPartition { Auto, AsWritten, Metis };

/// A QP read from files, with what its preconditioners may use of them.
struct QPFromFiles {
  ContactQP qp;
  MultigridInput multigrid;  ///< block size, coordinates and, with cells.mtx, the grid
  bool repartitioned = false;     ///< the nodes are METIS' parts, not equal shares in file order
  double crossRankCouplings = 0;  ///< fraction of Q's node couplings between ranks
  double crossRankCouplingsInFileOrder = 0;  ///< the same for equal shares in file order
};

/// Reads a QP written as writeQP() writes it. The unknowns are distributed by whole nodes,
/// so that a node's DOFs stay together (as MueLu and the rigid body modes need): an equal
/// share of them on every rank, or METIS' parts as `partition` says (global numbers are the
/// files' either way), and each constraint goes to the rank of its row's first
/// unknown (a nodal constraint then lives with its node); the block size is the
/// number of columns of coords.mtx. With an optional cells.mtx (P1 cells of the mesh, node
/// numbers of their vertices) for a P2/P3 space, MultigridInput::grid is their SimplexGrid.
/// Collective. Throws InputError naming the file and what is wrong (missing, not Matrix
/// Market, sizes that disagree, cells naming nodes that do not exist).
QPFromFiles readQP(const std::string& directory, const RCP<const Comm>& comm,
                   QPPartition partition = QPPartition::Auto);

}  // namespace signorini
