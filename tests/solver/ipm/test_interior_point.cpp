// The interior point solvers: QPs with known solutions, the whole benchmark family against
// an independent active-set solve, and independence of the rank count.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/ActiveSetReference.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

Teuchos::ParameterList method(const std::string& name) {
  Teuchos::ParameterList p;
  p.set("method", name);
  return p;
}

double relativeDifference(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// A QP with a known solution: Q = tridiag(-1, 3, -1) (n = 40, distributed), A = -I on the
// even unknowns, and (v*, y*) chosen first: constraint i is active where y*_i > 0. Pattern
// "degenerate" is "half" with a zero gap on the other constraints too: they are active with
// a zero multiplier (strict complementarity fails there).
struct KnownQP {
  ContactQP qp;
  RCP<Vector> vStar, lambdaStar;
};

KnownQP knownQP(const std::string& activePattern) {
  auto comm = Tpetra::getDefaultComm();
  const long long n = 40, m = 20;
  auto vmap = rcp(new Map(n, 0, comm));
  auto cmap = rcp(new Map(m, 0, comm));
  auto Q = rcp(new CrsMatrix(vmap, 3));
  for (std::size_t i = 0; i < vmap->getNodeNumElements(); ++i) {
    const GlobalOrdinal row = vmap->getGlobalElement(i);
    for (GlobalOrdinal col : {row - 1, row, row + 1})
      if (col >= 0 && col < n) {
        const double value = col == row ? 3.0 : -1.0;
        Q->insertGlobalValues(row, 1, &value, &col);
      }
  }
  Q->fillComplete();
  auto A = rcp(new CrsMatrix(cmap, 1));
  for (std::size_t k = 0; k < cmap->getNodeNumElements(); ++k) {
    const GlobalOrdinal row = cmap->getGlobalElement(k), col = 2 * row;
    const double value = -1.0;
    A->insertGlobalValues(row, 1, &value, &col);
  }
  A->fillComplete(vmap, cmap);

  KnownQP known;
  known.vStar = rcp(new Vector(vmap));
  auto y = rcp(new Vector(cmap)), gap = rcp(new Vector(cmap));
  {
    auto v = known.vStar->getDataNonConst();
    for (long i = 0; i < v.size(); ++i) v[i] = std::sin(0.3 * vmap->getGlobalElement(i));
    auto yd = y->getDataNonConst();
    auto gd = gap->getDataNonConst();
    for (long k = 0; k < yd.size(); ++k) {
      const GlobalOrdinal row = cmap->getGlobalElement(k);
      const bool even = row % 2 == 0;
      const bool active = activePattern == "all" || (activePattern != "none" && even);
      yd[k] = active ? 0.5 + 0.01 * row : 0.0;
      gd[k] = active || activePattern == "degenerate" ? 0.0 : 0.2;
    }
  }
  // d = A v* + gap; b = Q v* + A^T y*.
  auto d = rcp(new Vector(*gap, Teuchos::Copy)), b = rcp(new Vector(vmap));
  A->apply(*known.vStar, *d, Teuchos::NO_TRANS, 1.0, 1.0);
  Q->apply(*known.vStar, *b);
  A->apply(*y, *b, Teuchos::TRANS, 1.0, 1.0);
  known.qp.Q = Q;
  known.qp.A = A;
  known.qp.b = b;
  known.qp.d = d;
  known.lambdaStar = rcp(new Vector(cmap));
  known.lambdaStar->update(-1.0, *y, 0.0);
  return known;
}

TEST(InteriorPoint, KnownSolutionsToRoundOff) {
  for (const char* pattern : {"none", "half", "all"})
    for (const char* name : {"primal-dual", "primal"}) {
      KnownQP known = knownQP(pattern);
      Teuchos::ParameterList params = method(name);
      const double tol = 1e-13;
      params.set("kkt: tolerance", tol);
      IterationLog log(std::cout, std::getenv("SIGNORINI_TEST_LOG") != nullptr);
      SolveResult r = InteriorPointSolver(params).solve(known.qp, MultigridInput(), nullptr, &log);
      ASSERT_TRUE(r.converged()) << name << " " << pattern << ": " << r.message;
      Vector dv(*r.v, Teuchos::Copy);
      dv.update(-1.0, *known.vStar, 1.0);
      EXPECT_LT(dv.normInf(), 100 * tol * known.vStar->normInf()) << name << " " << pattern;
      Vector dl(*r.lambda, Teuchos::Copy);
      dl.update(-1.0, *known.lambdaStar, 1.0);
      EXPECT_LT(dl.normInf(), 1e4 * tol * known.lambdaStar->normInf() + 1e3 * tol) << name << " " << pattern;
      const long long expectedActive = std::string(pattern) == "none" ? 0 : std::string(pattern) == "half" ? 10 : 20;
      EXPECT_EQ(r.activeConstraints, expectedActive) << name << " " << pattern;
    }
}

// Where strict complementarity fails, a gap s and multiplier y that both vanish reach
// s y ~ mu together, so each is O(sqrt(mu)): stopping at a tolerance tol leaves v and lambda
// O(sqrt(tol)) from the solution, not O(tol). Which of the degenerate constraints are counted
// active is a matter of round-off.
TEST(InteriorPoint, DegenerateKnownSolutionToTheSquareRootOfTheTolerance) {
  for (const char* name : {"primal-dual", "primal"}) {
    KnownQP known = knownQP("degenerate");
    Teuchos::ParameterList params = method(name);
    const double tol = 1e-13;
    params.set("kkt: tolerance", tol);
    IterationLog log(std::cout, std::getenv("SIGNORINI_TEST_LOG") != nullptr);
    SolveResult r = InteriorPointSolver(params).solve(known.qp, MultigridInput(), nullptr, &log);
    ASSERT_TRUE(r.converged()) << name << ": " << r.message;
    Vector dv(*r.v, Teuchos::Copy);
    dv.update(-1.0, *known.vStar, 1.0);
    EXPECT_LT(dv.normInf(), 10 * std::sqrt(tol) * known.vStar->normInf()) << name;
    Vector dl(*r.lambda, Teuchos::Copy);
    dl.update(-1.0, *known.lambdaStar, 1.0);
    EXPECT_LT(dl.normInf(), 10 * std::sqrt(tol) * known.lambdaStar->normInf()) << name;
    EXPECT_GE(r.activeConstraints, 10) << name;
    EXPECT_LE(r.activeConstraints, 20) << name;
  }
}

// The active-set reference, computed on rank 0 on a one-rank copy of the problem with Q
// assembled (it factors Q).
double referenceObjective(Teuchos::ParameterList problem) {
  auto comm = Tpetra::getDefaultComm();
  double objective = 0;
  int converged = 0;
  problem.set("stiffness: operator", "assembled");
  if (comm->getRank() == 0) {
    AssembledProblem serial = buildSerial(problem);
    Teuchos::Time t("reference");
    t.start();
    ReferenceSolution ref = activeSetSolve(serial.qp);
    if (std::getenv("SIGNORINI_TEST_LOG"))
      std::cout << "reference: " << ref.iterations << " active-set iterations, " << t.stop() << " s\n";
    objective = ref.objective;
    converged = ref.converged;
  }
  Teuchos::broadcast(*comm, 0, 1, &objective);
  Teuchos::broadcast(*comm, 0, 1, &converged);
  EXPECT_TRUE(converged) << "active-set reference did not converge";
  return objective;
}

void expectFamilyMatchesReference(const std::string& name, const std::vector<std::string>& methods) {
  const Teuchos::ParameterList problem = shippedProblem("paper/" + name);
  const double reference = referenceObjective(problem);
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  for (const std::string& m : methods) {
    SolveResult r = InteriorPointSolver(method(m)).solve(p.qp, p.multigrid);
    if (std::getenv("SIGNORINI_TEST_LOG")) std::cout << name << " " << m << ": " << r.seconds << " s\n";
    EXPECT_TRUE(r.converged()) << name << " " << m << ": " << r.message;
    EXPECT_LE(r.kkt.worst(), 1e-8) << name << " " << m;
    EXPECT_LT(relativeDifference(r.objective, reference), 1e-8)
        << name << " " << m << ": " << r.objective << " vs reference " << reference;
  }
}

// Both methods on every problem of the family, F included.
TEST(InteriorPoint, Family2DBothMethodsMatchTheActiveSetReference) {
  for (const char* name : {"A", "G", "H", "I", "J", "K", "M"}) expectFamilyMatchesReference(name, {"primal-dual", "primal"});
}

TEST(InteriorPoint, Family3DBothMethodsMatchTheActiveSetReference) {
  for (const char* name : {"B", "C", "D", "E", "F", "L"}) expectFamilyMatchesReference(name, {"primal-dual", "primal"});
}

// The same problem solved on this communicator and on one rank: same n and m, same optimal
// value to 1e-10 relative, main iterations within one. Krylov counts may differ with the
// parallel smoother: the spread is printed, and bounded by a factor 1.5.
TEST(InteriorPoint, ResultsDoNotDependOnTheRankCount) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* name : {"M", "H", "B", "E"})
    for (const char* m : {"primal-dual", "primal"}) {
      const Teuchos::ParameterList problem = shippedProblem(std::string("paper/") + name);
      const AssembledProblem assembled = buildProblem(problem, comm);
      const ContactQP& qp = assembled.qp;
      const AssembledProblem serialProblem = buildSerial(problem);
      const ContactQP& serialQP = serialProblem.qp;
      EXPECT_EQ(qp.Q->getDomainMap()->getGlobalNumElements(), serialQP.Q->getDomainMap()->getGlobalNumElements());
      EXPECT_EQ(qp.A->getGlobalNumRows(), serialQP.A->getGlobalNumRows());
      SolveResult parallel = InteriorPointSolver(method(m)).solve(qp, assembled.multigrid);
      SolveResult serial = InteriorPointSolver(method(m)).solve(serialQP, serialProblem.multigrid);
      ASSERT_TRUE(parallel.converged() && serial.converged()) << name << " " << m;
      EXPECT_LT(relativeDifference(parallel.objective, serial.objective), 1e-10) << name << " " << m;
      EXPECT_LE(std::abs(parallel.outerIterations - serial.outerIterations), 1) << name << " " << m;
      const double spread = static_cast<double>(parallel.krylovIterations) / serial.krylovIterations;
      EXPECT_LT(std::max(spread, 1.0 / spread), 1.5) << name << " " << m;
      if (comm->getRank() == 0)
        std::cout << "  " << name << " " << m << " on " << comm->getSize() << " ranks: it " << parallel.outerIterations
                  << " (1 rank: " << serial.outerIterations << "), Krylov " << parallel.krylovIterations
                  << " (1 rank: " << serial.krylovIterations << ")\n";
    }
}

