// The start's multipliers balance the load along the rigid body motions only the contact
// holds, stay positive, and are left alone where no positive multipliers can balance it.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/RigidBodySupport.hpp"
#include "solver/ipm/FreeMotionBalance.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// A box on the obstacle, its sides on rollers (the normal displacement of each side held), its
// top pressed by the vertical `traction`: only the translation towards the obstacle is free.
AssembledProblem pressedBox(int dim, const char* traction) {
  Teuchos::ParameterList problem = boxProblem(dim, 4, 1);
  const char* sides[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  const char* components[3] = {"displacement: x", "displacement: y", "displacement: z"};
  for (int c = 0; c + 1 < dim; ++c)
    for (const char* side : sides[c]) problem.sublist("Dirichlet").sublist(side).set(components[c], "0");
  problem.sublist("Traction").sublist(sides[dim - 1][1]).set(dim == 2 ? "traction: y" : "traction: z", traction);
  problem.sublist("Contact").set("boundary", sides[dim - 1][0]);
  return buildProblem(problem, Tpetra::getDefaultComm());
}

// F^T (A^T y - b), the load along the free motions that y leaves unbalanced.
std::vector<double> imbalance(const ContactQP& qp, const MultiVector& F, const Vector& y) {
  Vector force(qp.Q->getDomainMap());
  qp.A->apply(y, force, Teuchos::TRANS);
  force.update(-1.0, *qp.b, 1.0);
  std::vector<double> result;
  for (std::size_t j = 0; j < F.getNumVectors(); ++j) result.push_back(F.getVector(j)->dot(force));
  return result;
}

TEST(FreeMotionBalance, MultipliersBalanceThePressingLoad) {
  for (int dim : {2, 3}) {
    const AssembledProblem p = pressedBox(dim, "-3");
    const RCP<const MultiVector> F = checkRigidBodyMotionsHeld(p.qp, p.multigrid);
    ASSERT_FALSE(F.is_null()) << "dim " << dim;
    Vector y(p.qp.A->getRangeMap());
    y.randomize(0.1, 10.0);  // unrelated to the load
    Vector y0(y, Teuchos::Copy);
    ASSERT_TRUE(detail::balanceLoadAlongFreeMotions(*p.qp.A, *p.qp.b, *F, y)) << "dim " << dim;
    double load = 0;
    for (std::size_t j = 0; j < F->getNumVectors(); ++j) load += std::abs(F->getVector(j)->dot(*p.qp.b));
    for (double value : imbalance(p.qp, *F, y)) EXPECT_LT(std::abs(value), 1e-10 * load) << "dim " << dim;
    EXPECT_GT(y.getVector(0)->normInf(), 0.0);
    // Positive, and a rescaling of the given y: y_i / y0_i = exp((G z)_i) is one factor here,
    // where every constraint moves alike under the free translation.
    auto yd = y.getData();
    auto y0d = y0.getData();
    double lowest = 1e300, lowestRatio = 1e300, highestRatio = 0;
    for (std::size_t i = 0; i < y.getLocalLength(); ++i) {
      lowest = std::min(lowest, yd[i]);
      lowestRatio = std::min(lowestRatio, yd[i] / y0d[i]);
      highestRatio = std::max(highestRatio, yd[i] / y0d[i]);
    }
    EXPECT_GT(lowest, 0.0);
    if (y.getLocalLength() > 0) {
      EXPECT_NEAR(lowestRatio, highestRatio, 1e-10 * highestRatio);
    }
  }
}

TEST(FreeMotionBalance, WithoutLoadAlongTheFreeMotionsNothingChanges) {
  const AssembledProblem p = pressedBox(2, "0");
  const RCP<const MultiVector> F = checkRigidBodyMotionsHeld(p.qp, p.multigrid);
  ASSERT_FALSE(F.is_null());
  Vector y(p.qp.A->getRangeMap());
  y.putScalar(2.0);
  EXPECT_FALSE(detail::balanceLoadAlongFreeMotions(*p.qp.A, *p.qp.b, *F, y));
  EXPECT_EQ(y.normInf(), 2.0);
}

}  // namespace
