#pragma once
// H = Q + A^T D A with D diagonal: the Hessian of the log-barrier function (D = mu / s^2)
// and the condensed primal-dual matrix (D = Lambda C^-1). Applied matrix-free: A^T D A is
// never formed into Q.
#include <Tpetra_Operator.hpp>

#include "signorini/TpetraTypes.hpp"

namespace signorini {

class BarrierHessianOperator : public Operator {
 public:
  BarrierHessianOperator(RCP<const Operator> Q, RCP<const CrsMatrix> A);

  // D, on A's range map (copied); all zeros until set.
  void setWeights(const Vector& D);
  const Vector& weights() const { return *D_; }

  // Y = alpha * H X + beta * Y (H is symmetric, so every mode applies H). X and Y must not alias.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override { return Q_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return Q_->getRangeMap(); }
  bool hasTransposeApply() const override { return true; }

  // Q + A^T D A as an assembled matrix (needs Q to be a CrsMatrix): for preconditioners
  // and tests, never for applying H.
  RCP<CrsMatrix> assemble() const;

 private:
  RCP<const Operator> Q_;
  RCP<const CrsMatrix> A_;
  RCP<Vector> D_;
  mutable RCP<MultiVector> AX_;  // scratch, resized to the number of columns of X
};

}  // namespace signorini