TEST(InteriorPoint, FixedCenteringWithMeritBacktrackingConverges) {
  for (const char* name : {"M", "G"}) {
    Teuchos::ParameterList params = method("primal-dual");
    params.set("primal-dual: centering", "fixed");
    const Teuchos::ParameterList problem = shippedProblem(std::string("paper/") + name);
    SolveResult r = InteriorPointSolver(params).solve(buildProblem(problem, Tpetra::getDefaultComm()).qp);
    EXPECT_TRUE(r.converged()) << name << ": " << r.message;
    EXPECT_GT(r.functionEvaluations, 0) << name;
    EXPECT_LT(relativeDifference(r.objective, referenceObjective(problem)), 1e-8) << name;
  }
}

// A user guess far outside the feasible set (every node pushed 0.1 into the obstacle).
TEST(InteriorPoint, InfeasibleInitialGuessIsAccepted) {
  const Teuchos::ParameterList problem = shippedProblem("paper/G");
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  Vector guess(p.qp.Q->getDomainMap());
  {
    auto g = guess.getDataNonConst();
    for (long i = 1; i < g.size(); i += 2) g[i] = -0.1;
  }
  const double reference = referenceObjective(problem);
  for (const char* m : {"primal-dual", "primal"}) {
    SolveResult r = InteriorPointSolver(method(m)).solve(p.qp, p.multigrid, &guess);
    EXPECT_TRUE(r.converged()) << m << ": " << r.message;
    EXPECT_LT(relativeDifference(r.objective, reference), 1e-8) << m;
  }
}

// The relaxed set S_varsigma (section 3.2) instead of the shift as the primal method's start.
TEST(InteriorPoint, RelaxedStartingPointConverges) {
  for (const char* name : {"M", "B"}) {
    Teuchos::ParameterList params = method("primal");
    params.set("primal: starting point", "relaxed");
    const Teuchos::ParameterList problem = shippedProblem(std::string("paper/") + name);
    SolveResult r = InteriorPointSolver(params).solve(buildProblem(problem, Tpetra::getDefaultComm()).qp);
    EXPECT_TRUE(r.converged()) << name << ": " << r.message;
    EXPECT_LE(r.kkt.primalFeasibility, 1e-8) << name;
    EXPECT_LT(relativeDifference(r.objective, referenceObjective(problem)), 1e-8) << name;
  }
}

// Every forcing rule and the selectable Belos solvers reach the same solution.
TEST(InteriorPoint, ForcingRulesAndKrylovSolversAreSelectable) {
  const Teuchos::ParameterList problem = shippedProblem("paper/G");
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  const double reference = referenceObjective(problem);
  for (const char* forcing : {"adaptive", "constant", "eisenstat-walker", "relative"})
    for (const char* m : {"primal-dual", "primal"}) {
      Teuchos::ParameterList params = method(m);
      params.set("forcing: type", forcing);
      params.set("forcing: eta", std::string(forcing) == "relative" ? 1e-10 : 0.01);
      SolveResult r = InteriorPointSolver(params).solve(p.qp, p.multigrid);
      EXPECT_TRUE(r.converged()) << forcing << " " << m << ": " << r.message;
      EXPECT_LT(relativeDifference(r.objective, reference), 1e-8) << forcing << " " << m;
    }
  {
    Teuchos::ParameterList params = method("primal-dual");
    params.set("primal-dual: corrector from predictor", false);  // the default is true
    SolveResult r = InteriorPointSolver(params).solve(p.qp, p.multigrid);
    EXPECT_TRUE(r.converged()) << "corrector from zero: " << r.message;
    EXPECT_LT(relativeDifference(r.objective, reference), 1e-8) << "corrector from zero";
  }
  for (const char* krylov : {"MINRES", "GMRES"}) {
    Teuchos::ParameterList params = method("primal-dual");
    params.sublist("Krylov").set("solver", krylov);
    SolveResult r = InteriorPointSolver(params).solve(p.qp, p.multigrid);
    EXPECT_TRUE(r.converged()) << krylov << ": " << r.message;
    EXPECT_LT(relativeDifference(r.objective, reference), 1e-8) << krylov;
  }
}

