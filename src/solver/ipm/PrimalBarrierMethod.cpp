// Algorithm 3.1 of the paper: the primal log-barrier method
//   psi(v, mu) = J(v) - mu sum log(d - A v)_i,  grad psi = Q v - b + A^T (mu / s),
//   H = Q + A^T diag(mu / s^2) A,  s = d - A v > 0,
// with inner truncated Newton loops to ||grad psi|| < zeta_k, Armijo backtracking from the
// fraction-to-boundary step (28), zeta_{k+1} = delta zeta_k, mu_{k+1} = gamma_{k+1} mu_k and
// the adaptive gamma of section 4. The initial guess is made strictly feasible by a shift
// along A^T ("shift") or by the relaxed set S_varsigma of section 3.2 ("relaxed"). Beyond the
// paper, each new barrier subproblem may start from a predictor step along the central path
// ("primal: extrapolation", Fiacco and McCormick's extrapolation).
#include <cmath>
#include <cstdio>
#include <limits>

#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/ParameterValidation.hpp"
#include "signorini/core/Error.hpp"
#include "solver/ipm/InteriorPointMethods.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {
namespace {

// sum_i log(1 + alpha ds_i / s_i): the change of sum log s along a step, computed without
// the cancellation that would make tiny decreases of psi invisible near the solution.
double logChange(const Vector& s, double alpha, const Vector& ds) {
  auto sd = s.getData();
  auto dd = ds.getData();
  return sumOverEntries(*s.getMap()->getComm(), s.getLocalLength(),
                        [&](std::size_t i) { return std::log1p(alpha * dd[i] / sd[i]); });
}

double globalMin(const Vector& x) {
  double local = std::numeric_limits<double>::infinity();
  auto xd = x.getData();
  for (std::size_t i = 0; i < x.getLocalLength(); ++i) local = std::min(local, xd[i]);
  return minOverRanks(*x.getMap()->getComm(), local);
}

void shiftAll(Vector& x, double shift) {
  auto xd = x.getDataNonConst();
  for (std::size_t i = 0; i < x.getLocalLength(); ++i) xd[i] += shift;
}

// Moves v along A^T so that every slack d - A v is at least `margin`. Exact when the rows of
// A touch disjoint unknowns (one row per contact node), which makes A A^T diagonal.
void shiftIntoInterior(const ContactQP& qp, Vector& v, double margin) {
  const auto cmap = qp.A->getRangeMap();
  CrsMatrix pattern(*qp.A, Teuchos::Copy);
  pattern.resumeFill();
  pattern.setAllToScalar(1.0);
  pattern.fillComplete(qp.A->getDomainMap(), cmap);
  Vector ones(cmap), rowsPerUnknown(v.getMap());
  ones.putScalar(1.0);
  pattern.apply(ones, rowsPerUnknown, Teuchos::TRANS);
  if (rowsPerUnknown.normInf() > 1.0)
    throw InputError("Solver/method \"primal\": the rows of A share unknowns, so no strictly feasible point "
                     "can be built from the initial guess; use method \"primal-dual\" (or, for weighted gaps "
                     "of P2 tetrahedra, Problem/Contact/formulation \"nodal\")");

  Vector rowNorm2(cmap), s(cmap), w(cmap);
  {
    auto rn = rowNorm2.getDataNonConst();
    for (std::size_t i = 0; i < cmap->getNodeNumElements(); ++i) {
      CrsMatrix::nonconst_local_inds_host_view_type cols("cols", qp.A->getNumEntriesInLocalRow(i));
      CrsMatrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
      size_t count = 0;
      qp.A->getLocalRowCopy(i, cols, vals, count);
      for (size_t j = 0; j < count; ++j) rn[i] += vals(j) * vals(j);
    }
  }
  qp.A->apply(v, s);
  s.update(1.0, *qp.d, -1.0);
  {
    auto sd = s.getData();
    auto rn = rowNorm2.getData();
    auto wd = w.getDataNonConst();
    for (std::size_t i = 0; i < s.getLocalLength(); ++i) {
      if (rn[i] == 0.0) {
        if (sd[i] <= 0) throw InputError("constraint with an empty row of A and d <= 0 is infeasible");
        continue;
      }
      wd[i] = std::min(0.0, sd[i] - margin) / rn[i];
    }
  }
  qp.A->apply(w, v, Teuchos::TRANS, 1.0, 1.0);
}

// The adaptive gamma of the paper's section 4: lowered after several main iterations in a
// row with few inner iterations, raised after one with many.
struct GammaRule {
  bool adaptive;
  int few, successive;
  double decrease, min, increase, max;
  int fewInARow = 0;

