// Algorithm 3.2 of the paper on the slack formulation (9): variables v, s = d - A v > 0
// (kept as an independent variable, so any initial guess is accepted) and y = -lambda > 0.
// Residuals r_d = Q v - b + A^T y, r_p = A v + s - d, r_c = s.y - mu_target; the Newton
// system condenses to H dv = -r_d - A^T ((-r_c + y.r_p)/s), H = Q + A^T (Y S^-1) A, with
// ds = -r_p - A dv and dy = (-r_c - y.ds)/s computed exactly, so the truncation error of the
// Krylov solve only enters the dual residual, and the forcing rule controls it.
#include <cmath>
#include <memory>

#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/ParameterValidation.hpp"
#include "solver/ipm/ActiveSetFinish.hpp"
#include "solver/ipm/FreeMotionBalance.hpp"
#include "solver/ipm/InteriorPointMethods.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {
namespace {

// out_i = f(i) over the local entries of vectors on the same map.
template <class F>
void forEach(Vector& out, F f) {
  auto o = out.getDataNonConst();
  for (std::size_t i = 0; i < out.getLocalLength(); ++i) o[i] = f(i);
}

// One primal-dual solve over the iterate (v, s, y): each main iteration evaluates the
// residuals, tests for the end, computes a direction (Mehrotra's predictor and corrector, or
// one step towards a fixed fraction of mu) and takes a step, backtracking on the merit
// function 1/2 ||F||^2 with fixed centering. Once the active set has settled, an active-set
// finish may end the solve (ActiveSetFinish).
class PrimalDualMethod {
 public:
  PrimalDualMethod(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p, const Vector* v0,
                   const RCP<const MultiVector>& freeMotions);
  SolveResult run(IterationObserver& observer, Teuchos::Time& timer);

 private:
  void start();
  KKTMeasures evaluate(int k);
  void tightenStalledForcing();
  bool continues(int k, const KKTMeasures& kkt);
  bool finishOnActiveSet(int k, const KKTMeasures& kkt);
  bool computeDirection();
  void predictorCorrector();
  void takeDirection(const Vector& rc, bool fromCurrentStep);
  double merit(double alpha);
  double meritSlope() const;
  bool backtrackOnMerit(double& alpha);
  void takeStep(int k, double alpha, bool move = true);
  void report(const KKTMeasures& kkt, Teuchos::Time& timer);
  IterationObserver* observer_ = nullptr;  // run()'s, which every report goes to

  const ContactQP& qp_;
  const MultigridInput& multigrid_;
  const Teuchos::ParameterList& p_;
  const RCP<const MultiVector> freeMotions_;  // null: Q holds every rigid body motion
  const long long m_;
  const Centering centering_;
  const bool correctorFromPredictor_;
  const double fractionToBoundary_, muFactor_, armijo_;
  const StoppingRule stop_;
  const double bnorm_;
  ForcingRule forcing_;
  NewtonSystemSolver newton_;
  std::unique_ptr<ActiveSetFinish> finish_;  // null: "primal-dual: active-set finish" is off
  SolveResult result_;

  RCP<Vector> v_;
  Vector s_, y_, D_;
  // Residuals and directions, on the displacement map (Qv_ ... trial_) and on the constraints.
  Vector Qv_, rd_, rhs_, dv_, t_, trial_;
  Vector Av_, lambda_, rp_, rc_, u_, Adv_, ds_, dy_, sAffine_, yAffine_;

