#pragma once
// A preconditioner B of H = Q + A^T D A combined with an exact solve on the rigid body
// motions that only the contact holds (F, orthonormal columns, Q F = 0):
//   M^-1 r:  x = C r,  x += B (r - H x),  x += C (r - H x),   C = F (F^T H F)^-1 F^T
// (symmetric: C, B, C; a coarse space of dimension at most 6 solved exactly, as balancing
// domain decomposition methods do with their coarse space). Along F, H has only the stiffness
// that the contact's barrier weights give it, sum_i D_i (a_i f)^2: many orders of magnitude
// below Q's once most constraints are released, and seen only in part by a multigrid built
// for filtered weights, which the contact correction then has to make up for every DOF of
// the body. With HF = H F kept, M^-1 costs B plus two reductions of f numbers.
#include <vector>

#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class BarrierHessianOperator;

class FreeMotionCorrection : public Operator {
 public:
  // F: the free motions on H's domain map (checkRigidBodyMotionsHeld). Collective.
  FreeMotionCorrection(RCP<const BarrierHessianOperator> H, RCP<const MultiVector> F);

  // H's weights changed: recomputes H F and factors F^T H F; without weights on F (F^T H F
  // singular), B alone until the next refresh. Collective.
  void refresh();
  // The preconditioner C, B, C is combined with.
  void setInner(RCP<const Operator> B) { B_ = std::move(B); }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override;
  RCP<const Map> getRangeMap() const override;
  bool hasTransposeApply() const override { return true; }

 private:
  RCP<const BarrierHessianOperator> H_;
  RCP<const MultiVector> F_;
  RCP<MultiVector> QF_, HF_;
  RCP<const Operator> B_;
  std::vector<double> factor_;  // Cholesky factor of F^T H F, column-major
  bool active_ = false;
  mutable RCP<Vector> z_, residual_, correction_;

  // (F^T H F)^-1 c, in place.
  void solveCoarse(std::vector<double>& c) const;
  // U^T x for the columns of U, summed over the ranks.
  std::vector<double> innerProducts(const MultiVector& U, const Vector& x) const;
};

}  // namespace signorini
