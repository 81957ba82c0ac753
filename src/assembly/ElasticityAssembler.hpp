#pragma once
// Parallel assembly of the contact QP of linear elasticity on a distributed P_k space: the
// stiffness Q (OverlapStiffness, Dirichlet conditions by symmetric elimination keeping
// the DOFs), loads b, contact constraints A v <= d (ProblemDefinition's ContactFormulation:
// one row per contact node: -n_o . u(p) <= g(p), or its weighted gap, see
// ContactMultiplierBasis), rigid body modes and node coordinates.
#include <optional>
#include <vector>

#include "assembly/DistributedSpace.hpp"
#include "assembly/MatrixFreeElasticityOperator.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/GeometricGrid.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

// With `assembleStiffness` false, Q is left null (for a matrix-free Q) and only the rest is
// assembled.
ContactQP assembleContactQP(const DistributedSpace& space, const ProblemDefinition& problem,
                            bool assembleStiffness = true);

// What the space gives the multigrid of every mesh: its block size (the dimension), the
// coordinates of the owned nodes and, for bodies meshed apart, each node's body. Grids are
// the problem builder's. Collective.
MultigridInput meshMultigridInput(const DistributedSpace& space);

// The P1 stiffness of `grid`, the space's mesh (a MeshVertexGrid or a BoxGrid of the same
// cells) or, if grid.refinesFineCells(), that mesh split at the nodes (LagrangeBasis::
// subSimplices): DOF dim * (grid vertex) + component, prescribed DOFs (those of the P_k space
// at the vertices) eliminated to unit rows (MultigridInput::gridStiffness). On the mesh's own
// grid it is P^T Q P for Q of assembleContactQP and P the P1 interpolation from the grid that
// the geometric multigrid uses. Rows on a one-to-one map of the vertices of each rank's
// cells. Collective.
RCP<CrsMatrix> assembleGridStiffness(const DistributedSpace& space, const ProblemDefinition& problem,
                                     const GeometricGrid& grid);

// Q of assembleContactQP applied cell by cell, with the same Dirichlet elimination; shares
// the space.
RCP<MatrixFreeElasticityOperator> matrixFreeStiffness(const std::shared_ptr<const DistributedSpace>& space,
                                                      const ProblemDefinition& problem);

// The contact nodes this rank owns, as space node ids in constraint order: row first + k of
// A is node nodes[k]. Each rank holds its nodes of every pair, pair after pair (those of pair
// p are nodes[pairStart[p] .. pairStart[p + 1])), each pair's in the order of the renumbered
// nodes, so each rank owns the contiguous range [first, first + nodes.size()) of the
// numGlobal constraints. A node on the contact boundaries of two pairs has a row in each. A
// pair between two bodies has rows at the slave nodes that its master boundary covers only
// (coveredSlaveNodes). Collective.
struct OwnedContactNodes {
  GlobalOrdinal first = 0;
  long long numGlobal = 0;
  std::vector<long long> nodes;
  std::vector<std::size_t> pairStart;  ///< one more than there are pairs
};
OwnedContactNodes ownedContactNodes(const DistributedSpace& space, const ProblemDefinition& problem);

// The constraint (row of A) of pair `pair` at each overlap node, in overlapSpaceNodes() order;
// -1 for a node off its contact boundary. Ghosts learn theirs from their owners. Collective.
std::vector<long long> overlapNodeConstraints(const DistributedSpace& space, const ProblemDefinition& problem,
                                              std::size_t pair);

// The contact boundary's measure lumped to the contact nodes, on A's range map: HRZ lumping
// of the P_k basis for nodal constraints (positive for every degree), the integral of the
// multiplier function psi for weighted gaps (between bodies, over the part of Gamma_c that
// the master covers). Each node stands for this much of Gamma_c. Every pair's, or only those of `onlyPair` (0 on the other rows).
RCP<Vector> contactNodeWeights(const DistributedSpace& space, const ProblemDefinition& problem,
                               const RCP<const Map>& constraintMap, std::optional<std::size_t> onlyPair = std::nullopt);

}  // namespace signorini