TEST(InteriorPoint, IterationLimitIsReportedWithAHint) {
  Teuchos::ParameterList params = method("primal-dual");
  params.set("maximum iterations", 2);
  SolveResult r = InteriorPointSolver(params).solve(buildProblem(shippedProblem("paper/M"), Tpetra::getDefaultComm()).qp);
  EXPECT_EQ(r.status, SolveStatus::IterationLimit);
  EXPECT_NE(r.message.find("maximum iterations"), std::string::npos);
}

// The forcing safety stays below 1: at 1 a step need not reduce the dual residual.
TEST(InteriorPoint, ForcingSafetyIsLimitedBelowOne) {
  Teuchos::ParameterList params = method("primal-dual");
  params.set("forcing: safety", 0.9);
  EXPECT_NO_THROW(InteriorPointSolver{params});
  params.set("forcing: safety", 1.0);
  EXPECT_THROW(InteriorPointSolver{params}, InputError);
}

// The message names the tolerance met (std::to_string printed 1e-7 as 0.000000).
TEST(InteriorPoint, ConvergedMessageNamesTheTolerance) {
  AssembledProblem p = buildProblem(shippedProblem("paper/M"), Tpetra::getDefaultComm());
  for (const char* m : {"primal-dual", "primal"}) {
    Teuchos::ParameterList params = method(m);
    params.set("kkt: tolerance", 1e-7);
    SolveResult r = InteriorPointSolver(params).solve(p.qp, p.multigrid);
    EXPECT_TRUE(r.converged()) << m << ": " << r.message;
    EXPECT_EQ(r.message, "every relative KKT measure is below 1e-07") << m;
  }
}

// Without a contact boundary (m = 0) the QP is Q v = b: one Krylov solve, whichever method,
// matching an independent CG + MueLu solve of the same system.
TEST(InteriorPoint, NoConstraintsIsOneLinearSolve) {
  Teuchos::ParameterList problem = shippedProblem("paper/J");
  problem.remove("Contact");
  const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  ASSERT_EQ(p.qp.A->getRangeMap()->getGlobalNumElements(), 0u);
  Vector reference(p.qp.Q->getDomainMap());
  ASSERT_GT(solveLinear(p.qp, p.multigrid, reference, 1e-12 * p.qp.b->norm2()), 0);
  for (const char* name : {"primal-dual", "primal"}) {
    const SolveResult r = InteriorPointSolver(method(name)).solve(p.qp, p.multigrid);
    ASSERT_TRUE(r.converged()) << name << ": " << r.message;
    EXPECT_EQ(r.newtonSteps, 1) << name;
    EXPECT_EQ(r.outerIterations, 0) << name;
    EXPECT_LE(r.kkt.stationarity, 1e-8) << name;
    Vector difference(*r.v, Teuchos::Copy);
    difference.update(-1.0, reference, 1.0);
    EXPECT_LT(difference.normInf(), 1e-6 * reference.normInf()) << name;
  }
}

}  // namespace
