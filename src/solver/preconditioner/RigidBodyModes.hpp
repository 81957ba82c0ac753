#pragma once
// The rigid body modes of linear elasticity (3 in 2D, 6 in 3D), the near-nullspace that
// multigrid for elasticity needs.
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// On `dofMap`, whose local DOF dim * i + c is component c of the node in row i of
// `nodeCoordinates` (dim columns, one row per owned node). Collective.
RCP<MultiVector> rigidBodyModes(const RCP<const Map>& dofMap, const MultiVector& nodeCoordinates);

}  // namespace signorini
