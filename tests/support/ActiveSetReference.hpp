#pragma once
// An independent solver of min 1/2 v^T Q v - b^T v s.t. A v <= d for the tests: the
// primal-dual active set method (semismooth Newton), each active set's system solved to
// round-off by a sparse Cholesky factorization. It shares nothing with the interior point
// code but the QP and that factorization (CHOLMOD, which the multigrid uses on its coarsest grid).
// The QP must live on a one-rank communicator.
#include "signorini/solver/ContactQP.hpp"

namespace signorini::testing {

struct ReferenceSolution {
  RCP<Vector> v;
  double objective = 0;
  int iterations = 0;
  long long active = 0;
  bool converged = false;
};

ReferenceSolution activeSetSolve(const ContactQP& qp, int maxIterations = 100);

}  // namespace signorini::testing