  explicit GammaRule(const Teuchos::ParameterList& p)
      : adaptive(p.get<bool>("gamma: adaptive")),
        few(p.get<int>("gamma: few inner iterations")),
        successive(p.get<int>("gamma: successive main iterations")),
        decrease(p.get<double>("gamma: decrease factor")),
        min(p.get<double>("gamma: min")),
        increase(p.get<double>("gamma: increase factor")),
        max(p.get<double>("gamma: max")) {}

  double next(double gamma, int inner) {
    if (!adaptive) return gamma;
    fewInARow = inner < few ? fewInARow + 1 : 0;
    if (fewInARow >= successive) {
      fewInARow = 0;
      return std::max(min, decrease * gamma);
    }
    return inner > few ? std::min(max, increase * gamma) : gamma;
  }
};

// One primal barrier solve: main iterations over barrier subproblems min psi(., mu_k), each
// solved by inner damped Newton steps to ||grad psi|| < zeta_k.
class PrimalBarrierMethod {
 public:
  PrimalBarrierMethod(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p, const Vector* v0,
                      const RCP<const MultiVector>& freeMotions);
  SolveResult run(IterationObserver& observer, Teuchos::Time& timer);

 private:
  void start();
  bool solveSubproblem(int k, IterationObserver& observer, Teuchos::Time& timer);
  double evaluate();
  bool newtonStep(int k, double gnorm, IterationObserver& observer, Teuchos::Time& timer);
  void solveDirection(double tighter, bool fromDirection);
  bool lineSearch(double& alpha);
  void record(int k, double alpha, IterationObserver& observer, Teuchos::Time& timer);
  void nextSubproblem();
  void extrapolate(double previousMu, double dvarsigma);

  const ContactQP& qp_;
  const MultigridInput& multigrid_;
  const Teuchos::ParameterList& p_;
  const bool freeWithoutContact_;
  const long long m_;
  const StoppingRule stop_;
  const int maxInner_;
  const double delta_, tau_, fractionToBoundary_, bnorm_;
  const bool relaxed_, extrapolate_;
  GammaRule gammaRule_;
  ForcingRule forcing_;
  NewtonSystemSolver newton_;
  SolveResult result_;

  RCP<Vector> v_;
  Vector s_, y_, lambda_, D_, Adv_, minusAdv_;  // on the constraints
  Vector Qv_, g_, dv_, Qdv_, rhs_;              // on the displacements

