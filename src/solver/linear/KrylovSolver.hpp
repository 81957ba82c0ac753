#pragma once
// A Belos Krylov solve of one linear system, to a relative residual tolerance.
// The "Belos" sublist is passed to the Belos solver unchanged.
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace Belos {
template <class ScalarType, class MV, class OP>
class SolverManager;
}

namespace signorini {

struct KrylovResult {
  int iterations = 0;
  bool converged = false;
  double relativeResidual = 0.0;  // ||b - A x|| / ||b||, as Belos measured it
};

class KrylovSolver {
 public:
  // "solver": CG (default), MINRES, GMRES, or any other name Belos' SolverFactory knows;
  // "Belos": sublist handed to the Belos solver as it is.
  static Teuchos::ParameterList validParameters();

  explicit KrylovSolver(const Teuchos::ParameterList& params = validParameters());

  // Solves A x = b from the initial x, preconditioned by M (may be null), until
  // ||b - A x|| <= tol ||b|| or maxIterations. With startReduction > 0 the target is instead
  // max(floor ||b||, min(tol ||b||, startReduction min(||r0||, ||b||))), where r0 = b - A x0 is
  // the starting residual (Belos computes it anyway: no extra product).
  KrylovResult solve(const RCP<const Operator>& A, const RCP<const Operator>& M,
                     const RCP<const MultiVector>& b, const RCP<MultiVector>& x, double tol,
                     int maxIterations, double startReduction = 0.0, double floor = 0.0) const;

  const std::string& solverName() const { return solver_; }

 private:
  using BelosSolver = Belos::SolverManager<Scalar, MultiVector, Operator>;

  std::string solver_;
  Teuchos::ParameterList belos_;
  // Made and configured at the first solve; later solves only set the tolerance and the
  // iteration limit (a Belos solver is not cheap to make: its parameter lists and status tests).
  mutable RCP<BelosSolver> belosSolver_;
  mutable bool skipLastPreconditioning_ = false;

  BelosSolver& belosSolver(double tol, int maxIterations) const;
};

}  // namespace signorini
