#pragma once
// The solve on the contact subspace: with P the injection of the degrees of freedom that
// appear in A (the contact DOFs), applies P (P^T H P)^-1 P^T for H = Q + A^T D A, exactly or
// block by block. P^T H P has one row per contact DOF; it is factored on one-rank
// communicators (LocalDirectSolver: a Cholesky factorization, as it is positive definite):
//   Gathered: the whole of it on rank 0; every application gathers the subspace residual
//             to rank 0 and scatters the correction back. Exact on any rank count.
//   PerRank:  each rank factors the block of the contact DOFs it owns (P_r^T H P_r, with
//             every constraint that touches them) and applies its inverse, block Jacobi over
//             the ranks: no step gathers the subspace. The same as Gathered on one rank;
//             close to it when every constraint's DOFs lie on one rank (nodal constraints:
//             the blocks then drop only stiffness couplings), far from it when constraints
//             that couple several nodes (weighted gaps) are split between ranks (their large
//             barrier weights couple the blocks; CG stalled on 3D P1 nx = 40 at 4 ranks).
//   Auto:     PerRank when every constraint's DOFs lie on one rank, Gathered otherwise.
#include <memory>

#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

enum class ContactSubspaceBlocks { Auto, Gathered, PerRank };

class ContactSubspaceSolver : public Operator {
 public:
  // Q and A as in the contact QP; Q's row map must be its domain map. Collective.
  ContactSubspaceSolver(const CrsMatrix& Q, const CrsMatrix& A,
                        ContactSubspaceBlocks blocks = ContactSubspaceBlocks::Auto);
  ~ContactSubspaceSolver() override;

  // D on A's range map: refactors P^T (Q + A^T D A) P, or each rank's block of it.
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
  // Whether each rank solves its own block (PerRank, or Auto resolved to it).
  bool perRank() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini
