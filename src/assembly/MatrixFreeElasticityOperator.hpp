#pragma once
// The stiffness matrix of isotropic linear elasticity on a DistributedSpace, applied cell by
// cell without storing it. Per cell it keeps only the inverse Jacobian, the volume and the
// cell's overlap node indices; the P_k gradients at the quadrature points are tabulated once
// on the reference cell. An application imports x to the overlap nodes, computes on every
// local cell the stress sigma(u) = lambda tr(grad u) I + mu (grad u + grad u^T) at the
// quadrature points and integrates sigma : grad phi_a, and exports the sums to the owners.
// Prescribed DOFs have the rows and columns of the identity, as in the assembled matrix.
#include <cstddef>
#include <memory>
#include <vector>

#include "assembly/CellBodies.hpp"
#include "assembly/DistributedSpace.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/fe/IsotropicMaterial.hpp"
#include "signorini/solver/StiffnessOperator.hpp"

namespace signorini {

class MatrixFreeElasticityOperator : public StiffnessOperator {
 public:
  // fixedSpaceDofs: 1 for a prescribed DOF, indexed dim * (node of ds->space()) + component;
  // bodies: the material of each cell of ds->mesh(). Shares ds, on whose cells it applies Q.
  MatrixFreeElasticityOperator(std::shared_ptr<const DistributedSpace> ds, CellBodies bodies,
                               const std::vector<char>& fixedSpaceDofs);

  // Y = beta Y + alpha Q X; Q is symmetric, so every mode applies Q.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override;
  RCP<const Map> getDomainMap() const override { return ds_.ownedDofMap(); }
  RCP<const Map> getRangeMap() const override { return ds_.ownedDofMap(); }
  bool hasTransposeApply() const override { return true; }

  // diagonal = diag(Q) on the owned DOFs, cell by cell: the entry of DOF (node a, component c)
  // is the integral of mu (|grad phi_a|^2 + (d_c phi_a)^2) + lambda (d_c phi_a)^2; 1 on
  // prescribed DOFs. What a Jacobi or Chebyshev smoother of Q needs, without Q. Collective.
  void getLocalDiagCopy(Vector& diagonal) const override;

  std::vector<char> prescribedDofs() const override;

  // The element matrices of the cells that hold a selected DOF, their selected rows summed
  // over the ranks' cells (the entries of the assembled Q, summed in another order).
  RCP<CrsMatrix> selectedRows(const Vector& selected) const override;

  // Heap bytes of what the operator stores (per-cell data, tables, work vectors).
  std::size_t bytes() const;

 private:
  template <int D>
  void applyCells(const double* x, double* y) const;
  template <int D, int NPC>
  void applyCellsOf(const double* x, double* y) const;
  template <int D>
  void diagonalOfCells(double* d) const;

  std::shared_ptr<const DistributedSpace> space_;
  const DistributedSpace& ds_;  // *space_
  CellBodies bodies_;
  std::vector<double> lambda_, mu_;  // per body
  int numPoints_ = 0;
  std::vector<double> weights_;          // reference quadrature weights
  std::vector<double> gradients_;        // [point][node][reference direction]
  std::vector<int> cellNodes_;           // overlap node index of each cell node
  std::vector<double> cellGeometry_;     // per cell: |det J|, then J^-1 row-major
  std::vector<char> fixed_;              // per overlap DOF
  std::vector<LocalOrdinal> ownedFixed_;  // owned DOFs that are prescribed
  RCP<const Import> toOverlap_;
  mutable RCP<MultiVector> xOverlap_, yOverlap_, result_;
};

}  // namespace signorini
