#include "solver/ipm/ActiveSetFinish.hpp"

#include <algorithm>
#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"

namespace signorini::detail {
namespace {

// The steps' length and the estimate's age from which the set counts as settled.
constexpr double kLongStep = 0.9;
constexpr int kUnchangedSteps = 2;
// A constraint whose multiplier and slack are both below this fraction of their scales may
// change sides of the estimate without unsettling it: at the edge of the contact zone such
// nearly degenerate constraints cross one or two per main iteration long after the rest has
// settled, and the finish's correction step (correctSet) decides them as well.
constexpr double kNearlyDegenerate = 1e-2;
// The held constraints' violation, as a fraction of the displacement scale per unit of the
// tolerance: far below what the primal feasibility measure allows.
constexpr double kViolation = 1e-2;

}  // namespace

ActiveSetFinish::ActiveSetFinish(const ContactQP& qp, NewtonSystemSolver& newton, double tolerance)
    : qp_(qp),
      newton_(newton),
      tolerance_(tolerance),
      bnorm_(qp.b->norm2()),
      active_(qp.A->getRangeMap()),
      previous_(active_.getMap()),
      tried_(active_.getMap()),
      W_(active_.getMap()),
      u_(active_.getMap()),
      Adv_(active_.getMap()),
      lambdaTrial_(active_.getMap()),
      rhs_(qp.Q->getDomainMap()),
      dv_(rhs_.getMap()),
      vTrial_(rhs_.getMap()) {}

bool ActiveSetFinish::differs(const Vector& a, const Vector& b) const {
  auto ad = a.getData();
  auto bd = b.getData();
  return sumOverEntries(*a.getMap()->getComm(), a.getLocalLength(), [&](std::size_t i) { return ad[i] != bd[i] ? 1.0 : 0.0; }) >
         0;
}

bool ActiveSetFinish::changedBeyondDegenerate(const PrimalDualIterate& x) const {
  auto a = active_.getData();
  auto before = previous_.getData();
  auto l = x.lambda.getData();
  auto s = x.s.getData();
  return sumOverEntries(*active_.getMap()->getComm(), active_.getLocalLength(), [&](std::size_t i) {
           const auto k = static_cast<LocalOrdinal>(i);
           return a[i] != before[i] && !criterion_->isNearlyDegenerate(k, l[i], s[i], kNearlyDegenerate) ? 1.0 : 0.0;
         }) > 0;
}

bool ActiveSetFinish::settled(const PrimalDualIterate& x, const KKTMeasures& kkt, double lastStep) {
  criterion_.emplace(qp_, x.v, x.lambda);
  {
    auto l = x.lambda.getData();
    auto s = x.s.getData();
    auto a = active_.getDataNonConst();
    for (std::size_t i = 0; i < active_.getLocalLength(); ++i)
      a[i] = criterion_->isActive(static_cast<LocalOrdinal>(i), l[i], s[i]) ? 1.0 : 0.0;
  }
  const bool unchanged = unchangedSteps_ >= 0 && lastStep >= kLongStep && !changedBeyondDegenerate(x);
  unchangedSteps_ = unchanged ? unchangedSteps_ + 1 : 0;
  previous_.assign(active_);
  return unchangedSteps_ >= kUnchangedSteps && kkt.worst() <= std::sqrt(tolerance_) &&
         !(haveTried_ && !differs(active_, tried_));
}

ActiveSetFinish::Outcome ActiveSetFinish::attempt(const PrimalDualIterate& x) {
  tried_.assign(active_);
  haveTried_ = true;
  Outcome outcome;
  KKTMeasures kkt;
  bool promising = false;
  for (int pass = 0; pass < 2 && !promising; ++pass) {
    if (pass > 0 && !correctSet()) break;
    setSystem(x);
    // The start (earlier solutions, the exact contact correction) leaves a residual near the
    // Newton steps' own; ten times less tells the multipliers' signs.
    outcome.krylovIterations += newton_.solve(rhs_, dv_, rhs_.norm2(), pass > 0, 0.1).iterations;
    kkt = trial(x);
    promising = std::max(kkt.primalFeasibility, kkt.dualFeasibility) <= std::max(tolerance_, 10 * kkt.stationarity);
  }
  if (promising && kkt.worst() > tolerance_) {
    // The stationarity measure is relative to max(||b||, ||A^T lambda||) >= ||b||.
    outcome.krylovIterations += newton_.solve(rhs_, dv_, 0.5 * tolerance_ * bnorm_, true).iterations;
    kkt = trial(x);
  }
  outcome.accepted = kkt.worst() <= tolerance_;
  return outcome;
}

// One step of the primal-dual active set method from the trial point: held constraints whose
// multiplier came out of the wrong sign are released, released ones the trial violates are
// held. False if the set stays the same.
bool ActiveSetFinish::correctSet() {
  qp_.A->apply(vTrial_, u_);
  auto Av = u_.getData();
  auto d = qp_.d->getData();
  auto lambda = lambdaTrial_.getData();
  auto a = active_.getDataNonConst();
  double changes = 0;
  for (std::size_t i = 0; i < active_.getLocalLength(); ++i) {
    const bool held = a[i] > 0 ? lambda[i] <= 0 : Av[i] > d[i];
    if (held != (a[i] > 0)) ++changes;
    a[i] = held ? 1.0 : 0.0;
  }
  return sumOverEntries(*active_.getMap()->getComm(), 1, [&](std::size_t) { return changes; }) > 0;
}

// W in the Newton solver's weights and the right-hand side -r_d - A^T u, for the iterate
// settled() last saw.
void ActiveSetFinish::setSystem(const PrimalDualIterate& x) {
  {
    auto a = active_.getData();
    auto y = x.y.getData();
    auto s = x.s.getData();
    auto rp = x.rp.getData();
    auto W = W_.getDataNonConst();
    auto u = u_.getDataNonConst();
    for (std::size_t i = 0; i < active_.getLocalLength(); ++i) {
      const bool held = a[i] > 0;
      W[i] = held ? std::max(y[i] / s[i], criterion_->weight(static_cast<LocalOrdinal>(i), kViolation * tolerance_)) : 0.0;
      u[i] = held ? W[i] * (rp[i] - s[i]) : -y[i];
    }
  }
  newton_.setWeights(W_);
  rhs_.assign(x.rd);
  qp_.A->apply(u_, rhs_, Teuchos::TRANS, -1.0, -1.0);
}

// The trial point (v + dv, -(y + dy)) of the step in dv_, and its KKT measures.
KKTMeasures ActiveSetFinish::trial(const PrimalDualIterate& x) {
  vTrial_.update(1.0, x.v, 1.0, dv_, 0.0);
  qp_.A->apply(dv_, Adv_);
  {
    auto a = active_.getData();
    auto y = x.y.getData();
    auto s = x.s.getData();
    auto rp = x.rp.getData();
    auto W = W_.getData();
    auto Adv = Adv_.getData();
    auto lambda = lambdaTrial_.getDataNonConst();
    for (std::size_t i = 0; i < active_.getLocalLength(); ++i) lambda[i] = a[i] > 0 ? -(y[i] + W[i] * (Adv[i] + rp[i] - s[i])) : 0.0;
  }
  return kktMeasures(qp_, vTrial_, lambdaTrial_);
}

}  // namespace signorini::detail