  double mu_ = 0, zeta_ = 0, gamma_ = 0;
  double varsigma_ = 0;         // relaxation of S_varsigma, 0 once back on the original set
  double displacementScale_ = 1;
  int inner_ = 0;               // Newton steps of the current subproblem
  double tolerance_ = 0;        // the forcing's Krylov tolerance of the current step
  int krylov_ = 0;              // Krylov iterations of the current step
  double slope_ = 0;            // g^T dv of the current direction
};

PrimalBarrierMethod::PrimalBarrierMethod(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p, const Vector* v0,
                                   const RCP<const MultiVector>& freeMotions)
    : qp_(qp),
      multigrid_(multigrid),
      p_(p),
      freeWithoutContact_(!freeMotions.is_null()),
      m_(qp.A->getRangeMap()->getGlobalNumElements()),
      stop_(p),
      maxInner_(p.get<int>("primal: maximum inner iterations")),
      delta_(p.get<double>("primal: delta")),
      tau_(p.get<double>("primal: tau")),
      fractionToBoundary_(p.get<double>("primal: fraction to boundary")),
      bnorm_(qp.b->norm2()),
      relaxed_(choice<StartingPoint>(p, "primal: starting point") == StartingPoint::Relaxed),
      extrapolate_(p.get<bool>("primal: extrapolation")),
      gammaRule_(p),
      forcing_(forcingRule(p, 0.1 * stop_.tolerance * bnorm_)),
      newton_(qp, multigrid, p, freeMotions),
      v_(initialDisplacement(qp, v0)),
      s_(qp.A->getRangeMap()), y_(s_.getMap()), lambda_(s_.getMap()), D_(s_.getMap()), Adv_(s_.getMap()),
      minusAdv_(s_.getMap()),
      Qv_(qp.Q->getDomainMap()), g_(Qv_.getMap()), dv_(Qv_.getMap()), Qdv_(Qv_.getMap()), rhs_(Qv_.getMap()) {}

// A strictly feasible start, the first barrier parameter and inner tolerance.
void PrimalBarrierMethod::start() {
  newton_.setWeights(D_);
  const ProblemScales scales = problemScales(qp_, multigrid_, newton_, *v_, freeWithoutContact_);
  result_.krylovIterations += scales.krylovIterations;
  displacementScale_ = scales.displacement;
  const double margin = p_.get<double>("primal: starting margin") * scales.displacement;
  if (!relaxed_) shiftIntoInterior(qp_, *v_, margin);
  mu_ = p_.get<double>("primal: mu0");
  zeta_ = p_.get<double>("primal: zeta0");
  gamma_ = p_.get<double>("primal: gamma");
  if (mu_ <= 0) mu_ = p_.get<double>("starting point: complementarity") * scales.energy / std::max(m_, 1LL);
  if (zeta_ <= 0) zeta_ = bnorm_ > 0 ? bnorm_ : 1.0;
  // The slack s = d - A v is computed once and then updated with each step, s <- s - alpha A dv:
  // recomputing it from v would cancel digits on the nearly active constraints, where
  // y = mu / s needs them most.
  qp_.A->apply(*v_, s_);
  s_.update(1.0, *qp_.d, -1.0);
  // The relaxed set S_varsigma = {A v - d <= varsigma} of section 3.2 contains the initial
  // guess strictly; varsigma is then driven to zero with mu.
  if (relaxed_) {
    varsigma_ = std::max(0.0, -globalMin(s_)) + margin;
    shiftAll(s_, varsigma_);
  }
}

SolveResult PrimalBarrierMethod::run(IterationObserver& observer, Teuchos::Time& timer) {
  start();
  for (int k = 0;; ++k) {
    if (!solveSubproblem(k, observer, timer)) break;
    observer.onMainIteration(k + 1, inner_);
    result_.outerIterations = k + 1;
    lambda_.update(-1.0, y_, 0.0);
    if (stop_.converged(kktMeasures(qp_, *v_, lambda_), result_) || stop_.outOfIterations(k + 1, result_)) break;
    gamma_ = gammaRule_.next(gamma_, inner_);
    nextSubproblem();
  }
  result_.preconditionerSetups = newton_.preconditionerSetups();
  result_.multigridNonzeros = newton_.multigridNonzeros();
  finishResult(qp_, *v_, lambda_, s_, result_);
  result_.seconds = timer.totalElapsedTime(true);
  observer.onFinish(result_);
  return result_;
}

// Inner Newton steps until ||grad psi|| < zeta (after at least one step); false if the
// solve must stop.
bool PrimalBarrierMethod::solveSubproblem(int k, IterationObserver& observer, Teuchos::Time& timer) {
  inner_ = 0;
  forcing_.restart();
  for (;;) {
    const double gnorm = evaluate();
    if (!std::isfinite(gnorm))
      return stopWith(result_, SolveStatus::NumericalBreakdown,
                      "non-finite gradient; check the problem data (Q must be positive definite)");
    if (inner_ > 0 && gnorm < zeta_) return true;
    if (inner_ == maxInner_) {
      char values[96];
      std::snprintf(values, sizeof values, "%.3e in %d steps at mu = %.3e", zeta_, maxInner_, mu_);
      return stopWith(result_, SolveStatus::NumericalBreakdown,
                      std::string("the inner Newton loop did not reach ||grad psi|| < ") + values +
                          ": the barrier Hessian is too ill-conditioned for the target; loosen Solver/kkt: "
                          "tolerance, or use Solver/method = primal-dual");
    }
    if (!newtonStep(k, gnorm, observer, timer)) return false;
  }
}

// y = mu / s, g = Q v - b + A^T y; returns ||g||.
double PrimalBarrierMethod::evaluate() {
  y_.reciprocal(s_);
  y_.scale(mu_);
  qp_.Q->apply(*v_, Qv_);
  g_.update(1.0, Qv_, -1.0, *qp_.b, 0.0);
  qp_.A->apply(y_, g_, Teuchos::TRANS, 1.0, 1.0);
  ++result_.gradientEvaluations;
  return g_.norm2();
}

// A truncated Newton direction on psi, then Armijo backtracking along it.
bool PrimalBarrierMethod::newtonStep(int k, double gnorm, IterationObserver& observer, Teuchos::Time& timer) {
  {
    auto sd = s_.getData();
    auto dd = D_.getDataNonConst();
    for (std::size_t i = 0; i < s_.getLocalLength(); ++i) dd[i] = mu_ / (sd[i] * sd[i]);
  }
  newton_.setWeights(D_);
  rhs_.update(-1.0, g_, 0.0);
  const double residualScale = gnorm * std::min(1.0, std::sqrt(gnorm / (bnorm_ > 0 ? bnorm_ : 1.0)));
  tolerance_ = std::min(0.5 * gnorm, forcing_.tolerance(gnorm, residualScale, gnorm));
  ++result_.newtonSteps;
  krylov_ = 0;
  slope_ = 0.0;
  solveDirection(1.0, false);
  if (!(slope_ < 0)) solveDirection(1e-3, false);  // no descent: once more, much tighter
  if (!(slope_ < 0))
    return stopWith(result_, SolveStatus::KrylovFailure,
                    "the Krylov solver returned no descent direction; raise Solver/Krylov/maximum "
                    "iterations or choose a stronger Solver/Preconditioner");
  double alpha = 0.0;
  if (!lineSearch(alpha))
    return stopWith(result_, SolveStatus::LineSearchFailure,
                    "no Armijo decrease along the Newton direction; tighten Solver/forcing: eta");
  v_->update(alpha, dv_, 1.0);
  ++inner_;
  record(k, alpha, observer, timer);
  return true;
}

// The direction dv, `tighter` times tighter than the forcing asks, and its slope g^T dv.
void PrimalBarrierMethod::solveDirection(double tighter, bool fromDirection) {
  const int iterations = newton_.solve(rhs_, dv_, tighter * tolerance_, fromDirection,
                                       tighter * forcing_.startReduction(), tighter * forcing_.floor).iterations;
  krylov_ += iterations;
  countKrylovSolve(result_, iterations, krylov_);
  slope_ = g_.dot(dv_);
}

// Fraction to the boundary (28), then Armijo backtracking on psi, evaluated without further
// operator applications: psi is quadratic plus a sum of logs along the line. A direction
// that finds no decrease is solved once more, much tighter, and searched again: near
// round-off a loosely solved direction's slope can be all error.
bool PrimalBarrierMethod::lineSearch(double& alpha) {
  int halvings = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (attempt == 1) {
      solveDirection(1e-3, true);
      if (!(slope_ < 0)) return false;
    }
    qp_.A->apply(dv_, Adv_);
    minusAdv_.update(-1.0, Adv_, 0.0);
    alpha = std::min(1.0, fractionToBoundary_ * maxStepToBoundary(s_, minusAdv_));
    qp_.Q->apply(dv_, Qdv_);
    const double linear = Qv_.dot(dv_) - qp_.b->dot(dv_), quadratic = 0.5 * Qdv_.dot(dv_);
    auto psiChange = [&](double a) {  // psi(v + a dv) - psi(v)
      ++result_.functionEvaluations;
      return a * linear + a * a * quadratic - mu_ * logChange(s_, a, minusAdv_);
    };
    halvings = 0;
    while (!(psiChange(alpha) <= tau_ * alpha * slope_) && halvings < 60) {
      alpha *= 0.5;
      ++halvings;
    }
    if (halvings < 60) return true;
  }
  return false;
}

