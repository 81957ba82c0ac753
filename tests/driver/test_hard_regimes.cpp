// Hard regimes: problem M (2D P1) or B (3D) with one thing pushed to an extreme converges to
// the default KKT tolerance with the default solver.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Tpetra_Core.hpp>

#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::shippedProblem;

// The family's load T4(2x - 1) with x measured in units of `length`, times `scale`.
std::string familyLoad(double scale, double length) {
  const std::string t = "(2*x/" + std::to_string(length) + "-1)";
  return std::to_string(-scale) + "*(8*" + t + "^4 - 8*" + t + "^2 + 1)";
}

SolveResult solve(const Teuchos::ParameterList& problem) {
  const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  return InteriorPointSolver(Teuchos::ParameterList()).solve(p.qp);
}

void expectConverges(const Teuchos::ParameterList& problem, const std::string& what) {
  const SolveResult r = solve(problem);
  EXPECT_TRUE(r.converged()) << what << ": " << r.message;
  EXPECT_LE(r.kkt.worst(), 1e-8) << what;
}

TEST(HardRegimes, NearlyIncompressibleMaterial) {
  for (double nu : {0.49, 0.499, 0.4999}) {
    Teuchos::ParameterList problem = shippedProblem("paper/M");
    problem.set("material: poisson ratio", nu);
    expectConverges(problem, "nu = " + std::to_string(nu));
  }
}

TEST(HardRegimes, UnitsOfSteelInMetresMillimetresAndKilometres) {
  // E = 210 GPa and the weight density of steel, 77 kN/m^3, in N and m, mm or km.
  struct Units {
    const char* name;
    double metre;  // one metre in these units of length
  };
  for (const Units u : {Units{"m", 1.0}, Units{"mm", 1e3}, Units{"km", 1e-3}}) {
    Teuchos::ParameterList problem = shippedProblem("paper/M");
    problem.set("mesh: lengths", Teuchos::Array<double>(2, u.metre));
    problem.set("material: young's modulus", 2.1e11 / (u.metre * u.metre));
    problem.set("body force: y", familyLoad(7.7e4 / (u.metre * u.metre * u.metre), u.metre));
    expectConverges(problem, u.name);
  }
}

TEST(HardRegimes, GapsFromTinyToNoContact) {
  for (double gap : {1e-8, 1e-4, 1e2}) {
    Teuchos::ParameterList problem = shippedProblem("paper/M");
    problem.sublist("Contact").set("gap: value", gap);
    const SolveResult r = solve(problem);
    EXPECT_TRUE(r.converged()) << "gap " << gap << ": " << r.message;
    if (gap == 1e2) {
      EXPECT_EQ(r.activeConstraints, 0);  // the body never reaches the plane
    }
  }
}

TEST(HardRegimes, LoadPullingAwayFromTheObstacle) {
  Teuchos::ParameterList problem = shippedProblem("paper/M");
  problem.set("body force: y", "1");
  const SolveResult r = solve(problem);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.activeConstraints, 0);
}

TEST(HardRegimes, EveryConstraintActive) {
  Teuchos::ParameterList problem = shippedProblem("paper/M");
  problem.set("body force: y", "-1");
  problem.sublist("Contact").set("gap: value", -1e-3);  // the plane pushes every node up
  const SolveResult r = solve(problem);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.activeConstraints, 11);
}

TEST(HardRegimes, CubicElementsIn3D) {
  Teuchos::ParameterList problem = shippedProblem("paper/B");
  problem.set("element: degree", 3);
  expectConverges(problem, "3D P3");
}

}  // namespace
