// Hertz contact on meshes small enough for every run: the rigid cylinder (plane strain) and
// sphere of examples/hertz, compared with Hertz' solution for the computed force. The full
// refinement study is scripts/hertz.py.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/ContactPressure.hpp"
#include "signorini/InteriorPointSolver.hpp"
#include "signorini/KKTMeasures.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

struct HertzErrors {
  double radius, peak, l2;  // relative to Hertz for the computed force
};

// Box cells per direction.
Teuchos::Array<int> cells(int x, int y, int z = 0) {
  Teuchos::Array<int> c;
  for (int n : {x, y, z})
    if (n > 0) c.push_back(n);
  return c;
}

// The example's problem with `degree`, `formulation` and the mesh parameter `meshSetting`
// ("mesh: cells" of a box, "mesh: size factor" of a Gmsh geometry) set to `mesh`.
template <class Mesh>
HertzErrors solveHertz(const std::string& example, int degree, const std::string& meshSetting, const Mesh& mesh,
                       const std::string& formulation = "nodal") {
  const std::string directory = signorini::testing::sourceDir() + "/examples/hertz/";
  auto file = Teuchos::getParametersFromXmlFile(directory + example + ".xml");
  Teuchos::ParameterList problem = file->sublist("Problem");
  problem.set(meshSetting, mesh);
  problem.set("element: degree", degree);
  problem.sublist("Contact").set("formulation", formulation);
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm(), directory);
  const SolveResult r = InteriorPointSolver(Teuchos::ParameterList()).solve(p.qp);
  EXPECT_TRUE(r.converged()) << r.message;

  const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap());
  const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
  const RCP<Vector> pressure = recovery.pressure(*r.lambda, *active);
  const ContactStatistics s = contactStatistics(recovery, *pressure, *p.qp.A, *r.lambda, *active,
                                                p.definition.obstacleDirection);
  const int dim = p.definition.dim;
  const double eStar = 1.0 / (1.0 - 0.3 * 0.3), R = 1.0, P = s.normalForce;
  double a, p0, measured;
  if (dim == 2) {
    a = std::sqrt(4.0 * P * R / (M_PI * eStar));
    p0 = 2.0 * P / (M_PI * a);
    measured = s.area / 2.0;
  } else {
    a = std::cbrt(3.0 * P * R / (4.0 * eStar));
    p0 = 3.0 * P / (2.0 * M_PI * a * a);
    measured = std::sqrt(s.area / M_PI);
  }
  // Centre of the contact: x = 1 under the cylinder, x = 0 under the half-disk, (0.5, 0.5) in 3D.
  const double cx = dim == 3 ? 0.5 : (example == "half-disk-2d" ? 0.0 : 1.0);
  const ContactPressureSamples samples = recovery.samples(*pressure);
  double local[2] = {0, 0}, global[2];
  for (std::size_t q = 0; q < samples.weights.size(); ++q) {
    const double* x = &samples.points[q * dim];
    const double r2 = dim == 2 ? (x[0] - cx) * (x[0] - cx) : (x[0] - cx) * (x[0] - cx) + (x[1] - 0.5) * (x[1] - 0.5);
    const double exact = p0 * std::sqrt(std::max(0.0, 1.0 - r2 / (a * a)));
    local[0] += samples.weights[q] * (samples.pressures[q] - exact) * (samples.pressures[q] - exact);
    local[1] += samples.weights[q] * exact * exact;
  }
  Teuchos::reduceAll(*p.space->comm(), Teuchos::REDUCE_SUM, 2, local, global);
  return {measured / a - 1.0, s.peakPressure / p0 - 1.0, std::sqrt(global[0] / global[1])};
}

TEST(Hertz, CylinderInPlaneStrainConvergesToHertz) {
  for (const auto& [degree, formulation] : {std::pair<int, std::string>{1, "nodal"}, {2, "nodal"}, {2, "weighted gap"}}) {
    const std::string what = "P" + std::to_string(degree) + " " + formulation;
    const int n = degree == 1 ? 80 : 40;
    const HertzErrors coarse = solveHertz("cylinder-2d", degree, "mesh: cells", cells(n, n / 2), formulation);
    const HertzErrors fine = solveHertz("cylinder-2d", degree, "mesh: cells", cells(2 * n, n), formulation);
    EXPECT_LT(std::abs(fine.radius), 0.04) << what;
    EXPECT_LT(std::abs(fine.peak), 0.02) << what;
    EXPECT_LT(fine.l2, 0.05) << what;
    EXPECT_LT(std::abs(fine.radius), std::abs(coarse.radius)) << what;
    EXPECT_LT(std::abs(fine.peak), std::abs(coarse.peak)) << what;
    EXPECT_LT(fine.l2, coarse.l2) << what;
  }
}

// A curved body meshed by Gmsh from examples/hertz/half-disk-2d.geo, P2: the half-width
// within 3% and the peak pressure within 8% of Hertz at the finer mesh, both decreasing.
TEST(Hertz, HalfDiskFromGmshConvergesToHertz) {
  const HertzErrors coarse = solveHertz("half-disk-2d", 2, "mesh: size factor", 2.0);
  const HertzErrors fine = solveHertz("half-disk-2d", 2, "mesh: size factor", 1.0);
  EXPECT_LT(std::abs(fine.radius), 0.03);
  EXPECT_LT(std::abs(fine.peak), 0.08);
  EXPECT_LT(std::abs(fine.radius), std::abs(coarse.radius));
  EXPECT_LT(std::abs(fine.peak), std::abs(coarse.peak));
  EXPECT_LT(fine.l2, coarse.l2);
}

// P2 with weighted gaps, where every constraint carries force: radius, peak pressure and L2
// error of the pressure all decrease, to within 5% of Hertz at the finer mesh.
TEST(Hertz, SphereWithWeightedGapsConvergesToHertz) {
  const HertzErrors coarse = solveHertz("sphere-3d", 2, "mesh: cells", cells(16, 16, 8), "weighted gap");
  const HertzErrors fine = solveHertz("sphere-3d", 2, "mesh: cells", cells(24, 24, 12), "weighted gap");
  EXPECT_LT(std::abs(fine.radius), 0.05);
  EXPECT_LT(std::abs(fine.peak), 0.05);
  EXPECT_LT(std::abs(fine.radius), std::abs(coarse.radius));
  EXPECT_LT(std::abs(fine.peak), std::abs(coarse.peak));
  EXPECT_LT(fine.l2, coarse.l2);
}

TEST(Hertz, SphereContactRadiusConvergesToHertz) {
  // P1: only the radius; its peak pressure converges slowly (scripts/hertz.py measures it).
  const HertzErrors coarse = solveHertz("sphere-3d", 1, "mesh: cells", cells(16, 16, 8));
  const HertzErrors fine = solveHertz("sphere-3d", 1, "mesh: cells", cells(32, 32, 16));
  EXPECT_LT(std::abs(fine.radius), 0.05);
  EXPECT_LT(std::abs(fine.radius), std::abs(coarse.radius));
}

}  // namespace
