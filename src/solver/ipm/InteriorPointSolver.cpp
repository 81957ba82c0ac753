#include "signorini/solver/InteriorPointSolver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/ParameterValidation.hpp"
#include "signorini/core/Error.hpp"
#include "solver/ContactQPChecks.hpp"
#include "solver/RigidBodySupport.hpp"
#include "solver/ipm/InteriorPointMethods.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"
#include "solver/linear/StiffnessParts.hpp"

namespace signorini {

using detail::Centering;
using detail::ForcingType;
using detail::Method;
using detail::StartingPoint;

namespace {

// The truncated Newton forcing of both methods.
void addForcingParameters(Teuchos::ParameterList& p) {
  p.set("forcing: type", "reduction",
        "Truncated Newton forcing: \"reduction\" (each Krylov solve reduces its starting residual by "
        "eta, and reaches the adaptive residual scale times forcing: reduction safeguard), \"adaptive\" "
        "(follows the barrier parameter), \"constant\", \"eisenstat-walker\" or \"relative\"; "
        "see doc/algorithms.md",
        choices<ForcingType>({{"reduction", ForcingType::Reduction},
                              {"adaptive", ForcingType::Adaptive},
                              {"constant", ForcingType::Constant},
                              {"eisenstat-walker", ForcingType::EisenstatWalker},
                              {"relative", ForcingType::Relative}},
                             "forcing: type"));
  p.set("forcing: eta", 0.3, "Reduction of each solve's starting residual, constant forcing term, or the largest adaptive one", range(1e-14, 0.9));
  p.set("forcing: safety", 0.3,
        "Adaptive forcing: the residual allowed as a fraction of the current residual scale; below 1 so "
        "that every step reduces the dual residual",
        expert(range(1e-6, 0.9)));
  p.set("forcing: tail safety", 0.01,
        "Adaptive forcing of the primal-dual method once only stationarity is left (the active set has "
        "settled): used instead of forcing: safety, the dual residual falls by about this much per main "
        "iteration",
        expert(range(1e-6, 0.9)));
  p.set("forcing: reduction safeguard", 1.0,
        "Forcing \"reduction\": every solve also reaches this times the adaptive forcing's residual "
        "scale, so that the dual residual follows mu where the starting vectors stop improving",
        expert(range(1e-6, 1e6)));
}

void addPrimalDualParameters(Teuchos::ParameterList& p) {
  p.set("starting point: complementarity", 1.0,
        "Initial s^T y as a multiple of the energy scale |b^T v_hat| of the unconstrained solution "
        "(primal-dual)", expert(range(1e-12, 1e12)));

  p.set("primal-dual: centering", "mehrotra",
        "\"mehrotra\": predictor-corrector; \"fixed\": mu_{k+1} = (primal-dual: mu factor) mu_k with "
        "backtracking on 1/2 ||F||^2 (the paper's Algorithm 3.2)",
        choices<Centering>({{"mehrotra", Centering::Mehrotra}, {"fixed", Centering::Fixed}},
                           "primal-dual: centering"));
  p.set("primal-dual: mu factor", 0.2, "Fixed centering: factor of mu per iteration", range(1e-6, 0.999));
  p.set("primal-dual: corrector from predictor", true,
        "Mehrotra: start the corrector's Krylov solve from the predictor's step instead of zero (the "
        "right-hand sides differ by the centering and second-order terms only)", expert());
  p.set("primal-dual: fraction to boundary", 0.995, "Step kept this fraction inside s > 0, y > 0", range(0.5, 0.99999));
  p.set("primal-dual: active-set finish", true,
        "Once the active-set estimate has stayed the same over two long steps (but at nearly degenerate "
        "constraints, multiplier and gap both within 1% of their scales) and every KKT measure is "
        "within the square root of the tolerance, try one Newton step of the equality-constrained problem "
        "on that set (its constraints held with a penalty far below the tolerance, the others released) and "
        "stop there if it meets every KKT tolerance (see doc/algorithms.md)");
  p.set("primal-dual: armijo", 0.01, "Fixed centering: Armijo constant of the merit backtracking", expert(range(1e-8, 0.5)));
}

// The primal method's, with the paper's adaptive gamma rule.
void addPrimalParameters(Teuchos::ParameterList& p) {
  p.set("primal: mu0", -1.0,
        "Initial barrier parameter mu_0; -1: from the problem's scale, (starting point: "
        "complementarity) |b^T v_hat| / m (the paper: 1)");
  p.set("primal: zeta0", -1.0,
        "Initial inner tolerance zeta_0 on ||grad psi||; -1: ||b|| (the paper: 1500)");
  p.set("primal: delta", 0.2, "zeta_{k+1} = delta zeta_k (the paper: 0.5)", range(1e-6, 0.999999));
  p.set("primal: gamma", 0.2, "mu_{k+1} = gamma mu_k; the initial gamma when adaptive (the paper: 0.5)", range(1e-6, 0.999999));
  p.set("primal: tau", 0.01, "Armijo constant tau of the backtracking line search", expert(range(1e-8, 0.5)));
  p.set("primal: fraction to boundary", 0.99, "sigma in (28): first trial step min(1, sigma alpha_bar)",
        expert(range(0.5, 0.999999)));
  p.set("primal: maximum inner iterations", 50, "Newton steps allowed per main iteration", expert(range(1, 10000)));
  p.set("primal: extrapolation", true,
        "Start each barrier subproblem with a predictor step along the central path, "
        "H dv = (mu_k - mu_k+1) A^T (1/s) (not in the paper's Algorithm 3.1)", expert());
  p.set("primal: starting point", "shift",
        "How the primal method makes the initial guess strictly feasible: \"shift\" moves it along "
        "A^T (exact when each constraint acts on its own unknowns, as contact constraints do); "
        "\"relaxed\" solves over S_varsigma = {A v - d <= varsigma} and drives varsigma to zero with mu",
        choices<StartingPoint>({{"shift", StartingPoint::Shift}, {"relaxed", StartingPoint::Relaxed}},
                               "primal: starting point"));
  p.set("primal: starting margin", 0.1,
        "The initial guess is shifted so that every slack d - A v is at least this times the "
        "displacement scale of the unconstrained solution",
        expert(range(1e-12, 1e6)));
  p.set("gamma: adaptive", false,
        "Adapt gamma by the rule of the paper's section 4 (the paper: true); see doc/algorithms.md");
  p.set("gamma: few inner iterations", 3, "Fewer inner iterations than this count as few", expert(range(1, 1000)));
  p.set("gamma: successive main iterations", 3, "Few inner iterations this many times in a row lower gamma",
        expert(range(1, 1000)));
  p.set("gamma: decrease factor", 0.99, "gamma <- max(gamma: min, factor * gamma)", expert(range(1e-6, 1.0)));
  p.set("gamma: min", 0.54, "Lower bound in the decrease rule", expert(range(1e-6, 0.999999)));
  p.set("gamma: increase factor", 1.05, "gamma <- min(gamma: max, factor * gamma) after more inner iterations",
        expert(range(1.0, 100.0)));
  p.set("gamma: max", 0.99, "Upper bound in the increase rule", expert(range(1e-6, 0.999999)));
}

}  // namespace

Teuchos::ParameterList InteriorPointSolver::validParameters() {
  Teuchos::ParameterList p("Solver");
  p.set("method", "primal-dual", "\"primal-dual\" (Algorithm 3.2 with slack variables) or \"primal\" (Algorithm 3.1)",
        choices<Method>({{"primal-dual", Method::PrimalDual}, {"primal", Method::Primal}}, "method"));
  p.set("kkt: tolerance", 1e-8, "Stop when every relative KKT measure is at most this", range(1e-16, 1.0));
  p.set("maximum iterations", 200, "Main iterations allowed", range(1, 100000));
  addForcingParameters(p);
  addPrimalDualParameters(p);
  addPrimalParameters(p);
  p.setParameters(NewtonSystemSolver::validParameters());
  return p;
}

namespace {

// Loads or gaps whose 2-norm overflows double precision (entries beyond ~1e154) break every
// residual the solver measures: say so before the solve, in the problem's terms. Collective.
void checkRepresentableScale(const ContactQP& qp) {
  const auto refuse = [](const char* what, const Vector& x) {
    std::ostringstream message;
    message << "Problem: the " << what << " (largest entry " << std::setprecision(3) << x.normInf()
            << ") overflow double precision in the solver's norms; rescale the units";
    throw InputError(message.str());
  };
  if (!std::isfinite(qp.b->norm2())) refuse("loads and prescribed displacements", *qp.b);
  if (!std::isfinite(qp.d->norm2())) refuse("gaps", *qp.d);
}

}  // namespace

InteriorPointSolver::InteriorPointSolver(const Teuchos::ParameterList& params)
    : params_(validatedParameters(params, validParameters(), "Solver")) {}

SolveResult InteriorPointSolver::solve(const ContactQP& qp, const MultigridInput& multigrid,
                                       const Vector* initialGuess, IterationObserver* observer) const {
  IterationObserver silent;
  IterationObserver& obs = observer ? *observer : silent;
  checkContactQP(qp, multigrid);
  checkRepresentableScale(qp);
  const RCP<const MultiVector> freeMotions = checkRigidBodyMotionsHeld(qp, multigrid);
  if (qp.A->getRangeMap()->getGlobalNumElements() == 0)
    return detail::solveUnconstrained(qp, multigrid, params_, initialGuess, obs);
  if (choice<Method>(params_, "method") == Method::Primal)
    return detail::solvePrimalBarrier(qp, multigrid, params_, initialGuess, obs, freeMotions);
  return detail::solvePrimalDual(qp, multigrid, params_, initialGuess, obs, freeMotions);
}

namespace detail {

Vector constraintRowNorms(const CrsMatrix& A) {
  Vector rows(A.getRowMap());
  auto out = rows.getDataNonConst();
  for (std::size_t i = 0; i < A.getNodeNumRows(); ++i) {
    CrsMatrix::local_inds_host_view_type cols;
    CrsMatrix::values_host_view_type vals;
    A.getLocalRowView(static_cast<LocalOrdinal>(i), cols, vals);
    double sum = 0;
    for (std::size_t k = 0; k < vals.extent(0); ++k) sum += vals(k) * vals(k);
    out[i] = sum > 0 ? std::sqrt(sum) : 1.0;
  }
  if (A.getRowMap()->isSameAs(*A.getRangeMap())) return rows;
  Vector norms(A.getRangeMap());
  norms.doExport(rows, Export(A.getRowMap(), A.getRangeMap()), Tpetra::INSERT);
  return norms;
}

double maxStepToBoundary(const Vector& x, const Vector& dx) {
  double local = std::numeric_limits<double>::infinity();
  auto xd = x.getData();
  auto dd = dx.getData();
  for (std::size_t i = 0; i < x.getLocalLength(); ++i)
    if (dd[i] < 0) local = std::min(local, -xd[i] / dd[i]);
  return minOverRanks(*x.getMap()->getComm(), local);
}

double objective(const ContactQP& qp, const Vector& v, const Vector& Qv) {
  return 0.5 * Qv.dot(v) - qp.b->dot(v);
}

RCP<Vector> initialDisplacement(const ContactQP& qp, const Vector* v0) {
  auto v = rcp(new Vector(qp.Q->getDomainMap()));
  if (v0) {
    if (!v0->getMap()->isSameAs(*v->getMap())) throw InputError("initial guess: not on Q's domain map");
    v->assign(*v0);
  }
  return v;
}

ProblemScales problemScales(const ContactQP& qp, const MultigridInput& multigrid, NewtonSystemSolver& newton,
                            const Vector& v0,
                            bool freeWithoutContact) {
  // r = b - Q v0; Q w = r roughly; v_hat = v0 + w.
  Vector r(*qp.b, Teuchos::Copy), w(qp.Q->getDomainMap());
  qp.Q->apply(v0, r, Teuchos::NO_TRANS, -1.0, 1.0);
  ProblemScales scales;
  // Q is singular when only the contact holds the body: then estimate with every constraint
  // held by a spring of its own stiffness q_i.
  const StiffnessParts stiffness(qp, multigrid);
  const bool springs = qp.A->getGlobalNumRows() > 0 && stiffness.available() && freeWithoutContact;
  if (springs) newton.setWeights(*constraintStiffness(*stiffness.diagonal(), *qp.A));
  scales.krylovIterations = newton.solve(r, w, 1e-2 * r.norm2()).iterations;
  if (springs) newton.setWeights(Vector(qp.A->getRangeMap()));
  w.update(1.0, v0, 1.0);
  Vector c(qp.A->getRangeMap());
  qp.A->apply(w, c);
  c.update(-1.0, *qp.d, 1.0);
  const double candidates[] = {qp.d->getGlobalLength() ? c.normInf() : 0.0, w.normInf(), 1.0};
  for (double value : candidates)
    if (value > 0) {
      scales.displacement = value;
      break;
    }
  const double energy = std::abs(qp.b->dot(w));
  scales.energy = energy > 0 ? energy : 1.0;
  return scales;
}

void finishResult(const ContactQP& qp, const Vector& v, const Vector& lambda, const Vector& slack,
                  SolveResult& result) {
  Vector Qv(qp.Q->getRangeMap());
  qp.Q->apply(v, Qv);
  result.objective = objective(qp, v, Qv);
  result.v = rcp(new Vector(v, Teuchos::Copy));
  result.lambda = rcp(new Vector(lambda, Teuchos::Copy));
  result.kkt = kktMeasures(qp, v, lambda);
  const ActiveSetCriterion criterion(qp, v, lambda);
  long long local = 0;
  auto l = lambda.getData();
  auto s = slack.getData();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(lambda.getLocalLength()); ++i)
    local += criterion.isActive(i, l[i], s[i]);
  result.activeConstraints = sumOverRanks(*v.getMap()->getComm(), local);
}

bool stopWith(SolveResult& result, SolveStatus status, std::string message) {
  result.status = status;
  result.message = std::move(message);
  return false;
}

StoppingRule::StoppingRule(const Teuchos::ParameterList& params)
    : tolerance(params.get<double>("kkt: tolerance")), maxIterations(params.get<int>("maximum iterations")) {}

bool StoppingRule::converged(const KKTMeasures& kkt, SolveResult& result) const {
  if (kkt.worst() > tolerance) return false;
  char text[96];
  std::snprintf(text, sizeof text, "every relative KKT measure is below %g", tolerance);
  stopWith(result, SolveStatus::Converged, text);
  return true;
}

bool StoppingRule::outOfIterations(int iterations, SolveResult& result) const {
  if (iterations < maxIterations) return false;
  stopWith(result, SolveStatus::IterationLimit,
           "maximum iterations (" + std::to_string(maxIterations) +
               ") reached; raise Solver/maximum iterations or loosen Solver/kkt: tolerance");
  return true;
}

void countKrylovSolve(SolveResult& result, int iterations, int stepIterations) {
  result.krylovIterations += iterations;
  result.maxKrylovPerNewton = std::max(result.maxKrylovPerNewton, stepIterations);
}

double ForcingRule::tolerance(double rhsNorm, double residualScale, double nonlinearNorm) {
  switch (type) {
    case ForcingType::Reduction:
      return std::max(floor, reductionSafeguard * residualScale);
    case ForcingType::Constant:
      return std::max(floor, eta * nonlinearNorm);
    case ForcingType::Relative:
      return eta * rhsNorm;
    case ForcingType::Adaptive:
      return std::min(eta * rhsNorm, std::max(floor, (stationarityOnly ? tailSafety : safety) * residualScale));
    case ForcingType::EisenstatWalker:
      break;
  }
  double forcing = eta;
  if (nonlinearNorm == previousNorm) {
    forcing = previousEta;  // another solve for the same Newton step (Mehrotra's corrector)
  } else if (previousNorm > 0) {
    const double ratio = nonlinearNorm / previousNorm;
    forcing = 0.9 * ratio * ratio;
    const double safeguard = 0.9 * previousEta * previousEta;  // no sudden drop of eta
    if (safeguard > 0.1) forcing = std::max(forcing, safeguard);
    forcing = std::min(forcing, eta);
  }
  previousNorm = nonlinearNorm;
  previousEta = forcing;
  return std::max(floor, forcing * nonlinearNorm);
}

ForcingRule forcingRule(const Teuchos::ParameterList& params, double floor) {
  ForcingRule rule;
  rule.type = choice<ForcingType>(params, "forcing: type");
  rule.eta = params.get<double>("forcing: eta");
  rule.safety = params.get<double>("forcing: safety");
  rule.tailSafety = params.get<double>("forcing: tail safety");
  rule.reductionSafeguard = params.get<double>("forcing: reduction safeguard");
  rule.floor = floor;
  return rule;
}

}  // namespace detail
}  // namespace signorini
