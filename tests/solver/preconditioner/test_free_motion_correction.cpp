// The exact solve on the rigid body motions only the contact holds and their preconditioned
// Krylov vectors, combined with another preconditioner: its result leaves a residual without
// component along that coarse space, it is symmetric, exact on the coarse space, and without
// weights the inner preconditioner alone.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/RigidBodySupport.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/preconditioner/FreeMotionCorrection.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// A 3D box on the obstacle, its sides on rollers, pressed on its top: the vertical
// translation is left to the contact.
AssembledProblem rollerBox() {
  Teuchos::ParameterList problem = boxProblem(3, 4, 1);
  for (const char* side : {"xmin", "xmax"}) problem.sublist("Dirichlet").sublist(side).set("displacement: x", "0");
  for (const char* side : {"ymin", "ymax"}) problem.sublist("Dirichlet").sublist(side).set("displacement: y", "0");
  problem.sublist("Traction").sublist("zmax").set("traction: z", "-1");
  problem.sublist("Contact").set("boundary", "zmin");
  return buildProblem(problem, Tpetra::getDefaultComm());
}

struct Corrected {
  AssembledProblem problem;
  RCP<const MultiVector> F;
  RCP<BarrierHessianOperator> H;
  std::shared_ptr<MueLuPreconditioner> amg;
  RCP<FreeMotionCorrection> M;
};

// H with weights from free (1e-8) to held (1e4) constraints, corrected around MueLu.
Corrected corrected() {
  Corrected c{rollerBox(), {}, {}, {}, {}};
  const ContactQP& qp = c.problem.qp;
  const MultigridInput& mg = c.problem.multigrid;
  c.F = checkRigidBodyMotionsHeld(qp, mg);
  c.H = rcp(new BarrierHessianOperator(qp.Q, qp.A));
  Vector D(qp.A->getRangeMap());
  D.randomize(1e-8, 1e4);
  c.H->setWeights(D);
  c.M = rcp(new FreeMotionCorrection(c.H, c.F, 2));
  c.amg = std::make_shared<MueLuPreconditioner>(Teuchos::ParameterList(), mg.blockSize, mg.nearNullspace(qp),
                                                  mg.coordinates);
  c.amg->compute(c.H->assemble());
  c.M->setInner(c.amg->getOperator());
  return c;
}

TEST(FreeMotionCorrection, TheProblemHasOneFreeMotion) {
  const AssembledProblem p = rollerBox();
  const RCP<const MultiVector> F = checkRigidBodyMotionsHeld(p.qp, p.multigrid);
  ASSERT_FALSE(F.is_null());
  EXPECT_EQ(F->getNumVectors(), 1u);
}

TEST(FreeMotionCorrection, LeavesNoResidualAlongItsCoarseSpace) {
  const Corrected c = corrected();
  Vector r(c.H->getRangeMap()), x(c.H->getDomainMap()), residual(c.H->getRangeMap());
  r.randomize();
  c.M->apply(r, x);
  residual.assign(r);
  c.H->apply(x, residual, Teuchos::NO_TRANS, -1.0, 1.0);
  const RCP<const MultiVector> U = c.M->coarseSpace();
  for (std::size_t j = 0; j < U->getNumVectors(); ++j)
    EXPECT_LT(std::abs(U->getVector(j)->dot(residual)), 1e-10 * r.norm2()) << "column " << j;
}

// The free motion and the two products B H f, independent of it and of each other: each is
// H's inverse applied to H u (the coarse solve is exact on its space, the inner
// preconditioner then sees no residual).
TEST(FreeMotionCorrection, IsExactOnTheFreeMotionsAndTheirProducts) {
  const Corrected c = corrected();
  Vector r(c.H->getRangeMap()), x(c.H->getDomainMap());
  r.randomize();
  c.M->apply(r, x);
  const RCP<const MultiVector> U = c.M->coarseSpace();
  ASSERT_EQ(U->getNumVectors(), 3u);
  EXPECT_NEAR(std::abs(U->getVector(0)->dot(*c.F->getVector(0))), 1.0, 1e-12);
  for (std::size_t j = 0; j < U->getNumVectors(); ++j) {
    Vector Hu(c.H->getRangeMap()), MHu(c.H->getDomainMap());
    c.H->apply(*U->getVector(j), Hu);
    c.M->apply(Hu, MHu);
    MHu.update(-1.0, *U->getVector(j), 1.0);
    EXPECT_LT(MHu.norm2(), 1e-8) << "column " << j;
  }
}

TEST(FreeMotionCorrection, IsSymmetric) {
  const Corrected c = corrected();
  Vector u(c.H->getRangeMap()), w(c.H->getRangeMap()), Mu(c.H->getDomainMap()), Mw(c.H->getDomainMap());
  u.randomize();
  w.randomize();
  c.M->apply(u, Mu);
  c.M->apply(w, Mw);
  EXPECT_NEAR(w.dot(Mu), u.dot(Mw), 1e-10 * std::abs(w.dot(Mu)));
}

// Without weights H = Q is singular along F: the inner preconditioner alone, unchanged.
TEST(FreeMotionCorrection, WithoutWeightsIsTheInnerPreconditioner) {
  Corrected c = corrected();
  c.H->setWeights(Vector(c.problem.qp.A->getRangeMap()));
  c.M->refresh();
  Vector r(c.H->getRangeMap()), x(c.H->getDomainMap()), inner(c.H->getDomainMap());
  r.randomize();
  c.M->apply(r, x);
  c.amg->getOperator()->apply(r, inner);
  x.update(-1.0, inner, 1.0);
  EXPECT_EQ(x.normInf(), 0.0);
}

}  // namespace
