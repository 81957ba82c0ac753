// Hertz contact on a Gmsh mesh, compared with the analytic solution.
//
// An elastic half-disk of radius R = 1 (plane strain, E = 1, nu = 0.3), meshed by Gmsh from
// half-disk-2d.geo with its mesh graded towards the first contact point, is pressed onto the
// rigid plane y = 0 by lowering its clamped flat top by 0.01. For the computed total force P
// per unit thickness, Hertz gives the contact half-width and the pressure
//
//     a = sqrt(4 P R / (pi E*)),   p(x) = p0 sqrt(1 - x^2 / a^2),   p0 = 2 P / (pi a),
//
// with E* = E / (1 - nu^2). The example solves with P2 elements, recovers the contact
// pressure as a field (signorini::ContactPressure) and prints the computed half-width and
// peak pressure against Hertz and the largest deviation of the pressure profile from Hertz,
// relative to p0, at the quadrature points of the contact boundary.
//
// Build against an installed Signorini and run on 2 ranks:
//   cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix> && cmake --build build
//   mpirun -np 2 build/hertz_gmsh <signorini source>/examples/hertz/half-disk-2d.geo [size factor] [refinements]
// A size factor above 1 coarsens the mesh, below 1 refines it. With refinements r > 0 Gmsh's
// mesh is the coarsest of r + 1 levels: every rank refines its part r times, the new vertices
// on the circle placed on it, and each level is a level of the geometric multigrid.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "signorini/signorini.hpp"

using namespace signorini;

namespace {

constexpr double kRadius = 1.0, kYoung = 1.0, kPoisson = 0.3, kPush = 0.01;

Teuchos::ParameterList halfDiskProblem(const std::string& geoFile, double sizeFactor, int refinements) {
  Teuchos::ParameterList problem("Problem");
  problem.set("name", "hertz-gmsh");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", geoFile);
  problem.set("mesh: size factor", sizeFactor);
  problem.set("mesh: refinements", refinements);
  problem.set("element: degree", 2);
  problem.set("material: young's modulus", kYoung);
  problem.set("material: poisson ratio", kPoisson);
  Teuchos::ParameterList& top = problem.sublist("Dirichlet").sublist("top");
  top.set("displacement: x", "0");
  top.set("displacement: y", std::to_string(-kPush));
  Teuchos::ParameterList& contact = problem.sublist("Contact");
  contact.set("boundary", "contact");
  contact.set("gap: type", "expression");
  contact.set("gap: expression", "y");  // the height of the curved side above the plane
  return problem;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const RCP<const Comm> comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 2) {
    if (root) std::fprintf(stderr, "usage: hertz_gmsh <half-disk-2d.geo> [size factor] [refinements]\n");
    return 2;
  }
  const double sizeFactor = argc > 2 ? std::atof(argv[2]) : 1.0;
  const int refinements = argc > 3 ? std::atoi(argv[3]) : 0;

  try {
    AssembledProblem assembled = buildProblem(halfDiskProblem(argv[1], sizeFactor, refinements), comm);
    const SolveResult result = InteriorPointSolver().solve(assembled.qp, assembled.multigrid);
    if (!result.converged()) {
      if (root) std::fprintf(stderr, "hertz_gmsh: %s\n", result.message.c_str());
      return 1;
    }

    // The pressure field and its totals: force, contact length, peak.
    const RCP<Vector> active = activeIndicator(assembled.qp, *result.v, *result.lambda);
    const ContactPressure recovery(*assembled.space, assembled.definition, assembled.qp.A->getRangeMap());
    const RCP<Vector> pressure = recovery.pressure(*result.lambda, *active);
    const ContactStatistics contact = contactStatistics(recovery, *pressure, *assembled.qp.A, *result.lambda,
                                                        *active, assembled.definition.contacts.front().obstacleDirection);

    // Hertz for the computed force.
    const double P = contact.normalForce, Estar = kYoung / (1 - kPoisson * kPoisson);
    const double a = std::sqrt(4 * P * kRadius / (M_PI * Estar)), p0 = 2 * P / (M_PI * a);

    // The largest deviation from the Hertz profile at this rank's quadrature points, then
    // over all ranks.
    const ContactPressureSamples samples = recovery.samples(*pressure);
    double deviation = 0;
    for (std::size_t q = 0; q < samples.pressures.size(); ++q) {
      const double x = samples.points[q * samples.dim];
      const double hertz = std::abs(x) < a ? p0 * std::sqrt(1 - x * x / (a * a)) : 0.0;
      deviation = std::max(deviation, std::abs(samples.pressures[q] - hertz));
    }
    double maxDeviation = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, deviation, Teuchos::outArg(maxDeviation));

    if (root) {
      std::printf("n = %lld unknowns, %lld contact nodes active, %d main iterations\n",
                  static_cast<long long>(assembled.qp.Q->getDomainMap()->getGlobalNumElements()),
                  contact.activeNodes, result.outerIterations);
      std::printf("force per unit thickness P = %.6e\n", P);
      std::printf("half-width    %.6f, Hertz %.6f (%+.2f%%)\n", contact.area / 2, a, 100 * (contact.area / 2 / a - 1));
      std::printf("peak pressure %.6f, Hertz %.6f (%+.2f%%)\n", contact.peakPressure, p0,
                  100 * (contact.peakPressure / p0 - 1));
      std::printf("largest deviation of the pressure from Hertz: %.2f%% of p0\n", 100 * maxDeviation / p0);
    }
    return 0;
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "hertz_gmsh: %s\n", e.what());
    return 1;
  }
}
