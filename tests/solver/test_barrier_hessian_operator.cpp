// H = Q + A^T D A applied matrix-free agrees with the assembled matrix, with the full
// Y = alpha H X + beta Y contract, on every rank count.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/BarrierHessianOperator.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

TEST(BarrierHessianOperator, MatchesTheAssembledMatrix) {
  for (const char* name : {"M", "B", "H"}) {
    AssembledProblem p = buildProblem(shippedProblem(std::string("paper/") + name), Tpetra::getDefaultComm());
    BarrierHessianOperator H(p.qp.Q, p.qp.A);
    Vector D(p.qp.A->getRangeMap());
    D.randomize(1.0, 1e6);  // spans the range of y/s met near a solution
    H.setWeights(D);
    const RCP<CrsMatrix> assembled = H.assemble();

    MultiVector X(H.getDomainMap(), 3), Y(H.getRangeMap(), 3), Z(H.getRangeMap(), 3);
    X.randomize();
    Y.randomize();
    Z.assign(Y);
    const double alpha = 0.7, beta = -1.3;
    H.apply(X, Y, Teuchos::NO_TRANS, alpha, beta);
    assembled->apply(X, Z, Teuchos::NO_TRANS, alpha, beta);

    Teuchos::Array<double> diff(3), scale(3);
    Z.norm2(scale());
    Z.update(-1.0, Y, 1.0);
    Z.norm2(diff());
    for (int k = 0; k < 3; ++k) EXPECT_LT(diff[k], 1e-13 * scale[k]) << name << " column " << k;

    // beta = 0 must ignore whatever Y held, even NaN.
    Y.putScalar(std::numeric_limits<double>::quiet_NaN());
    H.apply(X, Y);
    assembled->apply(X, Z);
    Z.update(-1.0, Y, 1.0);
    Z.norm2(diff());
    for (int k = 0; k < 3; ++k) EXPECT_LT(diff[k], 1e-13 * scale[k] / alpha) << name << " column " << k;
  }
}

TEST(BarrierHessianOperator, ZeroWeightsGiveQ) {
  AssembledProblem p = buildProblem(shippedProblem("paper/G"), Tpetra::getDefaultComm());
  BarrierHessianOperator H(p.qp.Q, p.qp.A);
  Vector x(H.getDomainMap()), y(H.getRangeMap()), z(H.getRangeMap());
  x.randomize();
  H.apply(x, y);
  p.qp.Q->apply(x, z);
  z.update(-1.0, y, 1.0);
  EXPECT_EQ(z.normInf(), 0.0);
}

}  // namespace