// The step's record, with s, lambda and Q v brought to the new point.
void PrimalBarrierMethod::record(int k, double alpha, IterationObserver& observer, Teuchos::Time& timer) {
  NewtonStepRecord step;
  step.outer = k + 1;
  step.inner = inner_;
  step.mu = mu_;
  step.step = alpha;
  step.krylovIterations = krylov_;
  s_.update(-alpha, Adv_, 1.0);
  lambda_.reciprocal(s_);
  lambda_.scale(-mu_);
  step.kkt = kktMeasures(qp_, *v_, lambda_);
  Qv_.update(alpha, Qdv_, 1.0);  // Q v at the new point, without another operator application
  step.objective = objective(qp_, *v_, Qv_);
  step.seconds = timer.totalElapsedTime(true);
  observer.onNewtonStep(step);
}

// mu_{k+1} = gamma mu_k, the relaxation shrunk with it, zeta_{k+1} = delta zeta_k.
void PrimalBarrierMethod::nextSubproblem() {
  const double previousMu = mu_;
  mu_ *= gamma_;
  const double dvarsigma = varsigma_ * (gamma_ - 1.0);
  if (extrapolate_) {
    extrapolate(previousMu, dvarsigma);
  } else if (varsigma_ > 0) {
    // Without the predictor, shrink the relaxation by at most 90% of the smallest slack,
    // so the iterate stays strictly inside.
    const double next = std::max(varsigma_ + dvarsigma, varsigma_ - 0.9 * globalMin(s_));
    shiftAll(s_, next - varsigma_);
    varsigma_ = next;
  }
  if (varsigma_ > 0 && varsigma_ < 1e-3 * stop_.tolerance * displacementScale_ && globalMin(s_) > 2 * varsigma_) {
    shiftAll(s_, -varsigma_);  // close enough: back to the original constraints
    varsigma_ = 0;
  }
  // Below the stationarity the KKT target asks for, a tighter inner loop buys nothing.
  zeta_ = std::max(delta_ * zeta_, 0.1 * stop_.tolerance * bnorm_);
}

