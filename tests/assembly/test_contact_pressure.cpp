// The contact pressure recovery against nodal forces computed independently: the
// assembler's traction load of a known pressure on the contact face.
#include <gtest/gtest.h>

#include <memory>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/assembly/ContactPressure.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// A box with contact on its bottom face, nodal constraints, and the traction `pressure`
// pushing that face inwards, so that A b = -f: exactly the multipliers (paper's sign) of that
// pressure.
struct LoadedFace {
  AssembledProblem problem;
  RCP<Vector> lambda;
  std::unique_ptr<ContactPressure> recovery;
  RCP<Vector> everyNode;  // every constraint active
};

LoadedFace loadedBottomFace(int dim, int degree, const std::string& pressure) {
  Teuchos::ParameterList list = signorini::testing::boxProblem(dim, dim == 2 ? 6 : 3, degree);
  const std::string bottom = dim == 2 ? "ymin" : "zmin";
  list.sublist("Traction").sublist(bottom).set(dim == 2 ? "traction: y" : "traction: z", pressure);
  list.sublist("Contact").set("boundary", bottom);
  list.sublist("Contact").set("formulation", "nodal");
  LoadedFace face{buildProblem(list, Tpetra::getDefaultComm()), Teuchos::null, nullptr, Teuchos::null};
  face.lambda = rcp(new Vector(face.problem.qp.A->getRangeMap()));
  face.problem.qp.A->apply(*face.problem.qp.b, *face.lambda);
  const AssembledProblem& p = face.problem;
  face.recovery = std::make_unique<ContactPressure>(*p.space, p.definition, p.qp.A->getRangeMap());
  face.everyNode = rcp(new Vector(p.qp.A->getRangeMap()));
  face.everyNode->putScalar(1.0);
  return face;
}

TEST(ContactPressure, RecoversAUniformPressureToRoundOff) {
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      LoadedFace face = loadedBottomFace(dim, degree, "2.5");
      const AssembledProblem& p = face.problem;
      const ContactPressure& recovery = *face.recovery;
      const RCP<Vector> pressure = recovery.pressure(*face.lambda, *face.everyNode);
      Vector expected(pressure->getMap());
      expected.putScalar(2.5);
      expected.update(-1.0, *pressure, 1.0);
      EXPECT_LT(expected.normInf(), 1e-12) << "dim " << dim << " P" << degree;

      const ContactStatistics stats = contactStatistics(recovery, *pressure, *p.qp.A, *face.lambda, *face.everyNode,
                                                        p.definition.contacts.front().obstacleDirection);
      EXPECT_NEAR(stats.normalForce, 2.5, 1e-12) << "dim " << dim << " P" << degree;  // face of measure 1
      EXPECT_NEAR(stats.area, 1.0, 1e-12) << "dim " << dim << " P" << degree;
      EXPECT_NEAR(stats.peakPressure, 2.5, 1e-12) << "dim " << dim << " P" << degree;

      // The samples integrate the pressure over the face.
      const ContactPressureSamples samples = recovery.samples(*pressure);
      double local = 0, total = 0;
      for (std::size_t q = 0; q < samples.weights.size(); ++q) local += samples.weights[q] * samples.pressures[q];
      Teuchos::reduceAll(*p.space->comm(), Teuchos::REDUCE_SUM, 1, &local, &total);
      EXPECT_NEAR(total, 2.5, 1e-12) << "dim " << dim << " P" << degree;
    }
}

TEST(ContactPressure, RecoversALinearPressureExactly) {
  // p = 1 + x lies in every P_k space: the L2 representative of its nodal forces is itself.
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      LoadedFace face = loadedBottomFace(dim, degree, "1 + x");
      const RCP<Vector> pressure = face.recovery->pressure(*face.lambda, *face.everyNode);
      const ContactPressureSamples samples = face.recovery->samples(*pressure);
      double worst = 0;
      for (std::size_t q = 0; q < samples.weights.size(); ++q)
        worst = std::max(worst, std::abs(samples.pressures[q] - (1.0 + samples.points[q * dim])));
      EXPECT_LT(worst, 1e-12) << "dim " << dim << " P" << degree;
    }
}

TEST(ContactPressure, VanishesOffTheLoadedFacets) {
  // Only the nodes with x < 0.5 are active: p is 0 on every node outside their facets, and
  // M p = f on the nodes of those facets.
  LoadedFace face = loadedBottomFace(2, 2, "1");
  const AssembledProblem& p = face.problem;
  const ContactPressure& recovery = *face.recovery;
  Vector active(p.qp.A->getRangeMap());
  Vector x(p.qp.A->getRangeMap());  // node x coordinate per constraint: -A applied to (x, 0) displacements
  {
    Vector displacement(p.qp.A->getDomainMap());
    auto coords = p.multigrid.coordinates->getData(0);
    auto u = displacement.getDataNonConst();
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(coords.size()); ++i) u[2 * i + 1] = -coords[i];
    p.qp.A->apply(displacement, x);
  }
  auto xs = x.getData();
  auto a = active.getDataNonConst();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(xs.size()); ++i) a[i] = xs[i] < 0.5 ? 1.0 : 0.0;
  a = Teuchos::null;
  const RCP<Vector> pressure = recovery.pressure(*face.lambda, active);
  Vector Mp(p.qp.A->getRangeMap());
  recovery.massMatrix().apply(*pressure, Mp);
  auto pd = pressure->getData();
  auto mp = Mp.getData();
  auto f = face.lambda->getData();
  const double h = 1.0 / 6;  // loaded facets reach one cell past x = 0.5 - h
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(xs.size()); ++i) {
    if (xs[i] > 0.5 + 1e-12) {
      EXPECT_EQ(pd[i], 0.0) << "x = " << xs[i];
    } else if (xs[i] < 0.5 - h) {
      EXPECT_NEAR(mp[i], -f[i], 1e-13) << "x = " << xs[i];
      EXPECT_GT(pd[i], 0.5) << "x = " << xs[i];
    }
  }
}

// The patch average of P1 nodal forces: exact for a uniform pressure, 0 where a node is not
// active, and a node's value is the ratio of the forces to the weights of its active facet
// neighbours, which a force that alternates from node to node does not shift.
TEST(ContactPressure, PatchAverageIsExactForAUniformPressureAndVanishesOffTheActiveNodes) {
  for (int dim : {2, 3}) {
    LoadedFace face = loadedBottomFace(dim, 1, "2.5");
    const ContactPressure& recovery = *face.recovery;
    const RCP<Vector> pressure = recovery.recover(PressureRecovery::Patch, *face.lambda, *face.everyNode);
    Vector expected(pressure->getMap());
    expected.putScalar(2.5);
    expected.update(-1.0, *pressure, 1.0);
    EXPECT_LT(expected.normInf(), 1e-12) << "dim " << dim;

    // Every other constraint inactive: those get 0; the others keep 2.5, the average over
    // their active neighbours.
    Vector active(pressure->getMap());
    auto a = active.getDataNonConst();
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(a.size()); ++i) a[i] = (active.getMap()->getGlobalElement(i) % 2 == 0) ? 1.0 : 0.0;
    a = Teuchos::null;
    const RCP<Vector> partial = recovery.recover(PressureRecovery::Patch, *face.lambda, active);
    auto p = partial->getData();
    auto on = active.getData();
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(p.size()); ++i) {
      if (on[i] == 0) {
        EXPECT_EQ(p[i], 0.0) << "dim " << dim;
      } else {
        EXPECT_NEAR(p[i], 2.5, 1e-12) << "dim " << dim;
      }
    }
  }
}

}  // namespace
