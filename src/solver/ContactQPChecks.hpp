#pragma once
// What InteriorPointSolver::solve() checks of a ContactQP before anything else, so that a QP
// built by another code fails in one line in the terms of the API rather than deep inside
// MueLu or Belos: the pieces present, their maps consistent, whole nodes on every rank, the
// entries finite, Q symmetric (checked on a random pair of vectors).
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

// Throws InputError (on every rank) naming the member and what to change. Collective.
void checkContactQP(const ContactQP& qp, const MultigridInput& multigrid);

}  // namespace signorini