// Predictor along the central path: differentiating grad psi = 0 with s = d + varsigma - A v,
// H dv = -(dmu) A^T (1/s) + mu A^T (dvarsigma / s^2), so the next subproblem starts near its
// solution instead of where the old one ended.
void PrimalBarrierMethod::extrapolate(double previousMu, double dvarsigma) {
  {
    auto sd = s_.getData();
    auto dd = D_.getDataNonConst();
    auto wd = y_.getDataNonConst();
    for (std::size_t i = 0; i < s_.getLocalLength(); ++i) {
      dd[i] = previousMu / (sd[i] * sd[i]);
      wd[i] = (previousMu - mu_) / sd[i] + previousMu * dvarsigma / (sd[i] * sd[i]);
    }
  }
  newton_.setWeights(D_);
  qp_.A->apply(y_, rhs_, Teuchos::TRANS);
  const KrylovResult kr = newton_.solve(rhs_, dv_, std::max(forcing_.floor, 0.01 * rhs_.norm2()));
  ++result_.newtonSteps;
  countKrylovSolve(result_, kr.iterations, kr.iterations);
  qp_.A->apply(dv_, Adv_);
  minusAdv_.putScalar(dvarsigma);  // the slack's change: dvarsigma - A dv
  minusAdv_.update(-1.0, Adv_, 1.0);
  const double alpha = std::min(1.0, fractionToBoundary_ * maxStepToBoundary(s_, minusAdv_));
  v_->update(alpha, dv_, 1.0);
  s_.update(alpha, minusAdv_, 1.0);
  varsigma_ += alpha * dvarsigma;
}

}  // namespace

SolveResult solvePrimalBarrier(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p,
                            const Vector* v0,
                               IterationObserver& observer, const RCP<const MultiVector>& freeMotions) {
  Teuchos::Time timer("primal");
  timer.start(true);
  observer.onStart("primal (Algorithm 3.1)", qp.Q->getDomainMap()->getGlobalNumElements(),
                   qp.A->getRangeMap()->getGlobalNumElements());
  PrimalBarrierMethod method(qp, multigrid, p, v0, freeMotions);
  return method.run(observer, timer);
}

}  // namespace signorini::detail