  double mu0_ = 0, mu_ = 0, muTarget_ = 0, rdNorm_ = 0;
  double previousRdNorm_ = -1.0, previousAlpha_ = 0.0;
  int stalls_ = 0;  // main iterations in a row in which r_d stalled
  int krylovThisStep_ = 0;
  int rejectedFinishKrylov_ = 0;  // counted with the next step
  bool krylovFailed_ = false;
  NewtonStepRecord pending_;  // the last step, reported once the next iterate's KKT measures are known
  bool havePending_ = false;
};

PrimalDualMethod::PrimalDualMethod(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p, const Vector* v0,
                                   const RCP<const MultiVector>& freeMotions)
    : qp_(qp),
      multigrid_(multigrid),
      p_(p),
      freeMotions_(freeMotions),
      m_(qp.A->getRangeMap()->getGlobalNumElements()),
      centering_(choice<Centering>(p, "primal-dual: centering")),
      correctorFromPredictor_(p.get<bool>("primal-dual: corrector from predictor")),
      fractionToBoundary_(p.get<double>("primal-dual: fraction to boundary")),
      muFactor_(p.get<double>("primal-dual: mu factor")),
      armijo_(p.get<double>("primal-dual: armijo")),
      stop_(p),
      bnorm_(qp.b->norm2()),
      forcing_(forcingRule(p, 0.1 * stop_.tolerance * bnorm_)),
      newton_(qp, multigrid, p, freeMotions),
      finish_(p.get<bool>("primal-dual: active-set finish") && m_ > 0
                  ? std::make_unique<ActiveSetFinish>(qp, newton_, stop_.tolerance)
                  : nullptr),
      v_(initialDisplacement(qp, v0)),
      s_(qp.A->getRangeMap()), y_(s_.getMap()), D_(s_.getMap()),
      Qv_(qp.Q->getDomainMap()), rd_(Qv_.getMap()), rhs_(Qv_.getMap()), dv_(Qv_.getMap()), t_(Qv_.getMap()),
      trial_(Qv_.getMap()),
      Av_(s_.getMap()), lambda_(s_.getMap()), rp_(s_.getMap()), rc_(s_.getMap()), u_(s_.getMap()),
      Adv_(s_.getMap()), ds_(s_.getMap()), dy_(s_.getMap()), sAffine_(s_.getMap()), yAffine_(s_.getMap()) {}

// s_i = max(d_i - a_i v, displacement scale |a_i| / max_j |a_j|), s^T y = theta * energy
// scale, y = mu0 / s; where only the contact holds the body, y rescaled to balance the load
// along the free motions. The slacks' floor follows each row's scale: a weighted gap of a
// small facet patch (a fine part of a graded mesh) gets a proportionally smaller one, as its
// gap and its movement are; nodal rows all have the same.
void PrimalDualMethod::start() {
  newton_.setWeights(D_);
  const ProblemScales scales = problemScales(qp_, multigrid_, newton_, *v_, !freeMotions_.is_null());
  result_.krylovIterations += scales.krylovIterations;
  qp_.A->apply(*v_, Av_);
  {
    const Vector rows = constraintRowNorms(*qp_.A);
    const double largest = rows.normInf();
    auto rd = rows.getData();
    auto dd = qp_.d->getData();
    auto ad = Av_.getData();
    forEach(s_, [&](std::size_t i) { return std::max(dd[i] - ad[i], scales.displacement * rd[i] / largest); });
  }
  mu0_ = m_ > 0 ? p_.get<double>("starting point: complementarity") * scales.energy / m_ : 0.0;
  {
    auto sd = s_.getData();
    forEach(y_, [&](std::size_t i) { return mu0_ / sd[i]; });
  }
  if (!freeMotions_.is_null() && balanceLoadAlongFreeMotions(*qp_.A, *qp_.b, *freeMotions_, y_)) mu0_ = s_.dot(y_) / m_;
}

SolveResult PrimalDualMethod::run(IterationObserver& observer, Teuchos::Time& timer) {
  observer_ = &observer;
  start();
  for (int k = 0;; ++k) {
    const KKTMeasures kkt = evaluate(k);
    if (havePending_) report(kkt, timer);
    result_.outerIterations = k;
    if (!continues(k, kkt)) break;
    if (finishOnActiveSet(k, kkt)) continue;  // the finished point is evaluated and tested as any other
    if (!computeDirection()) break;
    double alpha =
        std::min(1.0, fractionToBoundary_ * std::min(maxStepToBoundary(s_, ds_), maxStepToBoundary(y_, dy_)));
    if (centering_ == Centering::Fixed && !backtrackOnMerit(alpha)) break;
    takeStep(k, alpha);
  }
  Vector slack(s_.getMap());
  qp_.A->apply(*v_, slack);
  slack.update(1.0, *qp_.d, -1.0);
  result_.preconditionerSetups = newton_.preconditionerSetups();
  result_.multigridNonzeros = newton_.multigridNonzeros();
  finishResult(qp_, *v_, lambda_, slack, result_);
  result_.seconds = timer.totalElapsedTime(true);
  observer.onFinish(result_);
  return result_;
}

// r_d, r_p, mu and the KKT measures of the current iterate.
KKTMeasures PrimalDualMethod::evaluate(int k) {
  qp_.Q->apply(*v_, Qv_);
  rd_.assign(Qv_);
  rd_.update(-1.0, *qp_.b, 1.0);
  qp_.A->apply(y_, rd_, Teuchos::TRANS, 1.0, 1.0);
  qp_.A->apply(*v_, Av_);
  rp_.update(1.0, Av_, 1.0, s_, 0.0);
  rp_.update(-1.0, *qp_.d, 1.0);
  mu_ = m_ > 0 ? s_.dot(y_) / m_ : 0.0;
  rdNorm_ = rd_.norm2();
  tightenStalledForcing();
  ++result_.gradientEvaluations;
  lambda_.update(-1.0, y_, 0.0);
  const KKTMeasures kkt = kktMeasures(qp_, *v_, lambda_);
  // Not at the start: there v = 0 may give the complementarity measure no energy scale.
  const double tol = stop_.tolerance;
  forcing_.stationarityOnly =
      k > 0 && kkt.complementarity <= tol && kkt.primalFeasibility <= tol && kkt.dualFeasibility <= tol;
  return kkt;
}

// The Krylov residual of a step lands in r_d alone: after a step of length alpha,
// r_d = (1 - alpha) r_d + alpha (residual). When, twice in a row, r_d kept more than
// 1 - alpha/2 of itself and lagged behind mu (its term of the safeguard binds), the solves
// are too loose for it: the reduction forcing's safeguard tightens for the rest of the
// solve (without it, paper/K without the contact correction stalls at stationarity 1e-5 on
// 3 ranks while mu falls to nothing).
void PrimalDualMethod::tightenStalledForcing() {
  const bool stalled = forcing_.type == ForcingType::Reduction && previousRdNorm_ > 0 && mu0_ > 0 &&
                       rdNorm_ > bnorm_ * mu_ / mu0_ && rdNorm_ > (1 - 0.5 * previousAlpha_) * previousRdNorm_;
  stalls_ = stalled ? stalls_ + 1 : 0;
  if (stalls_ == 2) {
    forcing_.reductionSafeguard *= 0.5;
    stalls_ = 0;
  }
  previousRdNorm_ = rdNorm_;
}

bool PrimalDualMethod::continues(int k, const KKTMeasures& kkt) {
  if (!std::isfinite(mu_) || !std::isfinite(kkt.stationarityAbs))
    return stopWith(result_, SolveStatus::NumericalBreakdown,
                    "non-finite iterate; check the problem data (Q must be positive definite)");
  if (stop_.converged(kkt, result_)) return false;
  // Complementarity far below any need while the rest of the KKT conditions lag: the Newton
  // systems are solved too loosely for the target, and D = y/s degenerates.
  if (mu0_ > 0 && mu_ < 1e-30 * mu0_)
    return stopWith(result_, SolveStatus::NumericalBreakdown,
                    "the barrier parameter vanished before the KKT target was met: the Newton systems are "
                    "solved too loosely; tighten Solver/forcing: eta");
  return !stop_.outOfIterations(k, result_);
}

// Tries the active-set finish where it is due; true if it was accepted, the iterate then
// its point (v, s = d - A v, y = -lambda).
bool PrimalDualMethod::finishOnActiveSet(int k, const KKTMeasures& kkt) {
  if (!finish_) return false;
  const PrimalDualIterate x{*v_, s_, y_, lambda_, rd_, rp_};  // lambda_ = -y_ since evaluate()
  if (!finish_->settled(x, kkt, previousAlpha_)) return false;
  const ActiveSetFinish::Outcome outcome = finish_->attempt(x);
  result_.krylovIterations += outcome.krylovIterations;  // not a barrier step's system: not in the maximum
  ++result_.newtonSteps;
  observer_->onActiveSetFinish(ActiveSetFinishRecord{k, outcome.accepted, outcome.krylovIterations});
  if (!outcome.accepted) {
    rejectedFinishKrylov_ += outcome.krylovIterations;
    return false;
  }
  v_->assign(finish_->v());
  y_.update(-1.0, finish_->lambda(), 0.0);
  qp_.A->apply(*v_, Av_);
  s_.update(1.0, *qp_.d, -1.0, Av_, 0.0);
  krylovThisStep_ = outcome.krylovIterations;
  muTarget_ = 0.0;
  takeStep(k, 1.0, false);
  return true;
}

// (dv, ds, dy) for the current iterate; false if a Krylov solve made no progress.
bool PrimalDualMethod::computeDirection() {
  auto yd = y_.getData();
  auto sd = s_.getData();
  forEach(D_, [&](std::size_t i) { return yd[i] / sd[i]; });
  newton_.setWeights(D_);
  krylovThisStep_ = 0;
  krylovFailed_ = false;
  if (centering_ == Centering::Mehrotra) {
    predictorCorrector();
  } else {
    muTarget_ = muFactor_ * mu_;
    forEach(rc_, [&](std::size_t i) { return sd[i] * yd[i] - muTarget_; });
    takeDirection(rc_, false);
  }
  if (!krylovFailed_) return true;
  return stopWith(result_, SolveStatus::KrylovFailure,
                  "the Krylov solver made no progress on a Newton system; raise Solver/Krylov/maximum "
                  "iterations or choose a stronger Solver/Preconditioner");
}

// Mehrotra: the affine direction (r_c = s.y) predicts how far mu can fall, sigma =
// (mu_affine / mu)^3; the corrector targets sigma mu with the affine second-order term.
void PrimalDualMethod::predictorCorrector() {
  rc_.elementWiseMultiply(1.0, s_, y_, 0.0);
  takeDirection(rc_, false);
  const double ap = std::min(1.0, maxStepToBoundary(s_, ds_)), ad = std::min(1.0, maxStepToBoundary(y_, dy_));
  double muAffine = 0;
  if (m_ > 0) {
    sAffine_.update(1.0, s_, ap, ds_, 0.0);
    yAffine_.update(1.0, y_, ad, dy_, 0.0);
    muAffine = sAffine_.dot(yAffine_) / m_;
  }
  const double sigma = mu_ > 0 ? std::pow(muAffine / mu_, 3) : 0.0;
  muTarget_ = sigma * mu_;
  {
    // rc = s.y + ds_aff.dy_aff - sigma mu, from the affine direction still in ds, dy
    auto sd = s_.getData();
    auto yd = y_.getData();
    auto dsd = ds_.getData();
    auto dyd = dy_.getData();
    forEach(rc_, [&](std::size_t i) { return sd[i] * yd[i] + dsd[i] * dyd[i] - muTarget_; });
  }
  // The corrector's right-hand side differs from the predictor's by the centering and
  // second-order terms only: its CG may start from the predictor's step.
  takeDirection(rc_, correctorFromPredictor_);
}

// The direction for the complementarity residual rc: one truncated Krylov solve for dv,
// then ds and dy exactly.
void PrimalDualMethod::takeDirection(const Vector& rc, bool fromCurrentStep) {
  {
    auto rcd = rc.getData();
    auto yd = y_.getData();
    auto rpd = rp_.getData();
    auto sd = s_.getData();
    forEach(u_, [&](std::size_t i) { return (-rcd[i] + yd[i] * rpd[i]) / sd[i]; });
  }
  rhs_.assign(rd_);
  qp_.A->apply(u_, rhs_, Teuchos::TRANS, -1.0, -1.0);
  const double rpNorm = rp_.norm2();
  const double residualScale = std::max(rdNorm_, mu0_ > 0 ? bnorm_ * mu_ / mu0_ : 0.0);
  // ||F|| with ||s.y - mu_target|| estimated by sqrt(m) mu
  const double kktNorm = std::sqrt(rdNorm_ * rdNorm_ + rpNorm * rpNorm + static_cast<double>(m_) * mu_ * mu_);
  double tolerance = forcing_.tolerance(rhs_.norm2(), residualScale, kktNorm);
  // Fixed centering backtracks on 1/2 ||F||^2, along which only an inexact Newton direction,
  // ||residual|| <= eta ||F|| with eta < 1, is sure to descend.
  if (centering_ == Centering::Fixed)
    tolerance = std::max(forcing_.floor, std::min(tolerance, forcing_.eta * kktNorm));
  const KrylovResult kr =
      newton_.solve(rhs_, dv_, tolerance, fromCurrentStep, forcing_.startReduction(), forcing_.floor);
  qp_.A->apply(dv_, Adv_);
  ds_.update(-1.0, rp_, -1.0, Adv_, 0.0);
  {
    auto rcd = rc.getData();
    auto yd = y_.getData();
    auto dsd = ds_.getData();
    auto sd = s_.getData();
    forEach(dy_, [&](std::size_t i) { return (-rcd[i] - yd[i] * dsd[i]) / sd[i]; });
  }
  ++result_.newtonSteps;
  countKrylovSolve(result_, kr.iterations, kr.iterations);
  krylovThisStep_ += kr.iterations;
  if (!kr.converged && !(kr.relativeResidual < 1.0)) krylovFailed_ = true;
}

// phi(alpha) = 1/2 ||F(alpha)||^2 along the direction. F is linear in alpha but for the
// complementarity block, so it needs no operator application once t = Q dv + A^T dy is known.
double PrimalDualMethod::merit(double alpha) {
  trial_.update(1.0, rd_, alpha, t_, 0.0);
  const double linear = trial_.dot(trial_) + (1 - alpha) * (1 - alpha) * rp_.dot(rp_);
  auto sd = s_.getData();
  auto yd = y_.getData();
  auto dsd = ds_.getData();
  auto dyd = dy_.getData();
  const double complementarity = sumOverEntries(*s_.getMap()->getComm(), s_.getLocalLength(), [&](std::size_t i) {
    const double c = (sd[i] + alpha * dsd[i]) * (yd[i] + alpha * dyd[i]) - muTarget_;
    return c * c;
  });
  ++result_.functionEvaluations;
  return 0.5 * (linear + complementarity);
}

// phi'(0).
double PrimalDualMethod::meritSlope() const {
  auto sd = s_.getData();
  auto yd = y_.getData();
  auto dsd = ds_.getData();
  auto dyd = dy_.getData();
  return rd_.dot(t_) - rp_.dot(rp_) +
         sumOverEntries(*s_.getMap()->getComm(), s_.getLocalLength(), [&](std::size_t i) {
           return (sd[i] * yd[i] - muTarget_) * (dsd[i] * yd[i] + sd[i] * dyd[i]);
         });
}

// Halves alpha until the Armijo condition holds on phi; false if it never does.
bool PrimalDualMethod::backtrackOnMerit(double& alpha) {
  qp_.Q->apply(dv_, t_);
  qp_.A->apply(dy_, t_, Teuchos::TRANS, 1.0, 1.0);
  const double phi0 = merit(0.0);
  const double slope = meritSlope();
  int halvings = 0;
  while (merit(alpha) > phi0 + armijo_ * alpha * slope && halvings < 40) {
    alpha *= 0.5;
    ++halvings;
  }
  if (halvings < 40 && slope < 0) return true;
  return stopWith(result_, SolveStatus::LineSearchFailure,
                  "no decrease of the merit function along the Newton direction; tighten "
                  "Solver/forcing: eta or use Solver/primal-dual: centering = mehrotra");
}

// Records the step; with `move`, first takes it along (dv, ds, dy).
void PrimalDualMethod::takeStep(int k, double alpha, bool move) {
  if (move) {
    v_->update(alpha, dv_, 1.0);
    s_.update(alpha, ds_, 1.0);
    y_.update(alpha, dy_, 1.0);
  }
  previousAlpha_ = alpha;
  pending_ = NewtonStepRecord();
  pending_.outer = k + 1;
  pending_.mu = muTarget_;
  pending_.step = alpha;
  pending_.krylovIterations = krylovThisStep_ + rejectedFinishKrylov_;
  rejectedFinishKrylov_ = 0;
  havePending_ = true;
  observer_->onMainIteration(k + 1, 1);
}

void PrimalDualMethod::report(const KKTMeasures& kkt, Teuchos::Time& timer) {
  pending_.objective = objective(qp_, *v_, Qv_);
  pending_.kkt = kkt;
  pending_.seconds = timer.totalElapsedTime(true);
  observer_->onNewtonStep(pending_);
}

}  // namespace

SolveResult solvePrimalDual(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p,
                            const Vector* v0,
                            IterationObserver& observer, const RCP<const MultiVector>& freeMotions) {
  Teuchos::Time timer("primal-dual");
  timer.start(true);
  observer.onStart("primal-dual (" + p.get<std::string>("primal-dual: centering") + " centering)",
                   qp.Q->getDomainMap()->getGlobalNumElements(), qp.A->getRangeMap()->getGlobalNumElements());
  PrimalDualMethod method(qp, multigrid, p, v0, freeMotions);
  return method.run(observer, timer);
}

}  // namespace signorini::detail
