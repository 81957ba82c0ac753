// The exact solve of a small distributed matrix on rank 0: A^-1 on every rank count, the
// alpha/beta contract, a second matrix on the same maps, and LU for an indefinite matrix.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/GatheredDirectSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// |A x - b| / |b| for x = alpha A^-1 b + beta y0 given the operator's result, per column.
void expectInverse(const CrsMatrix& A, const Operator& inverse, double tolerance) {
  MultiVector x(A.getDomainMap(), 2), b(A.getRangeMap(), 2), y(A.getDomainMap(), 2), residual(A.getRangeMap(), 2);
  x.randomize();
  A.apply(x, b);
  y.randomize();
  MultiVector y0(y, Teuchos::Copy);
  inverse.apply(b, y, Teuchos::NO_TRANS, 2.0, -3.0);  // y = 2 x - 3 y0
  y.update(1.5, y0, 0.5);                              // x
  y.update(-1.0, x, 1.0);
  Teuchos::Array<double> error(2), size(2);
  y.norm2(error());
  x.norm2(size());
  for (int j = 0; j < 2; ++j) EXPECT_LT(error[j], tolerance * size[j]) << "column " << j;
}

TEST(GatheredDirectSolver, AppliesTheInverseOnEveryRankCount) {
  for (int dim : {2, 3}) {
    const AssembledProblem problem = buildProblem(contactBoxProblem(dim, dim == 2 ? 8 : 4), Tpetra::getDefaultComm());
    const auto Q = Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid));
    GatheredDirectSolver solver;
    solver.compute(Q);
    expectInverse(*Q, *solver.getOperator(), 1e-10);
    // A second matrix on the same maps: the new inverse, and the old operator unchanged.
    const RCP<const Operator> first = solver.getOperator();
    const RCP<CrsMatrix> doubled = Tpetra::MatrixMatrix::add(2.0, false, *Q, 0.0, false, *Q);
    solver.compute(doubled);
    expectInverse(*doubled, *solver.getOperator(), 1e-10);
    expectInverse(*Q, *first, 1e-10);
  }
}

// A matrix that is not positive definite is factored by LU instead of Cholesky.
TEST(GatheredDirectSolver, FactorsAnIndefiniteMatrixByLU) {
  const AssembledProblem problem = buildProblem(contactBoxProblem(2, 8), Tpetra::getDefaultComm());
  const auto Q = Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid));
  const RCP<CrsMatrix> negated = Tpetra::MatrixMatrix::add(-1.0, false, *Q, 0.0, false, *Q);
  GatheredDirectSolver solver;
  solver.compute(negated);
  expectInverse(*negated, *solver.getOperator(), 1e-10);
  solver.compute(Q);  // and back to Cholesky
  expectInverse(*Q, *solver.getOperator(), 1e-10);
}

TEST(GatheredDirectSolver, NeedsAComputedMatrix) { EXPECT_THROW(GatheredDirectSolver().getOperator(), Error); }

}  // namespace
