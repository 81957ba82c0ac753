// Two elastic bodies in contact, posed in code: a half-disk pressed onto a block.
//
// The half-disk (radius R = 1) and the block come from one Gmsh geometry,
// examples/bodies/disk-on-block-2d.geo, meshed apart: their nodes on the interface do not
// coincide. Each body is a physical surface with its own material (Problem/Bodies/<name>);
// the disk's lower arc is the slave side of a mortar contact pair whose master boundary is the
// block's top. The block's bottom is clamped and the disk's flat top is lowered by 0.01
// (plane strain, nu = 0.3, the block's E = 1, the disk's given on the command line).
//
// After the solve the example prints what a user checks first: the force of the master body
// on the slave side and of the slave side on the master body (action and reaction: they
// balance), and the contact half-width and peak pressure against Hertz for the computed force
// P per unit thickness, with 1/E* = (1 - nu^2)/E_disk + (1 - nu^2)/E_block:
//
//     a = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi a).
//
// Build against an installed Signorini and run on 2 ranks:
//   cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix> && cmake --build build
//   mpirun -np 2 build/two_bodies <signorini source>/examples/bodies/disk-on-block-2d.geo [disk modulus]
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "signorini/signorini.hpp"

using namespace signorini;

namespace {

constexpr double kRadius = 1.0, kBlockYoung = 1.0, kPoisson = 0.3, kPush = 0.01;

void clamp(Teuchos::ParameterList& problem, const std::string& boundary, double y) {
  Teuchos::ParameterList& list = problem.sublist("Dirichlet").sublist(boundary);
  list.set("displacement: x", "0");
  list.set("displacement: y", std::to_string(y));
}

Teuchos::ParameterList diskOnBlock(const std::string& geoFile, double diskYoung) {
  Teuchos::ParameterList problem("Problem");
  problem.set("name", "two-bodies");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", geoFile);
  problem.set("material: young's modulus", kBlockYoung);  // every body's unless it says otherwise
  problem.set("material: poisson ratio", kPoisson);
  problem.sublist("Bodies").sublist("disk").set("material: young's modulus", diskYoung);
  clamp(problem, "top", -kPush);
  clamp(problem, "block bottom", 0.0);
  Teuchos::ParameterList& contact = problem.sublist("Contact");
  contact.set("boundary", "arc");                // slave: the finer, curved side
  contact.set("master boundary", "block top");  // another body's surface: mortar constraints
  return problem;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const RCP<const Comm> comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 2) {
    if (root) std::fprintf(stderr, "usage: two_bodies <disk-on-block-2d.geo> [disk modulus]\n");
    return 2;
  }
  const double diskYoung = argc > 2 ? std::atof(argv[2]) : 1.0;

  try {
    AssembledProblem assembled = buildProblem(diskOnBlock(argv[1], diskYoung), comm);
    const SolveResult result = InteriorPointSolver().solve(assembled.qp, assembled.multigrid);
    if (!result.converged()) {
      if (root) std::fprintf(stderr, "two_bodies: %s\n", result.message.c_str());
      return 1;
    }

    // The pair's pressure field and totals; `masterForce` is the slave side's force on the block.
    const ContactPair& pair = assembled.definition.contacts.front();
    const RCP<Vector> active = activeIndicator(assembled.qp, *result.v, *result.lambda);
    const ContactPressure recovery(*assembled.space, assembled.definition, assembled.qp.A->getRangeMap());
    const RCP<Vector> pressure = recovery.recover(PressureRecovery::Auto, *result.lambda, *active);
    const ContactStatistics contact =
        contactStatistics(recovery, *pressure, *assembled.qp.A, *result.lambda, *active, pair.obstacleDirection);

    const double P = contact.normalForce;
    const double Estar = 1 / ((1 - kPoisson * kPoisson) * (1 / diskYoung + 1 / kBlockYoung));
    const double a = std::sqrt(4 * P * kRadius / (M_PI * Estar)), p0 = 2 * P / (M_PI * a);
    const std::array<double, 3>& onSlave = contact.force;
    const std::array<double, 3>& onMaster = *contact.masterForce;
    const double imbalance = std::hypot(onSlave[0] + onMaster[0], onSlave[1] + onMaster[1]);

    if (root) {
      std::printf("n = %lld unknowns, %lld contact nodes active, %d main iterations, %lld CG iterations\n",
                  static_cast<long long>(assembled.qp.Q->getDomainMap()->getGlobalNumElements()),
                  contact.activeNodes, result.outerIterations, result.krylovIterations);
      std::printf("force on the disk  (%+.6e, %+.6e)\n", onSlave[0], onSlave[1]);
      std::printf("force on the block (%+.6e, %+.6e), imbalance %.1e of the force\n", onMaster[0], onMaster[1],
                  imbalance / std::hypot(onSlave[0], onSlave[1]));
      std::printf("half-width    %.6f, Hertz %.6f (%+.2f%%)\n", contact.area / 2, a, 100 * (contact.area / 2 / a - 1));
      std::printf("peak pressure %.6f, Hertz %.6f (%+.2f%%)\n", contact.peakPressure, p0,
                  100 * (contact.peakPressure / p0 - 1));
    }
    return 0;
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "two_bodies: %s\n", e.what());
    return 1;
  }
}
