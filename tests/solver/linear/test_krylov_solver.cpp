// KrylovSolver's stopping targets: relative to the right-hand side, and, with a start
// reduction, relative to the starting residual between a floor and a cap.
#include <gtest/gtest.h>

#include <cmath>

#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
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

// Jacobi with a count of its applications.
class CountingJacobi : public Operator {
 public:
  explicit CountingJacobi(const CrsMatrix& A) : inverseDiagonal_(A.getRowMap()) {
    A.getLocalDiagCopy(inverseDiagonal_);
    inverseDiagonal_.reciprocal(inverseDiagonal_);
  }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha, Scalar beta) const override {
    ++applications;
    Y.elementWiseMultiply(alpha, inverseDiagonal_, X, beta);
  }
  RCP<const Map> getDomainMap() const override { return inverseDiagonal_.getMap(); }
  RCP<const Map> getRangeMap() const override { return inverseDiagonal_.getMap(); }
  mutable int applications = 0;

 private:
  Vector inverseDiagonal_;
};

// S L S with L the 1D Laplacian and S a varying diagonal: Jacobi is not a multiple of the identity.
RCP<CrsMatrix> scaledLaplacian(long long n) {
  auto map = rcp(new Map(n, 0, Tpetra::getDefaultComm()));
  auto A = rcp(new CrsMatrix(map, 3));
  auto s = [](GlobalOrdinal g) { return 1.0 + 0.5 * std::sin(0.1 * static_cast<double>(g)); };
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i);
    for (GlobalOrdinal j : {g - 1, g, g + 1})
      if (j >= 0 && j < n)
        A->insertGlobalValues(g, Teuchos::tuple(j), Teuchos::tuple(s(g) * s(j) * (j == g ? 2.0 : -1.0)));
  }
  A->fillComplete();
  return A;
}

TEST(KrylovSolver, CgSkipsThePreconditionerOnAConvergedResidual) {
  const auto A = scaledLaplacian(300);
  auto b = rcp(new MultiVector(A->getRangeMap(), 1));
  b->randomize();
  const double tol = 1e-8;

  auto M = rcp(new CountingJacobi(*A));
  auto x = rcp(new MultiVector(A->getDomainMap(), 1));
  const KrylovResult result = KrylovSolver().solve(A, M, b, x, tol, 1000);
  ASSERT_TRUE(result.converged);
  ASSERT_GT(result.iterations, 10);
  // Belos applies M once to r0 and once per iteration, the last time to a residual that
  // already passed: that one is left out.
  EXPECT_EQ(M->applications, result.iterations);
  EXPECT_LE(residualNorm(*A, *b, *x), tol * b->getVector(0)->norm2());

  // The iterates are Belos' own: its CG, run directly with the same M, ends on the same x
  // after the same iterations.
  auto direct = rcp(new CountingJacobi(*A));
  auto y = rcp(new MultiVector(A->getDomainMap(), 1));
  auto problem = rcp(new Belos::LinearProblem<Scalar, MultiVector, Operator>(A, y, b));
  problem->setRightPrec(direct);
  problem->setProblem();
  auto params = rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", tol);
  params->set("Maximum Iterations", 1000);
  params->set("Implicit Residual Scaling", "Norm of RHS");
  params->set("Assert Positive Definiteness", false);
  Belos::PseudoBlockCGSolMgr<Scalar, MultiVector, Operator> cg(problem, params);
  ASSERT_EQ(cg.solve(), Belos::Converged);
  EXPECT_EQ(cg.getNumIters(), result.iterations);
  EXPECT_EQ(direct->applications, result.iterations + 1);
  y->update(-1.0, *x, 1.0);
  EXPECT_EQ(y->getVector(0)->normInf(), 0.0);

  // A start that already meets the target: no iteration, no application.
  auto again = rcp(new CountingJacobi(*A));
  const KrylovResult none = KrylovSolver().solve(A, again, b, x, tol, 1000);
  EXPECT_TRUE(none.converged);
  EXPECT_EQ(none.iterations, 0);
  EXPECT_EQ(again->applications, 0);
}

}  // namespace
