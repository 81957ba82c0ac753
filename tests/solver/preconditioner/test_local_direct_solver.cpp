// The one-rank direct solve: Cholesky for a positive definite matrix, LU for an indefinite
// one, both for a matrix whose column map is not its row map, A^-1 to round-off in each
// case, and a copy that keeps the original usable.
#include <gtest/gtest.h>

#include <numeric>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "solver/preconditioner/LocalBlock.hpp"
#include "solver/preconditioner/LocalDirectSolver.hpp"
#include "support/DirectSolveResidual.hpp"

namespace {

using namespace signorini;
using signorini::testing::relativeResidual;

// tridiag(-1, diagonal, -1) of order n on MPI_COMM_SELF; with `reversedColumns`, its column
// map lists the columns last to first (the same matrix, other local column indices).
RCP<CrsMatrix> tridiagonal(int n, double diagonal, bool reversedColumns = false) {
  auto rows = rcp(new Map(n, 0, selfComm()));
  RCP<CrsMatrix> A;
  if (reversedColumns) {
    std::vector<GlobalOrdinal> ids(n);
    std::iota(ids.rbegin(), ids.rend(), GlobalOrdinal(0));
    auto columns = rcp(new Map(n, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, selfComm()));
    A = rcp(new CrsMatrix(rows, columns, 3));
  } else {
    A = rcp(new CrsMatrix(rows, 3));
  }
  for (GlobalOrdinal i = 0; i < n; ++i) {
    std::vector<GlobalOrdinal> cols{i};
    std::vector<double> vals{diagonal};
    if (i > 0) cols.push_back(i - 1), vals.push_back(-1.0);
    if (i + 1 < n) cols.push_back(i + 1), vals.push_back(-1.0);
    A->insertGlobalValues(i, cols.size(), vals.data(), cols.data());
  }
  A->fillComplete(rows, rows);
  return A;
}

TEST(LocalDirectSolver, FactorsAPositiveDefiniteMatrixByCholesky) {
  const RCP<CrsMatrix> A = tridiagonal(50, 2.5);
  LocalDirectSolver solver;
  solver.factor(A);
  EXPECT_TRUE(solver.cholesky());
  EXPECT_LT(relativeResidual(*A, solver), 1e-13);
}

TEST(LocalDirectSolver, FactorsAnIndefiniteMatrixByLU) {
  const RCP<CrsMatrix> indefinite = tridiagonal(50, 0.3), definite = tridiagonal(50, 2.5);
  LocalDirectSolver solver;
  solver.factor(indefinite);
  EXPECT_FALSE(solver.cholesky());
  EXPECT_LT(relativeResidual(*indefinite, solver), 1e-12);
  solver.factor(definite);  // and back to Cholesky
  EXPECT_TRUE(solver.cholesky());
  EXPECT_LT(relativeResidual(*definite, solver), 1e-13);
}

// Another order of the local columns than of the rows: the same solves.
TEST(LocalDirectSolver, FactorsAMatrixWithAnotherColumnOrder) {
  for (double diagonal : {2.5, 0.3}) {
    const RCP<CrsMatrix> A = tridiagonal(50, diagonal, true);
    LocalDirectSolver solver;
    solver.factor(A);
    EXPECT_EQ(solver.cholesky(), diagonal > 2.0) << diagonal;
    EXPECT_LT(relativeResidual(*A, solver), 1e-12) << diagonal;
  }
}

TEST(LocalDirectSolver, ACopyRefactorsAndLeavesTheOriginalUsable) {
  const RCP<CrsMatrix> A = tridiagonal(50, 2.5), B = tridiagonal(50, 4.0);
  LocalDirectSolver first;
  first.factor(A);
  LocalDirectSolver second(first);
  second.factor(B);
  EXPECT_LT(relativeResidual(*A, first), 1e-13);
  EXPECT_LT(relativeResidual(*B, second), 1e-13);
}

}  // namespace
