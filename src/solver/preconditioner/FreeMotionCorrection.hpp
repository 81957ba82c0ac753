#pragma once
// A preconditioner B of H = Q + A^T D A combined with an exact solve on a coarse space U
// built around the rigid body motions that only the contact holds (F, orthonormal columns,
// Q F = 0):
//   M^-1 r:  x = C r,  x += B (r - H x),  x += C (r - H x),   C = U (U^T H U)^+ U^T
// (symmetric: C, B, C; a small coarse space solved exactly, as balancing domain decomposition
// methods do with theirs). Along F, H has only the stiffness that the contact's barrier
// weights give it, sum_i D_i (a_i f)^2: orders of magnitude below Q's while most constraints
// are free, which B, built for filtered weights, sees only in part. Once the contact closes,
// F itself is stiff, and the soft modes are the rigid motions of the body around a pinned
// contact patch (a ball rocking about its centre on a small patch: stiffness of order
// E a^3 for a patch of radius a): F with a correction near the patch that F alone cannot
// express. U = [F, BHF, (BH)^2 F, ...] (the preconditioned Krylov space of F, `depth`
// products deep) holds them: each product B H f is what B makes of f's stiffness, and f
// minus it is what B gets wrong. With HU = H U kept, M^-1 costs B plus two reductions of
// dim U numbers; each refresh costs `depth` applications of B and H per free motion.
#include <vector>

#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class BarrierHessianOperator;

class FreeMotionCorrection : public Operator {
 public:
  // F: the free motions on H's domain map (checkRigidBodyMotionsHeld); depth: how many
  // products B H the coarse space adds to F. Collective.
  FreeMotionCorrection(RCP<const BarrierHessianOperator> H, RCP<const MultiVector> F, int depth);

  // H's weights changed: the coarse space is rebuilt at the next apply(), with the B given
  // then (its products depend on H and B both).
  void refresh() { stale_ = true; }
  // The preconditioner C, B, C is combined with.
  void setInner(RCP<const Operator> B) { B_ = std::move(B); }

  // The coarse space U of the last apply(), one column per vector (for tests).
  RCP<const MultiVector> coarseSpace() const { return U_; }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override;
  RCP<const Map> getRangeMap() const override;
  bool hasTransposeApply() const override { return true; }

 private:
  RCP<const BarrierHessianOperator> H_;
  RCP<const MultiVector> F_;
  int depth_;
  RCP<MultiVector> QF_;
  RCP<const Operator> B_;
  mutable bool stale_ = true;
  mutable RCP<MultiVector> U_, HU_;
  mutable std::vector<double> inverse_;  // (U^T H U)^+, column-major, dim U squared
  mutable RCP<Vector> z_, residual_, correction_;

  // U = [F, products], H U and (U^T H U)^+.
  void buildCoarseSpace() const;
  void factorCoarseMatrix() const;
  // (U^T H U)^+ c
  std::vector<double> solveCoarse(const std::vector<double>& c) const;
  // U^T x for the columns of U, summed over the ranks.
  std::vector<double> innerProducts(const MultiVector& U, const Vector& x) const;
};

}  // namespace signorini
