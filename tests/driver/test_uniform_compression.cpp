// An analytic contact solution: a block between frictionless side walls, pressed by a
// uniform traction p = 1 on its top onto a rigid plane at gap 0. The stress is uniform
// (sigma_dd = -1), the whole bottom is in contact, the contact pressure is 1 everywhere,
// and every element degree reproduces it exactly: so does the consistent pressure recovery
// of nodal constraints, and so do the multipliers of weighted gaps and of the dual mortar
// basis.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

TEST(UniformCompression, ContactPressureIsTheAppliedTraction) {
  const char* axes = "xyz";
  for (const char* formulation : {"nodal", "weighted gap", "dual mortar"})
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      const std::string what = std::string(formulation) + " dim " + std::to_string(dim) + " P" + std::to_string(degree);
      // Only nodal constraints at the vertices of P2 triangles are degenerate (below).
      const bool degenerate = std::string(formulation) == "nodal" && dim == 3 && degree == 2;
      Teuchos::ParameterList problem = signorini::testing::boxProblem(dim, dim == 2 ? 4 : 2, degree);
      const char* sides[2][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}};
      for (int c = 0; c < dim - 1; ++c)
        for (const char* side : sides[c])
          problem.sublist("Dirichlet").sublist(side).set(std::string("displacement: ") + axes[c], "0");
      problem.sublist("Traction").sublist(dim == 2 ? "ymax" : "zmax").set(std::string("traction: ") + axes[dim - 1], "-1");
      problem.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");
      problem.sublist("Contact").set("formulation", formulation);
      AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());

      Teuchos::ParameterList params;
      params.set("kkt: tolerance", 1e-11);
      SolveResult r = InteriorPointSolver(params).solve(p.qp, p.multigrid);
      ASSERT_TRUE(r.converged()) << what << ": " << r.message;
      // The whole bottom touches the plane. P2 vertices of triangles carry no consistent
      // nodal force: their constraints are degenerate (lambda = 0 and gap = 0 at the
      // solution), where an interior point method only drives the gap to ~sqrt(mu), so their
      // gaps are checked to 1e-5, the others to 1e-9.
      Vector gap(p.qp.A->getRangeMap());
      p.qp.A->apply(*r.v, gap);
      gap.update(1.0, *p.qp.d, -1.0);
      const double gapTolerance = degenerate ? 1e-5 : 1e-9;
      EXPECT_LT(gap.normInf(), gapTolerance * r.v->normInf()) << what;

      const RCP<Vector> w = contactNodeWeights(distributedSpace(*p.space), p.definition, p.qp.A->getRangeMap());
      EXPECT_NEAR(w->norm1(), 1.0, 1e-12) << what;  // the bottom face has measure 1
      if (std::string(formulation) == "nodal") {  // total force: the multipliers are nodal forces
        EXPECT_NEAR(-r.lambda->meanValue() * r.lambda->getGlobalLength(), 1.0, 1e-8) << what;
      }
      if (degree == 1 || std::string(formulation) != "nodal") {
        EXPECT_EQ(r.activeConstraints, static_cast<long long>(p.qp.d->getGlobalLength())) << what;
      }

      // M p = -lambda on the whole face (every node loaded) gives p = 1 at every node, for
      // every degree: the nodal forces of a uniform pressure are M 1 (with weighted gaps,
      // p = -sum lambda_j psi_j; with the dual basis, p_j = -lambda_j). The degenerate P2
      // vertex constraints keep multipliers of ~sqrt(mu) where the exact ones are 0, so the
      // recovered pressure is as accurate as those (the recovery itself is exact to round-off:
      // tests/assembly/test_contact_pressure.cpp).
      const double pressureTolerance = degenerate ? 1e-4 : 1e-8;
      const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap());
      Vector everyNode(p.qp.A->getRangeMap());
      everyNode.putScalar(1.0);
      const RCP<Vector> pressure = recovery.pressure(*r.lambda, everyNode);
      Vector one(pressure->getMap());
      one.putScalar(1.0);
      pressure->update(-1.0, one, 1.0);
      EXPECT_LT(pressure->normInf(), pressureTolerance) << what;
      pressure->update(1.0, one, 1.0);
      // Restricted to the loaded facets, as runs do: the same here, as every facet is loaded.
      const RCP<Vector> restricted = recovery.pressure(*r.lambda, *activeIndicator(p.qp, *r.v, *r.lambda));
      restricted->update(-1.0, one, 1.0);
      EXPECT_LT(restricted->normInf(), pressureTolerance) << what;
      const ContactStatistics stats = contactStatistics(recovery, *pressure, *p.qp.A, *r.lambda,
                                                        *activeIndicator(p.qp, *r.v, *r.lambda), p.definition.contacts.front().obstacleDirection);
      EXPECT_NEAR(stats.normalForce, 1.0, 1e-8) << what;
      EXPECT_NEAR(stats.force[0], 0.0, 1e-12) << what;
      // The degenerate P2 vertex constraints are not all counted active (lambda ~ slack ~ sqrt(mu)).
      if (!degenerate) {
        EXPECT_NEAR(stats.area, 1.0, 1e-12) << what;
      }
      EXPECT_NEAR(stats.peakPressure, 1.0, pressureTolerance) << what;
    }
}

}  // namespace
