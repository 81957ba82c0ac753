#pragma once
// An exact solve with a small distributed matrix, for the coarsest level of a multigrid
// hierarchy: the matrix is gathered to rank 0 and factored there on a one-rank communicator
// (LocalDirectSolver: CHOLMOD's Cholesky, or KLU2's LU if it is not positive definite); each application
// gathers the right-hand side to rank 0 and scatters the solution back.
// Why: an algebraic hierarchy rebuilt at every Newton step for a matrix of a few hundred
// unknowns costs more than the factorization, and solves only approximately.
#include <memory>

#include "signorini/core/TpetraTypes.hpp"
#include "solver/preconditioner/MultilevelPreconditioner.hpp"

namespace signorini {

class GatheredDirectSolver : public MultilevelPreconditioner {
 public:
  GatheredDirectSolver();
  ~GatheredDirectSolver() override;

  // Gathers and factors A (nonsingular; its row, range and domain maps the same set of rows).
  // `reuse` is ignored: the Cholesky factorization keeps its ordering and analysis while the
  // pattern stays. Operators handed out before stay valid. Collective.
  void compute(const RCP<CrsMatrix>& A, bool reuse = false) override;
  // Y = alpha A^-1 X + beta Y for the last A computed.
  RCP<Operator> getOperator() const override;

 private:
  struct Factorization;
  class RootSolve;
  std::shared_ptr<Factorization> factorization_;
  RCP<Operator> op_;
};

}  // namespace signorini
