// Force control: bodies that only their contact holds in the load's direction (a pressure
// on a face or a weight; the sides on rollers or the loaded face held sideways) converge with both methods
// on every rank count, the contact force equals the applied load, Hertz' solution holds for it,
// and the main iterations stay within 1.5 times those of the same body under displacement
// control. The problems are examples/hertz's force-controlled ones, a pressed box and a
// square held by two contact pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "core/Collectives.hpp"
#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

struct ControlledRun {
  SolveResult result;
  ContactStatistics stats;
  double load = 0;  // the applied force towards the obstacle: -sum of b's last components
  int dim = 0;
};

ControlledRun solve(const Teuchos::ParameterList& problem, const std::string& method, const std::string& directory = "") {
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm(), directory);
  Teuchos::ParameterList solver;
  solver.set("method", method);
  ControlledRun run;
  run.result = InteriorPointSolver(solver).solve(p.qp, p.multigrid);
  run.dim = p.definition.dim;
  const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap());
  const RCP<Vector> active = activeIndicator(p.qp, *run.result.v, *run.result.lambda);
  const RCP<Vector> pressure = recovery.recover(PressureRecovery::Auto, *run.result.lambda, *active);
  run.stats = contactStatistics(recovery, *pressure, *p.qp.A, *run.result.lambda, *active,
                                p.definition.contacts.front().obstacleDirection);
  auto b = p.qp.b->getData();
  double local = 0;
  for (std::size_t i = run.dim - 1; i < p.qp.b->getLocalLength(); i += run.dim) local -= b[i];
  run.load = sumOverRanks(*p.space->comm(), local);
  return run;
}

Teuchos::ParameterList example(const std::string& name) {
  return Teuchos::getParametersFromXmlFile(sourceDir() + "/examples/hertz/" + name + ".xml")->sublist("Problem");
}

// The same body with its loaded face moved by `approach` (the component "displacement: y"
// or "displacement: z" towards the obstacle) instead of pressed.
Teuchos::ParameterList underDisplacementControl(Teuchos::ParameterList problem, const std::string& face,
                                                const std::string& component, const std::string& approach) {
  problem.sublist("Traction").remove(face);
  problem.sublist("Dirichlet").sublist(face).set(component, approach);
  return problem;
}

