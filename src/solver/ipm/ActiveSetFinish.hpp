#pragma once
// The last step of the primal-dual method once its active set has settled: the equality-
// constrained problem on that set, A_i v = d_i for the constraints held and y_i = 0 for the
// others, solved by one Newton step, and kept if it meets every KKT tolerance.
//
// The barrier iterations converge superlinearly where strict complementarity holds; at the
// edge of the contact zone, nodes whose gap and multiplier both vanish (degenerate pairs)
// fall only linearly with mu, and on fine meshes such nodes add main iterations at the end
// of the solve. The finish settles them in one step, as an active set method would.
//
// The held constraints carry a penalty weight W_i >= D_i = y_i / s_i, large enough that the
// violation it leaves is far below the tolerance (ActiveSetCriterion::weight); with
// dy_i = W_i (A_i dv + r_p,i - s_i) on the held set and dy_i = -y_i elsewhere, the step is
//   (Q + A^T W A) dv = -r_d - A^T u,   u_i = W_i (r_p,i - s_i) held, -y_i released,
// one truncated Krylov solve with the Newton systems' solver and preconditioner.
#include <optional>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {

// The primal-dual iterate (v, s, y), lambda = -y, and its residuals r_d = Q v - b + A^T y,
// r_p = A v + s - d.
struct PrimalDualIterate {
  const Vector& v;
  const Vector& s;
  const Vector& y;
  const Vector& lambda;
  const Vector& rd;
  const Vector& rp;
};

class ActiveSetFinish {
 public:
  // `tolerance`: the KKT tolerance (Solver/kkt: tolerance).
  ActiveSetFinish(const ContactQP& qp, NewtonSystemSolver& newton, double tolerance);

  // Estimates the active set of the iterate (ActiveSetCriterion). True when a finish is worth
  // trying: every KKT measure is within the square root of the tolerance, the last two steps
  // were long (at least 0.9) and left the estimate unchanged but at nearly degenerate
  // constraints (multiplier and slack both within 1% of their scales), and it was not tried
  // before.
  // Collective; call once per main iteration.
  bool settled(const PrimalDualIterate& x, const KKTMeasures& kkt, double lastStep);

  struct Outcome {
    bool accepted = false;
    int krylovIterations = 0;
  };
  // Tries the finish on the estimated set. A first solve reduces its starting residual
  // tenfold; if the multipliers' signs or the released constraints' gaps then show the set
  // wrong, the set is corrected once (one primal-dual active set step) and solved again.
  // Only a set whose trial point is feasible to the solve's accuracy is solved to the end.
  // Accepted: the point is in v() and lambda(). Collective.
  Outcome attempt(const PrimalDualIterate& x);

  const Vector& v() const { return vTrial_; }
  const Vector& lambda() const { return lambdaTrial_; }

 private:
  const ContactQP& qp_;
  NewtonSystemSolver& newton_;
  const double tolerance_, bnorm_;
  Vector active_, previous_, tried_;  // 1 on the constraints held, 0 elsewhere
  int unchangedSteps_ = -1;           // steps in a row that kept the estimate (-1: none yet)
  bool haveTried_ = false;
  std::optional<ActiveSetCriterion> criterion_;  // of the iterate settled() last saw
  Vector W_, u_, Adv_, lambdaTrial_;  // on the constraints
  Vector rhs_, dv_, vTrial_;          // on the displacements

  void setSystem(const PrimalDualIterate& x);
  KKTMeasures trial(const PrimalDualIterate& x);
  bool correctSet();
  bool differs(const Vector& a, const Vector& b) const;
  // Whether the estimate changed from the last main iteration's at a constraint that is not
  // nearly degenerate (ActiveSetCriterion::isNearlyDegenerate). Collective.
  bool changedBeyondDegenerate(const PrimalDualIterate& x) const;
};

}  // namespace signorini::detail
