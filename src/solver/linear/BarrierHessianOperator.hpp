#pragma once
// H = Q + A^T D A with D diagonal: the Hessian of the log-barrier function (D = mu / s^2)
// and the condensed primal-dual matrix (D = Lambda C^-1). Applied matrix-free: A^T D A is
// never formed into Q.
#include <Tpetra_Operator.hpp>

#include <memory>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class BarrierHessianOperator : public Operator {
 public:
  // Qassembled: Q as a matrix when Q is an operator of its own (matrix-free), for
  // assemble(); by default Q itself if it is a CrsMatrix.
  BarrierHessianOperator(RCP<const Operator> Q, RCP<const CrsMatrix> A, RCP<const CrsMatrix> Qassembled = Teuchos::null);

  // D, on A's range map (copied); all zeros until set.
  void setWeights(const Vector& D);
  const Vector& weights() const { return *D_; }

  // Y = alpha * op(H) X + beta * Y. X and Y must not alias. H is symmetric when Q is; the
  // transpose is applied as such for the column slice below.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override { return Q_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return Q_->getRangeMap(); }
  bool hasTransposeApply() const override { return true; }

  // Y = Q X: what stays valid of H X when D changes.
  void applyQ(const MultiVector& X, MultiVector& Y) const;
  // Y = H X given QX = Q X, for the price of A^T D A X; the same values as apply(X, Y).
  void applyGivenQX(const MultiVector& X, const MultiVector& QX, MultiVector& Y) const;

  // Q + A^T D A as an assembled matrix (needs Q assembled): for preconditioners
  // and tests, never for applying H. When every entry of A^T D A falls on an entry of Q's
  // graph in a row this rank owns (nodal constraints couple the DOFs of one node), the
  // result shares Q's graph and costs a copy of Q's values; otherwise (weighted gaps couple
  // the nodes around a contact vertex) (A^T D) A is a sparse product that keeps its pattern
  // from the first call, added at known positions into the fixed pattern of Q + A^T A.
  RCP<CrsMatrix> assemble() const;
  // Q + A^T D A with other weights D than the operator's (on A's range map).
  RCP<CrsMatrix> assemble(const Vector& D) const;

  // A^T D A alone, on Q's row map (nonzero on the contact DOFs' rows), for weights D (on A's
  // range map); Q need not be assembled. The matrix keeps its pattern (that of A^T A) from
  // the first call and is overwritten by the next one. Collective.
  RCP<const CrsMatrix> contactTerm(const Vector& D) const;

  // Whether assemble() gives matrices on Q's graph, as above. Collective at its first call.
  bool assemblesOnQGraph() const;
  // H, assembled by assemble() on Q's graph, becomes Q + A^T D A in place: the values of
  // assemble(D), for the cost of the entries A^T D A touches. Returns the entries that
  // changed, by how much, as a matrix on H's row map. Needs assemblesOnQGraph(). Collective.
  RCP<CrsMatrix> updateAssembled(CrsMatrix& H, const Vector& D) const;

  // H P P^T, with P the restriction to the contact DOFs (those in A): Q's columns on the
  // contact DOFs plus A^T D A, with a copy of the current D. It applies H to vectors that
  // vanish off the contact DOFs, and its transpose P P^T H gives H's contact rows, for a
  // fraction of the cost of H. `contactRows`: a matrix on Q's row map whose rows at the
  // contact DOFs are Q's (Q itself will do); Q is symmetric, so its columns there are their
  // transpose. Collective.
  RCP<BarrierHessianOperator> onContactColumns(const CrsMatrix& contactRows) const;

 private:
  RCP<const Operator> Q_;
  RCP<const CrsMatrix> Qmatrix_;  // Q assembled, or null
  RCP<const CrsMatrix> A_;
  RCP<Vector> D_;
  mutable RCP<MultiVector> AX_;  // scratch, resized to the number of columns of X

  // Where A^T D A adds into Q's local values array: D[constraint] * coefficient at
  // `position`, in local row `row`; sorted by position. Found on the first assemble();
  // `inQPattern_` is -1 until then, and 0 if some entry is missing from Q's graph on some rank.
  struct Contribution {
    std::size_t position;
    LocalOrdinal row;
    int constraint;
    double coefficient;
  };
  mutable int inQPattern_ = -1;
  mutable std::vector<Contribution> contributions_;
  bool findPositionsInQPattern(const CrsMatrix& Q) const;

  struct ProductPattern;
  mutable std::shared_ptr<ProductPattern> product_;
  RCP<CrsMatrix> assembleByProduct(const CrsMatrix& Q, const Vector& D) const;
};

}  // namespace signorini
