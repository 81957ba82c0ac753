#pragma once
// Parallel assembly of the contact QP of linear elasticity on a distributed P_k space: the
// stiffness Q (Tpetra::FECrsMatrix, Dirichlet conditions by symmetric elimination keeping
// the DOFs), loads b, contact constraints A v <= d (one row per contact node:
// -n_o . u(p) <= g(p)), rigid body modes and node coordinates.
#include <vector>

#include "signorini/ContactQP.hpp"
#include "signorini/DistributedSpace.hpp"
#include "signorini/ProblemDefinition.hpp"

namespace signorini {

ContactQP assembleContactQP(const DistributedSpace& space, const ProblemDefinition& problem);

// Space node ids of the contact nodes in constraint order (row k of A is node k of this list).
std::vector<long long> contactNodeOrder(const DistributedSpace& space, const ProblemDefinition& problem);

// The contact boundary's measure lumped to its nodes (HRZ lumping, positive for every
// degree), on A's range map: the contact pressure is -lambda_i / w_i.
RCP<Vector> contactNodeWeights(const DistributedSpace& space, const ProblemDefinition& problem,
                               const RCP<const Map>& constraintMap);

// Rigid body modes (3 in 2D, 6 in 3D) of the space on its owned DOF map.
RCP<MultiVector> rigidBodyModes(const DistributedSpace& space);

}  // namespace signorini
