#include "solver/preconditioner/SubspaceCorrectedPreconditioner.hpp"

#include <stdexcept>

#include <Tpetra_MultiVector.hpp>


namespace signorini {

SubspaceCorrectedPreconditioner::SubspaceCorrectedPreconditioner(RCP<const Operator> H, RCP<const Operator> B,
                                                                 RCP<const Operator> S,
                                                                 ContactCorrection combination,
                                                                 RCP<const Operator> HP)
    : H_(std::move(H)),
      B_(std::move(B)),
      S_(std::move(S)),
      HP_(std::move(HP)),
      multiplicative_(combination == ContactCorrection::Multiplicative) {
  if (combination == ContactCorrection::None)
    throw std::logic_error("SubspaceCorrectedPreconditioner: a subspace correction needs a combination");
}

void SubspaceCorrectedPreconditioner::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                            Scalar beta) const {
  const std::size_t numVectors = X.getNumVectors();
  if (Z_.is_null() || Z_->getNumVectors() != numVectors) {
    Z_ = rcp(new MultiVector(H_->getDomainMap(), numVectors));
    correction_ = rcp(new MultiVector(H_->getDomainMap(), numVectors));
    residual_ = rcp(new MultiVector(H_->getRangeMap(), numVectors));
  }
  MultiVector &Z = *Z_, &correction = *correction_, &residual = *residual_;
  // Corrections go through a scratch vector: not every preconditioner honours beta.
  if (!multiplicative_) {
    B_->apply(X, Z);
    S_->apply(X, correction);
    Z.update(1.0, correction, 1.0);
  } else {
    S_->apply(X, Z);
    for (const Operator* M : {B_.get(), S_.get()}) {
      residual.assign(X);
      if (HP_.is_null())
        H_->apply(Z, residual, Teuchos::NO_TRANS, -1.0, 1.0);
      else  // H Z with Z on the subspace, then H Z on the subspace rows (all S reads)
        HP_->apply(Z, residual, M == B_.get() ? Teuchos::NO_TRANS : Teuchos::TRANS, -1.0, 1.0);
      M->apply(residual, correction);
      Z.update(1.0, correction, 1.0);
    }
  }
  Y.update(alpha, Z, beta);
}

}  // namespace signorini
