#pragma once
// An independent solver of min 1/2 v^T Q v - b^T v s.t. A v <= d for the tests: the
// primal-dual active set method (semismooth Newton), each active set's system solved to
// round-off by a sparse Cholesky factorization. It shares nothing with the interior point
// code but the QP and that factorization (CHOLMOD, which the multigrid uses on its coarsest grid).
// The QP must live on a one-rank communicator.
#include <Teuchos_ParameterList.hpp>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini::testing {

struct ReferenceSolution {
  RCP<Vector> v;
  double objective = 0;
  int iterations = 0;
  long long active = 0;
  bool converged = false;
};

ReferenceSolution activeSetSolve(const ContactQP& qp, int maxIterations = 100);

// max |v - v_ref| / max |v_ref| for v, the solution of the QP built from `problem` (whose
// coordinates `multigrid` holds) on
// any rank count, and v_ref the active-set reference of the same problem assembled and solved
// on rank 0 alone; compared node by node at the nodes' coordinates, since the rank count
// renumbers the nodes. The same on every rank; infinite if the reference did not converge.
// Collective.
double differenceToReference(const Teuchos::ParameterList& problem, const MultigridInput& multigrid, const Vector& v);

}  // namespace signorini::testing
