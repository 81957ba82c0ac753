#pragma once
// Parallel assembly of the contact QP of linear elasticity on a distributed P_k space: the
// stiffness Q (OverlapStiffness, Dirichlet conditions by symmetric elimination keeping
// the DOFs), loads b, contact constraints A v <= d (ProblemDefinition's ContactFormulation:
// one row per contact node: -n_o . u(p) <= g(p), or its weighted gap, see
// ContactMultiplierBasis), rigid body modes and node coordinates.
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
// A is node nodes[k]. Constraints follow the renumbered nodes, so each rank owns the
// contiguous range [first, first + nodes.size()) of the numGlobal constraints. Collective.
struct OwnedContactNodes {
  GlobalOrdinal first = 0;
  long long numGlobal = 0;
  std::vector<long long> nodes;
};
OwnedContactNodes ownedContactNodes(const DistributedSpace& space, const ProblemDefinition& problem);

// The constraint (row of A) of each overlap node, in overlapSpaceNodes() order; -1 for a node
// off the contact boundary. Ghosts learn theirs from their owners. Collective.
std::vector<long long> overlapNodeConstraints(const DistributedSpace& space, const ProblemDefinition& problem);

// The contact boundary's measure lumped to the contact nodes, on A's range map: HRZ lumping
// of the P_k basis for nodal constraints (positive for every degree), the integral of the
// multiplier function psi for weighted gaps. Each node stands for this much of Gamma_c.
RCP<Vector> contactNodeWeights(const DistributedSpace& space, const ProblemDefinition& problem,
                               const RCP<const Map>& constraintMap);

}  // namespace signorini
