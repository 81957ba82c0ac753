// An analytic contact solution: a block between frictionless side walls, pressed by a
// uniform traction p = 1 on its top onto a rigid plane at gap 0. The stress is uniform
// (sigma_dd = -1), the whole bottom is in contact, the contact pressure is 1 everywhere,
// and linear elements reproduce it exactly.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/ElasticityAssembler.hpp"
#include "signorini/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

TEST(UniformCompression, ContactPressureIsTheAppliedTraction) {
  const char* axes = "xyz";
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      Teuchos::ParameterList problem = signorini::testing::boxProblem(dim, dim == 2 ? 4 : 2, degree);
      const char* sides[2][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}};
      for (int c = 0; c < dim - 1; ++c)
        for (const char* side : sides[c])
          problem.sublist("Dirichlet").sublist(side).set(std::string("displacement: ") + axes[c], "0");
      problem.sublist("Traction").sublist(dim == 2 ? "ymax" : "zmax").set(std::string("traction: ") + axes[dim - 1], "-1");
      problem.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");
      AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());

      Teuchos::ParameterList params;
      params.set("kkt: tolerance", 1e-11);
      SolveResult r = InteriorPointSolver(params).solve(p.qp);
      ASSERT_TRUE(r.converged()) << "dim " << dim << " P" << degree << ": " << r.message;
      // The whole bottom touches the plane. P2 vertices of triangles carry no consistent
      // nodal force: their constraints are degenerate (lambda = 0 and gap = 0 at the
      // solution), where an interior point method only drives the gap to ~sqrt(mu), so their
      // gaps are checked to 1e-5, the others to 1e-9.
      Vector gap(p.qp.A->getRangeMap());
      p.qp.A->apply(*r.v, gap);
      gap.update(1.0, *p.qp.d, -1.0);
      const double gapTolerance = dim == 3 && degree == 2 ? 1e-5 : 1e-9;
      EXPECT_LT(gap.normInf(), gapTolerance * r.v->normInf()) << "dim " << dim << " P" << degree;

      const RCP<Vector> w = contactNodeWeights(*p.space, p.definition, p.qp.A->getRangeMap());
      EXPECT_NEAR(w->norm1(), 1.0, 1e-12);  // the bottom face has measure 1
      EXPECT_NEAR(-r.lambda->meanValue() * r.lambda->getGlobalLength(), 1.0, 1e-8);  // total force
      if (degree == 1) {
        EXPECT_EQ(r.activeConstraints, static_cast<long long>(p.qp.d->getGlobalLength())) << "dim " << dim;
        // Lumped and consistent weights agree for P1: the pressure is 1 at every node.
        Vector pressure(w->getMap());
        pressure.reciprocal(*w);
        pressure.elementWiseMultiply(-1.0, pressure, *r.lambda, 0.0);
        Vector one(w->getMap());
        one.putScalar(1.0);
        pressure.update(-1.0, one, 1.0);
        EXPECT_LT(pressure.normInf(), 1e-8) << "dim " << dim;
      }
    }
}

}  // namespace
