// The Chebyshev smoother of an operator: the polynomial Ifpack2's Chebyshev applies to the
// same matrix with the same eigenvalue bounds, for several degrees, and the alpha/beta
// contract, on every rank count.
#include <gtest/gtest.h>

#include <Ifpack2_Chebyshev.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/ChebyshevSmoother.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;
using RowMatrix = Tpetra::RowMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;

TEST(ChebyshevSmoother, AppliesIfpack2sPolynomial) {
  const AssembledProblem problem = buildProblem(contactBoxProblem(2, 8), Tpetra::getDefaultComm());
  const RCP<const CrsMatrix> Q = assembledStiffness(problem.qp, problem.multigrid);
  auto inverseDiagonal = rcp(new Vector(Q->getRowMap()));
  Q->getLocalDiagCopy(*inverseDiagonal);
  inverseDiagonal->reciprocal(*inverseDiagonal);
  for (int degree : {1, 2, 3}) {
    ChebyshevSmoother::Parameters p;
    p.degree = degree;
    p.maxEigenvalue = 1.9;
    p.eigenvalueRatio = 7;
    p.boostFactor = 1.1;
    Ifpack2::Chebyshev<RowMatrix> reference(Q);
    Teuchos::ParameterList list;
    list.set("chebyshev: degree", degree);
    list.set("chebyshev: max eigenvalue", p.maxEigenvalue);
    list.set("chebyshev: ratio eigenvalue", p.eigenvalueRatio);
    list.set("chebyshev: boost factor", p.boostFactor);
    list.set("chebyshev: operator inv diagonal", Teuchos::rcp_const_cast<const Vector>(inverseDiagonal));
    reference.setParameters(list);
    reference.initialize();
    reference.compute();
    const ChebyshevSmoother smoother(Q, inverseDiagonal, p);

    MultiVector x(Q->getDomainMap(), 2), expected(Q->getRangeMap(), 2), y(Q->getRangeMap(), 2);
    x.randomize();
    reference.apply(x, expected);
    smoother.apply(x, y);
    y.update(-1.0, expected, 1.0);
    Teuchos::Array<double> error(2), size(2);
    y.norm2(error());
    expected.norm2(size());
    for (int j = 0; j < 2; ++j) EXPECT_LT(error[j], 1e-13 * size[j]) << "degree " << degree << ", column " << j;

    // Y = alpha S X + beta Y.
    MultiVector y0(Q->getRangeMap(), 2);
    y0.randomize();
    y.assign(y0);
    smoother.apply(x, y, Teuchos::NO_TRANS, 2.0, -3.0);
    y.update(3.0, y0, -2.0, expected, 1.0);
    y.norm2(error());
    for (int j = 0; j < 2; ++j) EXPECT_LT(error[j], 1e-13 * size[j]) << "degree " << degree << ", column " << j;
  }
}

TEST(ChebyshevSmoother, RefusesBadParameters) {
  const AssembledProblem problem = buildProblem(contactBoxProblem(2, 4), Tpetra::getDefaultComm());
  auto d = rcp(new Vector(problem.qp.Q->getRangeMap()));
  d->putScalar(1.0);
  ChebyshevSmoother::Parameters p;  // no max eigenvalue
  EXPECT_THROW(ChebyshevSmoother(problem.qp.Q, d, p), Error);
  p.maxEigenvalue = 2.0;
  p.degree = 0;
  EXPECT_THROW(ChebyshevSmoother(problem.qp.Q, d, p), Error);
}

}  // namespace
