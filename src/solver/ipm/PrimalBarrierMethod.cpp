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

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/ipm/InteriorPointMethods.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {
namespace {

// sum_i log(1 + alpha ds_i / s_i): the change of sum log s along a step, computed without
// the cancellation that would make tiny decreases of psi invisible near the solution.
double logChange(const Vector& s, double alpha, const Vector& ds) {
  double local = 0;
  auto sd = s.getData();
  auto dd = ds.getData();
  for (std::size_t i = 0; i < s.getLocalLength(); ++i) local += std::log1p(alpha * dd[i] / sd[i]);
  double global = local;
  Teuchos::reduceAll(*s.getMap()->getComm(), Teuchos::REDUCE_SUM, 1, &local, &global);
  return global;
}

double globalMin(const Vector& x) {
  double local = std::numeric_limits<double>::infinity();
  auto xd = x.getData();
  for (std::size_t i = 0; i < x.getLocalLength(); ++i) local = std::min(local, xd[i]);
  double global = local;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_MIN, 1, &local, &global);
  return global;
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
                     "can be built from the initial guess; use method \"primal-dual\"");

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

}  // namespace

SolveResult solvePrimalBarrier(const ContactQP& qp, const Teuchos::ParameterList& p, const Vector* v0,
                               IterationObserver& observer) {
  Teuchos::Time timer("primal");
  timer.start(true);
  const auto vmap = qp.Q->getDomainMap();
  const auto cmap = qp.A->getRangeMap();
  const long long m = cmap->getGlobalNumElements();
  observer.onStart("primal (Algorithm 3.1)", vmap->getGlobalNumElements(), m);

  SolveResult result;
  NewtonSystemSolver newton(qp, p);
  RCP<Vector> v = initialDisplacement(qp, v0);
  Vector D(cmap);
  newton.setWeights(D);
  const ProblemScales scales = problemScales(qp, newton, *v);
  result.krylovIterations += scales.krylovIterations;
  const double margin = p.get<double>("primal: starting margin") * scales.displacement;
  const bool relaxed = p.get<std::string>("primal: starting point") == "relaxed";
  const bool extrapolate = p.get<bool>("primal: extrapolation");
  if (!relaxed) shiftIntoInterior(qp, *v, margin);

  const double tol = p.get<double>("kkt: tolerance");
  const int maxIterations = p.get<int>("maximum iterations");
  const int maxInner = p.get<int>("primal: maximum inner iterations");
  const double delta = p.get<double>("primal: delta"), tau = p.get<double>("primal: tau");
  const double ftb = p.get<double>("primal: fraction to boundary");
  const bool adaptiveGamma = p.get<bool>("gamma: adaptive");
  const int few = p.get<int>("gamma: few inner iterations");
  const int successive = p.get<int>("gamma: successive main iterations");
  const double gammaDecrease = p.get<double>("gamma: decrease factor"), gammaMin = p.get<double>("gamma: min");
  const double gammaIncrease = p.get<double>("gamma: increase factor"), gammaMax = p.get<double>("gamma: max");
  const double bnorm = qp.b->norm2();
  double mu = p.get<double>("primal: mu0"), zeta = p.get<double>("primal: zeta0"), gamma = p.get<double>("primal: gamma");
  if (mu <= 0) mu = p.get<double>("starting point: complementarity") * scales.energy / std::max(m, 1LL);
  if (zeta <= 0) zeta = bnorm > 0 ? bnorm : 1.0;
  ForcingRule forcing = forcingRule(p, 0.1 * tol * bnorm);

  Vector s(cmap), y(cmap), lambda(cmap), Adv(cmap), minusAdv(cmap), Qv(vmap), g(vmap), dv(vmap), Qdv(vmap), rhs(vmap);
  // The slack s = d - A v is computed once and then updated with each step, s <- s - alpha A dv:
  // recomputing it from v would cancel digits on the nearly active constraints, where
  // y = mu / s needs them most.
  qp.A->apply(*v, s);
  s.update(1.0, *qp.d, -1.0);
  // The relaxed set S_varsigma = {A v - d <= varsigma} of section 3.2 contains the initial
  // guess strictly; varsigma is then driven to zero with mu.
  double varsigma = 0;
  if (relaxed) {
    varsigma = std::max(0.0, -globalMin(s)) + margin;
    shiftAll(s, varsigma);
  }
  // y = mu / s, g = Q v - b + A^T y
  auto evaluate = [&]() {
    y.reciprocal(s);
    y.scale(mu);
    qp.Q->apply(*v, Qv);
    g.update(1.0, Qv, -1.0, *qp.b, 0.0);
    qp.A->apply(y, g, Teuchos::TRANS, 1.0, 1.0);
    ++result.gradientEvaluations;
    return g.norm2();
  };

  int fewInARow = 0;
  bool failed = false;
  for (int k = 0;; ++k) {
    int inner = 0;
    forcing.restart();  // a new barrier subproblem
    for (;;) {
      const double gnorm = evaluate();
      if (!std::isfinite(gnorm)) {
        result.status = SolveStatus::NumericalBreakdown;
        result.message = "non-finite gradient; check the problem data (Q must be positive definite)";
        failed = true;
        break;
      }
      if (inner > 0 && gnorm < zeta) break;
      if (inner == maxInner) {
        result.status = SolveStatus::NumericalBreakdown;
        char values[96];
        std::snprintf(values, sizeof values, "%.3e in %d steps at mu = %.3e", zeta, maxInner, mu);
        result.message = std::string("the inner Newton loop did not reach ||grad psi|| < ") + values +
                         ": the barrier Hessian is too ill-conditioned for the target; loosen Solver/kkt: "
                         "tolerance, or use Solver/method = primal-dual";
        failed = true;
        break;
      }

      {
        auto sd = s.getData();
        auto dd = D.getDataNonConst();
        for (std::size_t i = 0; i < s.getLocalLength(); ++i) dd[i] = mu / (sd[i] * sd[i]);
      }
      newton.setWeights(D);
      rhs.update(-1.0, g, 0.0);
      const double residualScale = gnorm * std::min(1.0, std::sqrt(gnorm / (bnorm > 0 ? bnorm : 1.0)));
      const double tolAbs = std::min(0.5 * gnorm, forcing.tolerance(gnorm, residualScale, gnorm));
      ++result.newtonSteps;
      int krylov = 0;
      double slope = 0.0;
      // Solves for the direction dv, `tighter` times tighter than the forcing asks, counts the
      // iterations, and updates its slope g^T dv.
      auto solveDirection = [&](double tighter, bool fromDirection) {
        const int iterations =
            newton.solve(rhs, dv, tighter * tolAbs, fromDirection, tighter * forcing.startReduction(),
                         tighter * forcing.floor).iterations;
        krylov += iterations;
        result.krylovIterations += iterations;
        result.maxKrylovPerNewton = std::max(result.maxKrylovPerNewton, krylov);
        slope = g.dot(dv);
      };
      solveDirection(1.0, false);
      if (!(slope < 0)) solveDirection(1e-3, false);  // no descent: once more, much tighter
      if (!(slope < 0)) {
        result.status = SolveStatus::KrylovFailure;
        result.message = "the Krylov solver returned no descent direction; raise Solver/Krylov/maximum "
                         "iterations or choose a stronger Solver/Preconditioner";
        failed = true;
        break;
      }

      // Fraction to the boundary (28), then Armijo backtracking on psi, evaluated without
      // further operator applications: psi is quadratic plus a sum of logs along the line.
      // A direction that finds no decrease is solved once more, much tighter, and searched
      // again: near round-off a loosely solved direction's slope can be all error.
      double alpha = 0.0;
      int halvings = 0;
      for (int attempt = 0; attempt < 2; ++attempt) {
        if (attempt == 1) {
          solveDirection(1e-3, true);
          if (!(slope < 0)) break;
        }
        qp.A->apply(dv, Adv);
        minusAdv.update(-1.0, Adv, 0.0);
        alpha = std::min(1.0, ftb * maxStepToBoundary(s, minusAdv));
        qp.Q->apply(dv, Qdv);
        const double linear = Qv.dot(dv) - qp.b->dot(dv), quadratic = 0.5 * Qdv.dot(dv);
        auto psiChange = [&](double a) {  // psi(v + a dv) - psi(v)
          ++result.functionEvaluations;
          return a * linear + a * a * quadratic - mu * logChange(s, a, minusAdv);
        };
        halvings = 0;
        while (!(psiChange(alpha) <= tau * alpha * slope) && halvings < 60) {
          alpha *= 0.5;
          ++halvings;
        }
        if (halvings < 60) break;
      }
      if (halvings == 60 || !(slope < 0)) {
        result.status = SolveStatus::LineSearchFailure;
        result.message = "no Armijo decrease along the Newton direction; tighten Solver/forcing: eta";
        failed = true;
        break;
      }
      v->update(alpha, dv, 1.0);
      ++inner;

      NewtonStepRecord record;
      record.outer = k + 1;
      record.inner = inner;
      record.mu = mu;
      record.step = alpha;
      record.krylovIterations = krylov;
      s.update(-alpha, Adv, 1.0);
      lambda.reciprocal(s);
      lambda.scale(-mu);
      record.kkt = kktMeasures(qp, *v, lambda);
      Qv.update(alpha, Qdv, 1.0);  // Q v at the new point, without another operator application
      record.objective = objective(qp, *v, Qv);
      record.seconds = timer.totalElapsedTime(true);
      result.history.push_back(record);
      observer.onNewtonStep(record);
    }
    if (failed) break;
    result.innerIterations.push_back(inner);
    result.outerIterations = k + 1;

    lambda.update(-1.0, y, 0.0);
    if (kktMeasures(qp, *v, lambda).worst() <= tol) {
      result.status = SolveStatus::Converged;
      result.message = convergedMessage(tol);
      break;
    }
    if (k + 1 == maxIterations) {
      result.status = SolveStatus::IterationLimit;
      result.message = "maximum iterations (" + std::to_string(maxIterations) +
                       ") reached; raise Solver/maximum iterations or loosen Solver/kkt: tolerance";
      break;
    }
    if (adaptiveGamma) {
      fewInARow = inner < few ? fewInARow + 1 : 0;
      if (fewInARow >= successive) {
        gamma = std::max(gammaMin, gammaDecrease * gamma);
        fewInARow = 0;
      } else if (inner > few) {
        gamma = std::min(gammaMax, gammaIncrease * gamma);
      }
    }
    const double previousMu = mu;
    mu *= gamma;
    // The relaxation of S_varsigma shrinks with mu.
    const double dvarsigma = varsigma * (gamma - 1.0);
    if (extrapolate) {
      // Predictor along the central path: differentiating grad psi = 0 with s = d + varsigma - A v,
      // H dv = -(dmu) A^T (1/s) + mu A^T (dvarsigma / s^2), so the next subproblem starts near
      // its solution instead of where the old one ended.
      {
        auto sd = s.getData();
        auto dd = D.getDataNonConst();
        auto wd = y.getDataNonConst();
        for (std::size_t i = 0; i < s.getLocalLength(); ++i) {
          dd[i] = previousMu / (sd[i] * sd[i]);
          wd[i] = (previousMu - mu) / sd[i] + previousMu * dvarsigma / (sd[i] * sd[i]);
        }
      }
      newton.setWeights(D);
      qp.A->apply(y, rhs, Teuchos::TRANS);
      const KrylovResult kr = newton.solve(rhs, dv, std::max(forcing.floor, 0.01 * rhs.norm2()));
      ++result.newtonSteps;
      result.krylovIterations += kr.iterations;
      result.maxKrylovPerNewton = std::max(result.maxKrylovPerNewton, kr.iterations);
      qp.A->apply(dv, Adv);
      minusAdv.putScalar(dvarsigma);  // the slack's change: dvarsigma - A dv
      minusAdv.update(-1.0, Adv, 1.0);
      const double alpha = std::min(1.0, ftb * maxStepToBoundary(s, minusAdv));
      v->update(alpha, dv, 1.0);
      s.update(alpha, minusAdv, 1.0);
      varsigma += alpha * dvarsigma;
    } else if (varsigma > 0) {
      // Without the predictor, shrink the relaxation by at most 90% of the smallest slack,
      // so the iterate stays strictly inside.
      const double next = std::max(varsigma + dvarsigma, varsigma - 0.9 * globalMin(s));
      shiftAll(s, next - varsigma);
      varsigma = next;
    }
    if (varsigma > 0 && varsigma < 1e-3 * tol * scales.displacement && globalMin(s) > 2 * varsigma) {
      shiftAll(s, -varsigma);  // close enough: back to the original constraints
      varsigma = 0;
    }
    // Below the stationarity the KKT target asks for, a tighter inner loop buys nothing.
    zeta = std::max(delta * zeta, 0.1 * tol * bnorm);
  }

  result.preconditionerSetups = newton.preconditionerSetups();
  finishResult(qp, *v, lambda, s, result);
  result.seconds = timer.totalElapsedTime(true);
  observer.onFinish(result);
  return result;
}

}  // namespace signorini::detail
