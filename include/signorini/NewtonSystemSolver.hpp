#pragma once
// Solves the Newton systems H dv = r of the interior point methods, H = Q + A^T D A applied
// matrix-free, by a preconditioned Belos Krylov method to an absolute residual tolerance
// (the truncated Newton step). The preconditioner is chosen by the "Preconditioner" list:
//   "none";
//   "amg of Q":  MueLu on Q, set up once and reused for every step;
//   "amg of H":  MueLu on the assembled Q + A^T D A (assembled for the preconditioner only),
//                rebuilt each step, with MueLu's "reuse: type" if the MueLu list sets it.
#include <memory>

#include <Teuchos_ParameterList.hpp>

#include "signorini/BarrierHessianOperator.hpp"
#include "signorini/ContactQP.hpp"
#include "signorini/KrylovSolver.hpp"
#include "signorini/MueLuPreconditioner.hpp"

namespace signorini {

class NewtonSystemSolver {
 public:
  // Sublists "Krylov" (see KrylovSolver) and "Preconditioner".
  static Teuchos::ParameterList validParameters();

  NewtonSystemSolver(const ContactQP& qp, const Teuchos::ParameterList& params);

  // Sets D and refreshes the preconditioner as its strategy says.
  void setWeights(const Vector& D);

  // Solves H x = r from x = 0 until ||r - H x|| <= absoluteTolerance.
  KrylovResult solve(const Vector& r, Vector& x, double absoluteTolerance);

  const BarrierHessianOperator& hessian() const { return *H_; }
  int maxIterations() const { return maxIterations_; }

 private:
  RCP<BarrierHessianOperator> H_;
  KrylovSolver krylov_;
  std::string strategy_;
  int maxIterations_;
  std::unique_ptr<MueLuPreconditioner> amg_;
  bool reuseHierarchy_ = false;
  bool amgReady_ = false;
};

}  // namespace signorini
