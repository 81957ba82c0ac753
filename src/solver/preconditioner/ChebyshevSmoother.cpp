#include "solver/preconditioner/ChebyshevSmoother.hpp"

#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

ChebyshevSmoother::ChebyshevSmoother(RCP<const Operator> A, RCP<const Vector> inverseDiagonal,
                                     const Parameters& parameters)
    : A_(std::move(A)), inverseDiagonal_(std::move(inverseDiagonal)), parameters_(parameters) {
  if (parameters_.degree < 1 || !(parameters_.maxEigenvalue > 0) || !(parameters_.eigenvalueRatio > 1) ||
      !(parameters_.boostFactor >= 1))
    throw Error("ChebyshevSmoother: needs degree >= 1, a positive max eigenvalue, ratio > 1 and boost >= 1");
}

void ChebyshevSmoother::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                              Scalar beta) const {
  const std::size_t numVectors = X.getNumVectors(), n = X.getLocalLength();
  if (W_.is_null() || W_->getNumVectors() != numVectors) {
    W_ = rcp(new MultiVector(A_->getRangeMap(), numVectors, false));
    AZ_ = rcp(new MultiVector(A_->getRangeMap(), numVectors, false));
    Z_ = rcp(new MultiVector(A_->getRangeMap(), numVectors, false));
  }
  // The polynomial's iterate goes straight into Y when nothing of Y is kept.
  MultiVector& Z = beta == 0.0 ? Y : *Z_;
  const double lower = parameters_.maxEigenvalue / parameters_.eigenvalueRatio;
  const double upper = parameters_.boostFactor * parameters_.maxEigenvalue;
  const double delta = 2.0 / (upper - lower), theta = (upper + lower) / 2.0, s1 = theta * delta;
  const auto dInverse = inverseDiagonal_->getData();
  for (std::size_t j = 0; j < numVectors; ++j) {  // W = D^-1 X / theta, Z = W
    const auto x = X.getData(j);
    auto w = W_->getDataNonConst(j);
    auto z = Z.getDataNonConst(j);
    for (std::size_t i = 0; i < n; ++i) z[i] = w[i] = (1.0 / theta) * dInverse[i] * x[i];
  }
  double rho = 1.0 / s1;
  for (int k = 1; k < parameters_.degree; ++k) {
    const double rhoNext = 1.0 / (2.0 * s1 - rho), c1 = rhoNext * rho, c2 = 2.0 * rhoNext * delta;
    rho = rhoNext;
    A_->apply(Z, *AZ_);
    for (std::size_t j = 0; j < numVectors; ++j) {  // W = c2 D^-1 (X - A Z) + c1 W, Z += W
      const auto x = X.getData(j), az = AZ_->getData(j);
      auto w = W_->getDataNonConst(j);
      auto z = Z.getDataNonConst(j);
      for (std::size_t i = 0; i < n; ++i) {
        w[i] = c2 * dInverse[i] * (x[i] - az[i]) + c1 * w[i];
        z[i] += w[i];
      }
    }
  }
  if (beta == 0.0) {
    if (alpha != 1.0) Y.scale(alpha);
  } else {
    Y.update(alpha, *Z_, beta);
  }
}

}  // namespace signorini
