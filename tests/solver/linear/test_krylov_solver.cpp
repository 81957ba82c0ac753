// KrylovSolver's stopping targets: relative to the right-hand side, and, with a start
// reduction, relative to the starting residual between a floor and a cap.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/linear/KrylovSolver.hpp"

namespace {

using namespace signorini;

// The 1D Laplacian with n rows, spread over the ranks: SPD, and CG needs many iterations on it.
RCP<CrsMatrix> laplacian(long long n) {
  auto map = rcp(new Map(n, 0, Tpetra::getDefaultComm()));
  auto A = rcp(new CrsMatrix(map, 3));
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i);
    for (GlobalOrdinal j : {g - 1, g, g + 1})
      if (j >= 0 && j < n) A->insertGlobalValues(g, Teuchos::tuple(j), Teuchos::tuple(j == g ? 2.0 : -1.0));
  }
  A->fillComplete();
  return A;
}

double residualNorm(const CrsMatrix& A, const MultiVector& b, const MultiVector& x) {
  MultiVector r(b, Teuchos::Copy);
  A.apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  return r.getVector(0)->norm2();
}

struct StoppedSolve {
  KrylovResult result;
  double r0 = 0, r = 0;
};

// Solves from x0 = x* + offset * (a smooth error), so that ||r0|| is set by the offset.
StoppedSolve solveFrom(const RCP<CrsMatrix>& A, double offset, double tol, double reduction, double floor) {
  auto b = rcp(new MultiVector(A->getRangeMap(), 1));
  auto x = rcp(new MultiVector(A->getDomainMap(), 1));
  {
    auto position = [&](long i) {  // in [0, 1)
      return static_cast<double>(A->getRowMap()->getGlobalElement(i)) / A->getGlobalNumRows();
    };
    auto xd = x->getDataNonConst(0);
    for (long i = 0; i < xd.size(); ++i) xd[i] = std::sin(3.0 * position(i)) + position(i) * position(i);  // x*
    A->apply(*x, *b);
    for (long i = 0; i < xd.size(); ++i) xd[i] += offset * std::sin(7.0 * position(i)) * std::cos(31.0 * position(i));
  }
  StoppedSolve run;
  run.r0 = residualNorm(*A, *b, *x);
  run.result = KrylovSolver().solve(A, Teuchos::null, b, x, tol, 10000, reduction, floor);
  run.r = residualNorm(*A, *b, *x) / b->getVector(0)->norm2();
  run.r0 /= b->getVector(0)->norm2();
  return run;
}

TEST(KrylovSolver, StartReductionStopsRelativeToTheStartingResidual) {
  const auto A = laplacian(400);
  // A start close to the solution: reducing its residual 10x is a tighter target than 0.5 ||b||.
  const StoppedSolve reduced = solveFrom(A, 1e-3, 0.5, 0.1, 0.0);
  ASSERT_TRUE(reduced.result.converged);
  ASSERT_LT(reduced.r0, 0.01);
  EXPECT_LE(reduced.r, 0.1 * reduced.r0 * (1 + 1e-6));
  EXPECT_GT(reduced.result.iterations, 0);
  // The same as asking for that residual relative to ||b||.
  const StoppedSolve explicitTarget = solveFrom(A, 1e-3, 0.1 * reduced.r0, 0.0, 0.0);
  EXPECT_EQ(reduced.result.iterations, explicitTarget.result.iterations);

  // The cap binds when it is the tighter target.
  const StoppedSolve capped = solveFrom(A, 1e-3, 1e-3 * reduced.r0, 0.1, 0.0);
  EXPECT_LE(capped.r, 1e-3 * reduced.r0 * (1 + 1e-6));
  EXPECT_GT(capped.result.iterations, reduced.result.iterations);

  // The floor binds when the reduction would go below it: stop as soon as it is met.
  const StoppedSolve floored = solveFrom(A, 1e-3, 0.5, 1e-6, 0.05 * reduced.r0);
  const StoppedSolve floorTarget = solveFrom(A, 1e-3, 0.05 * reduced.r0, 0.0, 0.0);
  EXPECT_EQ(floored.result.iterations, floorTarget.result.iterations);
  EXPECT_LT(floored.result.iterations, solveFrom(A, 1e-3, 0.5, 1e-6, 0.0).result.iterations);
}

TEST(KrylovSolver, AStartWorseThanZeroCountsAsZero) {
  const auto A = laplacian(400);
  const StoppedSolve far = solveFrom(A, 1e3, 0.5, 0.1, 0.0);
  ASSERT_GT(far.r0, 1.0);  // the start's residual is larger than ||b||
  EXPECT_LE(far.r, 0.1 * (1 + 1e-6));
  // Not merely 0.1 ||r0||, which would be above ||b||.
  EXPECT_LT(far.r, 0.1 * far.r0);
}

}  // namespace
