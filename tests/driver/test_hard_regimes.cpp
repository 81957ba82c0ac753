// Hard regimes: problem M (2D P1) or B (3D) with one thing pushed to an extreme converges to
// the default KKT tolerance with the default solver, to the solution of an independent solve
// of the same discrete problem (the active-set reference, on rank 0).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Tpetra_Core.hpp>

#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/ActiveSetReference.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::shippedProblem;

// The family's load T4(2x - 1) with x measured in units of `length`, times `scale`.
std::string familyLoad(double scale, double length) {
  const std::string t = "(2*x/" + std::to_string(length) + "-1)";
  return std::to_string(-scale) + "*(8*" + t + "^4 - 8*" + t + "^2 + 1)";
}

SolveResult solve(const Teuchos::ParameterList& problem, double* difference = nullptr) {
  const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  SolveResult r = InteriorPointSolver(Teuchos::ParameterList()).solve(p.qp, p.multigrid);
  if (difference) *difference = r.converged() ? signorini::testing::differenceToReference(problem, p.multigrid, *r.v) : 0.0;
  return r;
}

// Converged to the KKT tolerance, and to the reference's displacements to 1e-7 of their size
// (a solution perturbed by 1e-6 of it fails).
void expectConverges(const Teuchos::ParameterList& problem, const std::string& what) {
  double difference = 0;
  const SolveResult r = solve(problem, &difference);
  ASSERT_TRUE(r.converged()) << what << ": " << r.message;
  EXPECT_LE(r.kkt.worst(), 1e-8) << what;
  EXPECT_LT(difference, 1e-7) << what;
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
    const std::string what = "gap " + std::to_string(gap);
    expectConverges(problem, what);
    if (gap == 1e2) {
      EXPECT_EQ(solve(problem).activeConstraints, 0) << what;  // the body never reaches the plane
    }
  }
}

TEST(HardRegimes, LoadPullingAwayFromTheObstacle) {
  Teuchos::ParameterList problem = shippedProblem("paper/M");
  problem.set("body force: y", "1");
  expectConverges(problem, "pulled");
  EXPECT_EQ(solve(problem).activeConstraints, 0);
}

TEST(HardRegimes, EveryConstraintActive) {
  Teuchos::ParameterList problem = shippedProblem("paper/M");
  problem.set("body force: y", "-1");
  problem.sublist("Contact").set("gap: value", -1e-3);  // the plane pushes every node up
  expectConverges(problem, "every constraint active");
  EXPECT_EQ(solve(problem).activeConstraints, 11);
}

TEST(HardRegimes, CubicElementsIn3D) {
  Teuchos::ParameterList problem = shippedProblem("paper/B");
  problem.set("element: degree", 3);
  expectConverges(problem, "3D P3");
}

}  // namespace
