#pragma once
// Parallel assembly of the contact QP of linear elasticity on a distributed P_k space: the
// stiffness Q (Tpetra::FECrsMatrix, Dirichlet conditions by symmetric elimination keeping
// the DOFs), loads b, contact constraints A v <= d (ProblemDefinition's ContactFormulation:
// one row per contact node, -n_o . u(p) <= g(p), or one per contact vertex, the weighted
// gap), rigid body modes and node coordinates.
#include <vector>

#include "signorini/ContactQP.hpp"
#include "signorini/DistributedSpace.hpp"
#include "signorini/ProblemDefinition.hpp"

namespace signorini {

ContactQP assembleContactQP(const DistributedSpace& space, const ProblemDefinition& problem);

// The basis of the multipliers on a contact facet: the space's P_k basis for nodal
// constraints, P1 for weighted gaps. Its local node a is the cell's local node a (vertices
// come first in every P_k basis), so cellNodes(cell)[a] is its space node.
LagrangeBasis contactMultiplierBasis(const LagrangeSpace& space, const ProblemDefinition& problem);

// The contact nodes that carry a constraint (every node of Gamma_c, or its vertices for
// weighted gaps) this rank owns, as space node ids in constraint order: row first + k of
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

// The contact boundary's measure lumped to the constraint nodes, on A's range map: HRZ
// lumping of the P_k basis for nodal constraints (positive for every degree), the integral
// of the hat function for weighted gaps. Each constraint node stands for this much of Gamma_c.
RCP<Vector> contactNodeWeights(const DistributedSpace& space, const ProblemDefinition& problem,
                               const RCP<const Map>& constraintMap);

}  // namespace signorini