// A unit box on the obstacle, its sides on rollers, pressed by a unit pressure on its top:
// uniform compression, a contact pressure of 1 everywhere.
Teuchos::ParameterList pressedBox(int dim) {
  Teuchos::ParameterList problem = boxProblem(dim, 6, 1);
  const char* sides[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  const char* components[3] = {"displacement: x", "displacement: y", "displacement: z"};
  for (int c = 0; c + 1 < dim; ++c)
    for (const char* side : sides[c]) problem.sublist("Dirichlet").sublist(side).set(components[c], "0");
  problem.sublist("Traction").sublist(sides[dim - 1][1]).set(dim == 2 ? "traction: y" : "traction: z", "-1");
  problem.sublist("Contact").set("boundary", sides[dim - 1][0]);
  return problem;
}

// Hertz' peak pressure for the computed force, relative error.
double hertzPeakError(const ControlledRun& run, double youngsModulus, double radius) {
  const double eStar = youngsModulus / (1.0 - 0.3 * 0.3), P = run.stats.normalForce;
  if (run.dim == 2) {
    const double a = std::sqrt(4.0 * P * radius / (M_PI * eStar));
    return run.stats.peakPressure / (2.0 * P / (M_PI * a)) - 1.0;
  }
  const double a = std::cbrt(3.0 * P * radius / (4.0 * eStar));
  return run.stats.peakPressure / (3.0 * P / (2.0 * M_PI * a * a)) - 1.0;
}

struct Case {
  const char* name;
  Teuchos::ParameterList problem;
  std::string directory, face, component, approach;
  double youngsModulus, radius, hertzBound;  // radius 0: no Hertz check
};

std::vector<Case> cases() {
  const std::string examples = sourceDir() + "/examples/hertz/";
  Teuchos::ParameterList ball = example("half-ball-pressed-3d");
  ball.set("mesh: size factor", 2.0);
  Teuchos::ParameterList heavyBall = ball;  // the load a weight instead of a pressure
  heavyBall.sublist("Traction").sublist("top").set("traction: z", "0");
  heavyBall.set("body force: z", "-0.0015");
  const std::string y = "displacement: y", z = "displacement: z";
  return {{"steel half-cylinder 2D", example("steel-half-cylinder-2d"), examples, "top", y, "-0.35", 210000, 50, 0.03},
          {"half-ball 3D", ball, examples, "top", z, "-0.015", 1, 1, 0.05},
          {"half-ball 3D under its weight", heavyBall, examples, "top", z, "-0.015", 1, 1, 0.05},
          {"box 2D", pressedBox(2), "", "ymax", y, "-0.75", 1, 0, 0},
          {"box 3D", pressedBox(3), "", "zmax", z, "-0.75", 1, 0, 0}};
}

// Both methods with nodal constraints; the primal-dual one with weighted gaps too (the primal
// method needs rows that do not share unknowns). Hertz' peak is checked on the nodal
// multipliers, whose recovered pressure is the sound one on these P1 meshes.
TEST(ForceControl, ConvergesToTheLoadOnEveryRankCount) {
  const std::pair<const char*, const char*> runs[] = {
      {"primal-dual", "nodal"}, {"primal", "nodal"}, {"primal-dual", "weighted gap"}};
  for (Case c : cases())
    for (const auto& [method, formulation] : runs) {
      const std::string what = std::string(c.name) + ", " + method + ", " + formulation;
      c.problem.sublist("Contact").set("formulation", formulation);
      const ControlledRun force = solve(c.problem, method, c.directory);
      ASSERT_TRUE(force.result.converged()) << what << ": " << force.result.message;
      EXPECT_GT(force.load, 0.0) << what;
      EXPECT_NEAR(force.stats.normalForce, force.load, 1e-6 * force.load) << what;
      if (c.radius > 0 && std::string(formulation) == "nodal") {
        EXPECT_LT(std::abs(hertzPeakError(force, c.youngsModulus, c.radius)), c.hertzBound) << what;
      }
      const ControlledRun displacement =
          solve(underDisplacementControl(c.problem, c.face, c.component, c.approach), method, c.directory);
      ASSERT_TRUE(displacement.result.converged()) << what << " (displacement control)";
      EXPECT_LE(force.result.outerIterations, 1.5 * displacement.result.outerIterations) << what;
    }
}

// The uniform compression: the pressure is the applied one at every contact node.
TEST(ForceControl, PressedBoxCarriesTheUniformPressure) {
  for (int dim : {2, 3}) {
    const ControlledRun run = solve(pressedBox(dim), "primal-dual");
    ASSERT_TRUE(run.result.converged()) << run.result.message;
    EXPECT_NEAR(run.stats.peakPressure, 1.0, 1e-6) << "dim " << dim;
    EXPECT_NEAR(run.stats.area, 1.0, 1e-12) << "dim " << dim;
  }
}

// A square held by contact alone, nothing prescribed: pressed down and to the left by a
// traction on its top, it rests on the floor (pair "floor", ymin) and against a wall (pair
// "wall", xmin, the obstacle direction +x); the corner node is on both. Each pair's contact
// force balances its component of the load, on every rank count, P1 and P2.
TEST(ForceControl, ASquareHeldByTheFloorAndAWallAlone) {
  for (int degree : {1, 2}) {
    Teuchos::ParameterList problem = boxProblem(2, 12, degree);
    Teuchos::ParameterList& top = problem.sublist("Traction").sublist("ymax");
    top.set("traction: x", "-0.5");
    top.set("traction: y", "-1");
    problem.sublist("Contact").sublist("floor").set("boundary", "ymin");
    problem.sublist("Contact").sublist("wall").set("boundary", "xmin");
    problem.sublist("Contact").sublist("wall").set("obstacle: direction", Teuchos::Array<double>(Teuchos::tuple(1.0, 0.0)));
    const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
    const SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
    ASSERT_TRUE(r.converged()) << r.message;
    const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
    const double loads[2] = {1.0, 0.5};  // the floor's and the wall's normal forces
    for (std::size_t pair = 0; pair < 2; ++pair) {
      const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap(), pair);
      const RCP<Vector> pressure = recovery.recover(PressureRecovery::Auto, *r.lambda, *active);
      const ContactStatistics s = contactStatistics(recovery, *pressure, *p.qp.A, *r.lambda, *active,
                                                    p.definition.contacts[pair].obstacleDirection);
      EXPECT_NEAR(s.normalForce, loads[pair], 1e-6 * loads[pair]) << p.definition.contacts[pair].name << " P" << degree;
      EXPECT_GT(s.activeNodes, 0) << p.definition.contacts[pair].name << " P" << degree;
    }
  }
}

}  // namespace
