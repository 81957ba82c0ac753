#pragma once
// A preconditioner B of H (an AMG cycle) combined with an exact subspace solve S =
// P (P^T H P)^-1 P^T, in the manner of AMG with filtering (Petrides, Hartland, Kolev et al.):
//   "additive":        M^-1 = B + S;
//   "multiplicative":  M^-1 r: x = S r, x += B (r - H x), x += S (r - H x)
//                      (symmetric: S, B, S; symmetric positive definite when B is).
// The subspace takes over what B cannot see: the large A^T D A entries of the active
// contact DOFs as the barrier parameter goes to zero.
// Given HP = H P P^T (BarrierHessianOperator::onContactColumns), the multiplicative form
// takes both residuals from it instead of H: the first x = S r lies on the subspace, so
// H x = HP x; the second residual is read by S on the subspace only, so P^T H x = (HP)^T x.
// This saves two applications of H per application of M^-1, with the same result.
#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// How the subspace solve joins the AMG ("Preconditioner/contact correction").
enum class ContactCorrection { None, Additive, Multiplicative };

class SubspaceCorrectedPreconditioner : public Operator {
 public:
  // S must vanish off the subspace and read only the subspace entries of its input;
  // `combination` is Additive or Multiplicative.
  SubspaceCorrectedPreconditioner(RCP<const Operator> H, RCP<const Operator> B, RCP<const Operator> S,
                                  ContactCorrection combination, RCP<const Operator> HP = Teuchos::null);

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override { return H_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return H_->getRangeMap(); }
  bool hasTransposeApply() const override { return true; }

 private:
  RCP<const Operator> H_, B_, S_, HP_;
  bool multiplicative_;
  // Scratch, allocated once per number of columns: apply() runs in every Krylov iteration.
  mutable RCP<MultiVector> Z_, correction_, residual_;
};

}  // namespace signorini
