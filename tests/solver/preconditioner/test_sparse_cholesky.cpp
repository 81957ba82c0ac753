// CHOLMOD's Cholesky factorization on one rank: A^-1 to round-off, a matrix of the same
// pattern refactored with the kept analysis, a copy that leaves the original usable, a new
// pattern, and a matrix that is not positive definite refused.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/LocalBlock.hpp"
#include "solver/preconditioner/SparseCholesky.hpp"
#include "support/DirectSolveResidual.hpp"

namespace {

using namespace signorini;
using signorini::testing::relativeResidual;

// The n x n matrix tridiag(-1, diagonal, -1) (plus a coupling of the ends if `ring`) on MPI_COMM_SELF.
RCP<CrsMatrix> tridiagonal(int n, double diagonal, bool ring = false) {
  auto map = rcp(new Map(n, 0, selfComm()));
  auto A = rcp(new CrsMatrix(map, 3));
  for (GlobalOrdinal i = 0; i < n; ++i) {
    std::vector<GlobalOrdinal> cols{i};
    std::vector<double> vals{diagonal};
    if (i > 0 || ring) cols.push_back((i + n - 1) % n), vals.push_back(-1.0);
    if (i + 1 < n || ring) cols.push_back((i + 1) % n), vals.push_back(-1.0);
    A->insertGlobalValues(i, cols.size(), vals.data(), cols.data());
  }
  A->fillComplete();
  return A;
}

TEST(SparseCholesky, SolvesRefactorsAndCopies) {
  const auto A = tridiagonal(500, 2.5);
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(*A));
  EXPECT_LT(relativeResidual(*A, cholesky), 1e-14);

  const SparseCholesky copy(cholesky);
  const auto B = tridiagonal(500, 4.0);  // same pattern, new values
  ASSERT_TRUE(cholesky.factor(*B));
  EXPECT_LT(relativeResidual(*B, cholesky), 1e-14);
  EXPECT_LT(relativeResidual(*A, copy), 1e-14);  // the copy still holds A's factor

  const auto ring = tridiagonal(300, 2.5, true);  // another pattern and size
  ASSERT_TRUE(cholesky.factor(*ring));
  EXPECT_LT(relativeResidual(*ring, cholesky), 1e-14);
}

TEST(SparseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  SparseCholesky cholesky;
  EXPECT_FALSE(cholesky.factor(*tridiagonal(50, 1.0, true)));  // singular: the constant vector
  EXPECT_FALSE(cholesky.factor(*tridiagonal(50, -2.5)));
  MultiVector b(tridiagonal(50, 2.5)->getRangeMap(), 1), x(b, Teuchos::Copy);
  EXPECT_THROW(cholesky.solve(b, x), Error);  // no factor is kept
}

}  // namespace
