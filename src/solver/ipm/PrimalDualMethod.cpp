// Algorithm 3.2 of the paper on the slack formulation (9): variables v, s = d - A v > 0
// (kept as an independent variable, so any initial guess is accepted) and y = -lambda > 0.
// Residuals r_d = Q v - b + A^T y, r_p = A v + s - d, r_c = s.y - mu_target; the Newton
// system condenses to H dv = -r_d - A^T ((-r_c + y.r_p)/s), H = Q + A^T (Y S^-1) A, with
// ds = -r_p - A dv and dy = (-r_c - y.ds)/s computed exactly, so the truncation error of the
// Krylov solve only enters the dual residual, and the forcing rule controls it.
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

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

}  // namespace

SolveResult solvePrimalDual(const ContactQP& qp, const Teuchos::ParameterList& p, const Vector* v0,
                            IterationObserver& observer) {
  Teuchos::Time timer("primal-dual");
  timer.start(true);
  const std::string centering = p.get<std::string>("primal-dual: centering");
  const bool correctorFromPredictor = p.get<bool>("primal-dual: corrector from predictor");
  const auto vmap = qp.Q->getDomainMap();
  const auto cmap = qp.A->getRangeMap();
  const long long m = cmap->getGlobalNumElements();
  observer.onStart("primal-dual (" + centering + " centering)", vmap->getGlobalNumElements(), m);

  SolveResult result;
  NewtonSystemSolver newton(qp, p);
  RCP<Vector> v = initialDisplacement(qp, v0);
  Vector s(cmap), y(cmap), D(cmap);
  newton.setWeights(D);
  const ProblemScales scales = problemScales(qp, newton, *v);
  result.krylovIterations += scales.krylovIterations;

  // Start: s = max(d - A v, displacement scale), s^T y = theta * energy scale, y = mu0 / s.
  Vector Av(cmap);
  qp.A->apply(*v, Av);
  {
    auto dd = qp.d->getData();
    auto ad = Av.getData();
    forEach(s, [&](std::size_t i) { return std::max(dd[i] - ad[i], scales.displacement); });
  }
  const double mu0 = m > 0 ? p.get<double>("starting point: complementarity") * scales.energy / m : 0.0;
  {
    auto sd = s.getData();
    forEach(y, [&](std::size_t i) { return mu0 / sd[i]; });
  }

  const double tol = p.get<double>("kkt: tolerance");
  const int maxIterations = p.get<int>("maximum iterations");
  const double bnorm = qp.b->norm2();
  ForcingRule forcing = forcingRule(p, 0.1 * tol * bnorm);
  const double ftb = p.get<double>("primal-dual: fraction to boundary");
  const double muFactor = p.get<double>("primal-dual: mu factor");
  const double armijo = p.get<double>("primal-dual: armijo");

  Vector Qv(vmap), rd(vmap), rhs(vmap), dv(vmap), t(vmap), trial(vmap), lambda(cmap), rp(cmap), rc(cmap), u(cmap),
      Adv(cmap), ds(cmap), dy(cmap), sAffine(cmap), yAffine(cmap);
  NewtonStepRecord pending;
  bool havePending = false;
  double mu = 0;

  double rdNorm = 0.0;  // ||r_d|| of the current iterate, set with r_d in the main loop
  // Direction for a complementarity residual rc; returns the Krylov result.
  auto direction = [&](const Vector& rcv, bool fromCurrentStep) {
    {
      auto rcd = rcv.getData();
      auto yd = y.getData();
      auto rpd = rp.getData();
      auto sd = s.getData();
      forEach(u, [&](std::size_t i) { return (-rcd[i] + yd[i] * rpd[i]) / sd[i]; });
    }
    rhs.assign(rd);
    qp.A->apply(u, rhs, Teuchos::TRANS, -1.0, -1.0);
    const double rpNorm = rp.norm2();
    const double residualScale = std::max(rdNorm, mu0 > 0 ? bnorm * mu / mu0 : 0.0);
    // ||F|| with ||s.y - mu_target|| estimated by sqrt(m) mu
    const double kktNorm = std::sqrt(rdNorm * rdNorm + rpNorm * rpNorm + static_cast<double>(m) * mu * mu);
    double tolerance = forcing.tolerance(rhs.norm2(), residualScale, kktNorm);
    // Fixed centering backtracks on 1/2 ||F||^2, along which only an inexact Newton direction,
    // ||residual|| <= eta ||F|| with eta < 1, is sure to descend.
    if (centering == "fixed") tolerance = std::max(forcing.floor, std::min(tolerance, forcing.eta * kktNorm));
    KrylovResult kr =
        newton.solve(rhs, dv, tolerance, fromCurrentStep, forcing.startReduction(), forcing.floor);
    qp.A->apply(dv, Adv);
    ds.update(-1.0, rp, -1.0, Adv, 0.0);
    {
      auto rcd = rcv.getData();
      auto yd = y.getData();
      auto dsd = ds.getData();
      auto sd = s.getData();
      forEach(dy, [&](std::size_t i) { return (-rcd[i] - yd[i] * dsd[i]) / sd[i]; });
    }
    ++result.newtonSteps;
    result.krylovIterations += kr.iterations;
    result.maxKrylovPerNewton = std::max(result.maxKrylovPerNewton, kr.iterations);
    return kr;
  };

  double previousRdNorm = -1.0, previousAlpha = 0.0;
  int stalls = 0;  // main iterations in a row in which r_d stalled
  for (int k = 0;; ++k) {
    qp.Q->apply(*v, Qv);
    rd.assign(Qv);
    rd.update(-1.0, *qp.b, 1.0);
    qp.A->apply(y, rd, Teuchos::TRANS, 1.0, 1.0);
    qp.A->apply(*v, Av);
    rp.update(1.0, Av, 1.0, s, 0.0);
    rp.update(-1.0, *qp.d, 1.0);
    mu = m > 0 ? s.dot(y) / m : 0.0;
    {
      // The Krylov residual of a step lands in r_d alone: after a step of length alpha,
      // r_d = (1 - alpha) r_d + alpha (residual). When, twice in a row, r_d kept more than
      // 1 - alpha/4 of itself and lagged behind mu (its term of the safeguard binds), the solves
      // are too loose for it: the reduction forcing's safeguard tightens for the rest of the
      // solve. Without the contact correction, paper/K at 3 ranks otherwise stalled at
      // stationarity 1e-5 while mu fell to nothing; a single stall (2D nx = 400, step 3) passes.
      rdNorm = rd.norm2();
      const bool stalled = forcing.type == "reduction" && previousRdNorm > 0 && mu0 > 0 &&
                           rdNorm > bnorm * mu / mu0 && rdNorm > (1 - 0.25 * previousAlpha) * previousRdNorm;
      stalls = stalled ? stalls + 1 : 0;
      if (stalls == 2) {
        forcing.reductionSafeguard *= 0.5;
        stalls = 0;
      }
      previousRdNorm = rdNorm;
    }
    ++result.gradientEvaluations;
    lambda.update(-1.0, y, 0.0);
    const KKTMeasures kkt = kktMeasures(qp, *v, lambda);
    // Not at the start: there v = 0 may give the complementarity measure no energy scale.
    forcing.stationarityOnly =
        k > 0 && kkt.complementarity <= tol && kkt.primalFeasibility <= tol && kkt.dualFeasibility <= tol;

    if (havePending) {
      pending.objective = objective(qp, *v, Qv);
      pending.kkt = kkt;
      pending.seconds = timer.totalElapsedTime(true);
      result.history.push_back(pending);
      observer.onNewtonStep(pending);
    }
    result.outerIterations = k;
    if (!std::isfinite(mu) || !std::isfinite(kkt.stationarityAbs)) {
      result.status = SolveStatus::NumericalBreakdown;
      result.message = "non-finite iterate; check the problem data (Q must be positive definite)";
      break;
    }
    if (kkt.worst() <= tol) {
      result.status = SolveStatus::Converged;
      result.message = convergedMessage(tol);
      break;
    }
    if (mu0 > 0 && mu < 1e-30 * mu0) {
      // Complementarity far below any need while the rest of the KKT conditions lag: the
      // Newton systems are solved too loosely for the target, and D = y/s degenerates.
      result.status = SolveStatus::NumericalBreakdown;
      result.message = "the barrier parameter vanished before the KKT target was met: the Newton systems are "
                       "solved too loosely; tighten Solver/forcing: eta";
      break;
    }
    if (k == maxIterations) {
      result.status = SolveStatus::IterationLimit;
      result.message = "maximum iterations (" + std::to_string(maxIterations) +
                       ") reached; raise Solver/maximum iterations or loosen Solver/kkt: tolerance";
      break;
    }

    {
      auto yd = y.getData();
      auto sd = s.getData();
      forEach(D, [&](std::size_t i) { return yd[i] / sd[i]; });
    }
    newton.setWeights(D);

    int krylovThisStep = 0;
    double muTarget = 0;
    bool krylovFailed = false;
    auto takeDirection = [&](const Vector& rcv, bool fromCurrentStep) {
      KrylovResult kr = direction(rcv, fromCurrentStep);
      krylovThisStep += kr.iterations;
      if (!kr.converged && !(kr.relativeResidual < 1.0)) krylovFailed = true;
    };
    if (centering == "mehrotra") {
      rc.elementWiseMultiply(1.0, s, y, 0.0);
      takeDirection(rc, false);
      const double ap = std::min(1.0, maxStepToBoundary(s, ds)), ad = std::min(1.0, maxStepToBoundary(y, dy));
      double muAffine = 0;
      if (m > 0) {
        sAffine.update(1.0, s, ap, ds, 0.0);
        yAffine.update(1.0, y, ad, dy, 0.0);
        muAffine = sAffine.dot(yAffine) / m;
      }
      const double sigma = mu > 0 ? std::pow(muAffine / mu, 3) : 0.0;
      muTarget = sigma * mu;
      {
        // rc = s.y + ds_aff.dy_aff - sigma mu, from the affine direction still in ds, dy
        auto sd = s.getData();
        auto yd = y.getData();
        auto dsd = ds.getData();
        auto dyd = dy.getData();
        forEach(rc, [&](std::size_t i) { return sd[i] * yd[i] + dsd[i] * dyd[i] - muTarget; });
      }
      // The corrector's right-hand side differs from the predictor's by the centering and
      // second-order terms only: its CG may start from the predictor's step.
      takeDirection(rc, correctorFromPredictor);
    } else {
      muTarget = muFactor * mu;
      {
        auto sd = s.getData();
        auto yd = y.getData();
        forEach(rc, [&](std::size_t i) { return sd[i] * yd[i] - muTarget; });
      }
      takeDirection(rc, false);
    }
    if (krylovFailed) {
      result.status = SolveStatus::KrylovFailure;
      result.message = "the Krylov solver made no progress on a Newton system; raise Solver/Krylov/maximum "
                       "iterations or choose a stronger Solver/Preconditioner";
      break;
    }

    const double alphaMax = std::min(maxStepToBoundary(s, ds), maxStepToBoundary(y, dy));
    double alpha = std::min(1.0, ftb * alphaMax);

    if (centering == "fixed") {
      // Backtracking on phi = 1/2 ||F||^2 along the direction; F is linear in alpha but for
      // the complementarity block, so phi(alpha) needs no operator application.
      qp.Q->apply(dv, t);
      qp.A->apply(dy, t, Teuchos::TRANS, 1.0, 1.0);
      auto phi = [&](double a) {
        trial.update(1.0, rd, a, t, 0.0);
        double value = trial.dot(trial) + (1 - a) * (1 - a) * rp.dot(rp);
        double local = 0;
        auto sd = s.getData();
        auto yd = y.getData();
        auto dsd = ds.getData();
        auto dyd = dy.getData();
        for (std::size_t i = 0; i < s.getLocalLength(); ++i) {
          double c = (sd[i] + a * dsd[i]) * (yd[i] + a * dyd[i]) - muTarget;
          local += c * c;
        }
        double global = local;
        Teuchos::reduceAll(*cmap->getComm(), Teuchos::REDUCE_SUM, 1, &local, &global);
        ++result.functionEvaluations;
        return 0.5 * (value + global);
      };
      const double phi0 = phi(0.0);
      double slope = rd.dot(t) - rp.dot(rp);
      {
        double local = 0;
        auto sd = s.getData();
        auto yd = y.getData();
        auto dsd = ds.getData();
        auto dyd = dy.getData();
        for (std::size_t i = 0; i < s.getLocalLength(); ++i)
          local += (sd[i] * yd[i] - muTarget) * (dsd[i] * yd[i] + sd[i] * dyd[i]);
        double global = local;
        Teuchos::reduceAll(*cmap->getComm(), Teuchos::REDUCE_SUM, 1, &local, &global);
        slope += global;
      }
      int halvings = 0;
      while (phi(alpha) > phi0 + armijo * alpha * slope && halvings < 40) {
        alpha *= 0.5;
        ++halvings;
      }
      if (halvings == 40 || slope >= 0) {
        result.status = SolveStatus::LineSearchFailure;
        result.message = "no decrease of the merit function along the Newton direction; tighten "
                         "Solver/forcing: eta or use Solver/primal-dual: centering = mehrotra";
        break;
      }
    }

    v->update(alpha, dv, 1.0);
    s.update(alpha, ds, 1.0);
    y.update(alpha, dy, 1.0);
    previousAlpha = alpha;

    pending = NewtonStepRecord();
    pending.outer = k + 1;
    pending.mu = muTarget;
    pending.step = alpha;
    pending.krylovIterations = krylovThisStep;
    havePending = true;
    result.innerIterations.push_back(1);
  }

  Vector slack(cmap);
  qp.A->apply(*v, slack);
  slack.update(1.0, *qp.d, -1.0);
  result.preconditionerSetups = newton.preconditionerSetups();
  finishResult(qp, *v, lambda, slack, result);
  result.seconds = timer.totalElapsedTime(true);
  observer.onFinish(result);
  return result;
}

}  // namespace signorini::detail
