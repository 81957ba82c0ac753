#pragma once
// Interior point solvers of min 1/2 v^T Q v - b^T v s.t. A v <= d (Tanoh, Renard, Noll):
//   "primal-dual": Newton on the perturbed KKT system through the condensed system (24),
//                  with slack variables (formulation (9)), so any initial guess is accepted;
//                  Mehrotra predictor-corrector centering (default) or the paper's fixed
//                  mu factor with backtracking on the merit function 1/2 ||F||^2;
//   "primal":      Algorithm 3.1, the log-barrier method with inner Newton loops, Armijo
//                  backtracking with the fraction-to-boundary rule (28) and the adaptive
//                  gamma of section 4; the initial guess is shifted into the interior.
// Every Newton system is a truncated Krylov solve with H = Q + A^T D A applied matrix-free.
#include <Teuchos_ParameterList.hpp>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/IterationObserver.hpp"
#include "signorini/solver/SolveResult.hpp"

namespace signorini {

class InteriorPointSolver {
 public:
  // The "Solver" parameter list with defaults, documentation and validators.
  static Teuchos::ParameterList validParameters();

  // `params` is validated here (unknown names, types and ranges); throws InputError.
  explicit InteriorPointSolver(const Teuchos::ParameterList& params = Teuchos::ParameterList());

  // Solves from `initialGuess` (zero if null). The observer, if any, sees every Newton step.
  SolveResult solve(const ContactQP& qp, const Vector* initialGuess = nullptr,
                    IterationObserver* observer = nullptr) const;

  const Teuchos::ParameterList& parameters() const { return params_; }

 private:
  Teuchos::ParameterList params_;
};

}  // namespace signorini
