#pragma once
/// \file
/// Interior point solvers of min 1/2 v^T Q v - b^T v s.t. A v <= d (Tanoh, Renard, Noll):
///   "primal-dual": Newton on the perturbed KKT system through the condensed system (24),
///                  with slack variables (formulation (9)), so any initial guess is accepted;
///                  Mehrotra predictor-corrector centering (default) or the paper's fixed
///                  mu factor with backtracking on the merit function 1/2 ||F||^2;
///   "primal":      Algorithm 3.1, the log-barrier method with inner Newton loops, Armijo
///                  backtracking with the fraction-to-boundary rule (28) and the adaptive
///                  gamma of section 4; the initial guess is shifted into the interior.
/// Every Newton system is a truncated Krylov solve with H = Q + A^T D A applied matrix-free.
#include <Teuchos_ParameterList.hpp>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/IterationObserver.hpp"
#include "signorini/solver/MultigridInput.hpp"
#include "signorini/solver/SolveResult.hpp"

namespace signorini {

/// The interior point solver with its validated "Solver" parameters (doc/parameters.md).
/// Cheap to construct; one solver may solve many QPs, one at a time.
class InteriorPointSolver {
 public:
  /// The "Solver" parameter list with defaults, documentation and validators.
  static Teuchos::ParameterList validParameters();

  /// `params` is validated here (unknown names, types and ranges); throws InputError.
  explicit InteriorPointSolver(const Teuchos::ParameterList& params = Teuchos::ParameterList());

  /// Solves from `initialGuess` (zero if null; on Q's domain map), preconditioned with what
  /// `multigrid` gives. The observer, if any, sees every Newton step. Collective over the
  /// communicator of qp's maps; the result owns new vectors v and lambda. Throws InputError
  /// for a QP that is incomplete or inconsistent, or a parameter that does not fit it (an AMG
  /// for a matrix-free Q); solver failures are reported in the result's status.
  SolveResult solve(const ContactQP& qp, const MultigridInput& multigrid = MultigridInput(),
                    const Vector* initialGuess = nullptr, IterationObserver* observer = nullptr) const;

  const Teuchos::ParameterList& parameters() const { return params_; }

 private:
  Teuchos::ParameterList params_;
};

}  // namespace signorini
