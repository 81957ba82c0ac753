#pragma once
// Whether a contact QP holds its body. A rigid body motion r (a combination of the QP's
// rigid body modes) with Q r = 0 is one no prescribed displacement removes; frictionless
// contact can stop it only in the obstacle's direction. If no constraint row moves under r,
// Q + AᵀDA is singular; if the load pulls along r and no constraint resists (A r <= 0,
// bᵀr > 0), the energy has no minimum. Either way the solver would spend its Krylov limit
// before failing, so the problem is refused before the solve, with the motion named.
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

// Throws an InputError (on every rank) naming the first rigid body motion that nothing
// holds or that the load pulls free. Returns the rigid body motions no prescribed
// displacement removes (those the contact alone holds), orthonormal columns on Q's domain
// map; null if there are none or the QP has no rigid body modes (multigrid.nearNullspace(qp)).
// Collective; costs one application of Q and of A to the modes.
RCP<const MultiVector> checkRigidBodyMotionsHeld(const ContactQP& qp, const MultigridInput& multigrid);

}  // namespace signorini
