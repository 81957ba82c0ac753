#pragma once
// Chebyshev polynomial smoothing of A x = b for an operator known only by its action and its
// diagonal: Y = alpha p(D^-1 A) D^-1 X + beta Y, the polynomial of the given degree that is
// small on [lambda_max / ratio, boost * lambda_max], from a zero start. The recurrence is
// Ifpack2's Chebyshev; Ifpack2 needs A as a RowMatrix, and the fine level of the geometric
// hierarchy, Q + A^T D A, is not assembled.
#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class ChebyshevSmoother : public Operator {
 public:
  struct Parameters {
    int degree = 2;
    double maxEigenvalue = 0;  // an estimate of the largest eigenvalue of D^-1 A
    double eigenvalueRatio = 7;
    double boostFactor = 1.1;
  };
  // `inverseDiagonal` (D^-1, on A's range map) is read at every application, not copied.
  ChebyshevSmoother(RCP<const Operator> A, RCP<const Vector> inverseDiagonal, const Parameters& parameters);

  // X and Y must not alias; every mode applies the same (symmetric) polynomial.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override { return A_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return A_->getRangeMap(); }
  bool hasTransposeApply() const override { return true; }

 private:
  RCP<const Operator> A_;
  RCP<const Vector> inverseDiagonal_;
  Parameters parameters_;
  mutable RCP<MultiVector> W_, AZ_, Z_;  // scratch, sized for the last number of columns
};

}  // namespace signorini
