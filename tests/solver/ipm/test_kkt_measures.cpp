// The active set criterion judges each constraint row normalised by its norm: scaling a row
// of A and d by any factor (and its multiplier by the inverse, the same QP) leaves the active
// set unchanged, so rows in other units than a displacement, like weighted gaps, are judged
// as node-wise rows are.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

double sum(const Vector& x) {
  auto d = x.getData();
  double local = 0, global = 0;
  for (double v : d) local += v;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, 1, &local, &global);
  return global;
}

TEST(ActiveSetCriterion, DoesNotDependOnTheScaleOfAConstraintRow) {
  const AssembledProblem p = buildProblem(signorini::testing::shippedProblem("paper/K"), Tpetra::getDefaultComm());
  const SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
  ASSERT_TRUE(r.converged()) << r.message;
  const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
  const double activeCount = sum(*active);
  ASSERT_GT(activeCount, 0);
  ASSERT_LT(activeCount, p.qp.d->getGlobalLength());

  // Row i scaled by s_i in [1e-6, 1e2] (a weighted gap's row is as small as a facet's area).
  ContactQP scaled = p.qp;
  Vector s(p.qp.A->getRangeMap()), lambda(*r.lambda, Teuchos::Copy), d(*p.qp.d, Teuchos::Copy);
  {
    auto sd = s.getDataNonConst();
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(sd.size()); ++i)
      sd[i] = (p.qp.A->getRangeMap()->getGlobalElement(i) % 3 == 0) ? 1e-6 : 1e2;
  }
  auto A = rcp(new CrsMatrix(*p.qp.A, Teuchos::Copy));
  A->leftScale(s);
  d.elementWiseMultiply(1.0, s, *p.qp.d, 0.0);
  Vector inverse(s.getMap());
  inverse.reciprocal(s);
  lambda.elementWiseMultiply(1.0, inverse, *r.lambda, 0.0);
  scaled.A = A;
  scaled.d = rcp(new Vector(d, Teuchos::Copy));

  const RCP<Vector> scaledActive = activeIndicator(scaled, *r.v, lambda);
  Vector difference(active->getMap());
  difference.update(1.0, *active, -1.0, *scaledActive, 0.0);
  EXPECT_EQ(difference.normInf(), 0.0);
}

// Nearly degenerate: the multiplier and the slack both within a fraction of their scales (the
// force scale is at least every |lambda_i r_i|, so a multiplier of the solution is within 1 of
// it); one large value of either is enough to be clear.
TEST(ActiveSetCriterion, NearlyDegenerateNeedsBothMultiplierAndSlackSmall) {
  const AssembledProblem p = buildProblem(signorini::testing::shippedProblem("paper/K"), Tpetra::getDefaultComm());
  const SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
  ASSERT_TRUE(r.converged()) << r.message;
  const ActiveSetCriterion criterion(p.qp, *r.v, *r.lambda);
  auto lambda = r.lambda->getData();
  int pressed = 0;
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(lambda.size()); ++i) {
    EXPECT_TRUE(criterion.isNearlyDegenerate(i, 0.0, 0.0, 0.0)) << i;
    EXPECT_FALSE(criterion.isNearlyDegenerate(i, 1e30, 0.0, 1.0)) << i;
    EXPECT_FALSE(criterion.isNearlyDegenerate(i, 0.0, 1e30, 1.0)) << i;
    if (lambda[i] == 0) continue;
    ++pressed;
    EXPECT_TRUE(criterion.isNearlyDegenerate(i, lambda[i], 0.0, 1.0)) << i;
    EXPECT_FALSE(criterion.isNearlyDegenerate(i, lambda[i], 1e30, 1.0)) << i;
    EXPECT_FALSE(criterion.isNearlyDegenerate(i, lambda[i], 0.0, 0.0)) << i;
  }
  int total = pressed;
  Teuchos::reduceAll(*p.qp.A->getRangeMap()->getComm(), Teuchos::REDUCE_SUM, 1, &pressed, &total);
  EXPECT_GT(total, 0);
}

}  // namespace
