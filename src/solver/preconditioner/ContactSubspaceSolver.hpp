#pragma once
// The exact solve on the contact subspace: with P the injection of the degrees of freedom
// that appear in A (the contact DOFs), applies P (P^T H P)^-1 P^T for H = Q + A^T D A.
// P^T H P has one row per contact DOF, so it is small, and it is factored by Amesos2's KLU2
// on rank 0 alone: Debian's Amesos2 solvers are wrong on communicators of more than one
// rank, so the subspace residual is gathered to rank 0, solved there on a one-rank
// communicator, and the correction scattered back.
#include <memory>

#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class ContactSubspaceSolver : public Operator {
 public:
  // Q and A as in the contact QP; Q's row map must be its domain map.
  ContactSubspaceSolver(const CrsMatrix& Q, const CrsMatrix& A);
  ~ContactSubspaceSolver() override;

  // D on A's range map: refactors P^T (Q + A^T D A) P.
  void setWeights(const Vector& D);

  // Y = alpha P (P^T H P)^-1 P^T X + beta Y.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override;
  RCP<const Map> getRangeMap() const override;
  bool hasTransposeApply() const override { return true; }

  // Number of contact DOFs (the dimension of the subspace).
  long long dimension() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini
