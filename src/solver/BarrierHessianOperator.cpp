#include "signorini/BarrierHessianOperator.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/Error.hpp"

namespace signorini {

BarrierHessianOperator::BarrierHessianOperator(RCP<const Operator> Q, RCP<const CrsMatrix> A)
    : Q_(std::move(Q)), A_(std::move(A)), D_(rcp(new Vector(A_->getRangeMap()))) {
  if (!A_->getDomainMap()->isSameAs(*Q_->getDomainMap()))
    throw Error("BarrierHessianOperator: A's domain map differs from Q's");
}

void BarrierHessianOperator::setWeights(const Vector& D) { D_->assign(D); }

void BarrierHessianOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp,
                                   Scalar alpha, Scalar beta) const {
  const std::size_t numVectors = X.getNumVectors();
  if (AX_.is_null() || AX_->getNumVectors() != numVectors)
    AX_ = rcp(new MultiVector(A_->getRangeMap(), numVectors));
  A_->apply(X, *AX_);
  AX_->elementWiseMultiply(1.0, *D_, *AX_, 0.0);
  Q_->apply(X, Y, Teuchos::NO_TRANS, alpha, beta);
  A_->apply(*AX_, Y, Teuchos::TRANS, alpha, 1.0);
}

RCP<CrsMatrix> BarrierHessianOperator::assemble() const {
  auto Q = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q_);
  if (Q.is_null()) throw Error("BarrierHessianOperator::assemble needs Q as a CrsMatrix");
  CrsMatrix DA(*A_, Teuchos::Copy);
  DA.leftScale(*D_);
  auto AtDA = rcp(new CrsMatrix(A_->getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(*A_, true, DA, false, *AtDA);
  return Tpetra::MatrixMatrix::add(1.0, false, *Q, 1.0, false, *AtDA);
}

}  // namespace signorini
