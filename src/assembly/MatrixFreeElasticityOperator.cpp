#include "assembly/MatrixFreeElasticityOperator.hpp"

#include <utility>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/SummedRows.hpp"
#include "fe/ElasticityElement.hpp"
#include "fe/SimplexQuadrature.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {

MatrixFreeElasticityOperator::MatrixFreeElasticityOperator(std::shared_ptr<const DistributedSpace> shared,
                                                           CellBodies bodies,
                                                           const std::vector<char>& fixedSpaceDofs)
    : space_(std::move(shared)), ds_(*space_), bodies_(std::move(bodies)) {
  for (int b = 0; b < bodies_.numBodies(); ++b) {
    lambda_.push_back(bodies_.body(b).material.effectiveLame1(ds_.dim()));
    mu_.push_back(bodies_.body(b).material.lame2());
  }
  const DistributedSpace& ds = ds_;
  const LagrangeSpace& space = ds.space();
  const LagrangeBasis& basis = space.basis();
  const int dim = ds.dim(), npc = space.nodesPerCell();
  // Gradients of P_k are of degree k - 1: a rule of degree 2 (k - 1) integrates their products.
  const QuadratureRule rule = simplexQuadrature(dim, 2 * (space.degree() - 1));
  numPoints_ = rule.size();
  weights_ = rule.weights;
  gradients_.resize(numPoints_ * npc * dim);
  for (int q = 0; q < numPoints_; ++q) basis.gradients(&rule.points[q * dim], &gradients_[q * npc * dim]);

  const auto& overlap = ds.overlapSpaceNodes();
  std::vector<int> overlapIndex(space.numNodes());
  for (std::size_t i = 0; i < overlap.size(); ++i) overlapIndex[overlap[i]] = static_cast<int>(i);
  const long long numCells = ds.mesh().numCells();
  cellNodes_.resize(numCells * npc);
  cellGeometry_.resize(numCells * (1 + dim * dim));
  std::vector<double> vertexCoords((dim + 1) * dim);
  for (long long cell = 0; cell < numCells; ++cell) {
    for (int a = 0; a < npc; ++a) cellNodes_[cell * npc + a] = overlapIndex[space.cellNodes(cell)[a]];
    ds.mesh().cellVertexCoordinates(cell, vertexCoords.data());
    double* geometry = &cellGeometry_[cell * (1 + dim * dim)];
    geometry[0] = inverseJacobian(dim, vertexCoords.data(), geometry + 1);
  }

  fixed_.resize(overlap.size() * dim);
  for (std::size_t i = 0; i < overlap.size(); ++i)
    for (int c = 0; c < dim; ++c) fixed_[dim * i + c] = fixedSpaceDofs[dim * overlap[i] + c];
  const std::size_t numOwned = ds.ownedDofMap()->getNodeNumElements();
  for (std::size_t i = 0; i < numOwned; ++i)
    if (fixed_[i]) ownedFixed_.push_back(static_cast<LocalOrdinal>(i));
  toOverlap_ = rcp(new Import(ds.ownedDofMap(), ds.overlapDofMap()));
}

// y += Q x on the overlap DOFs of the local cells, prescribed DOFs left out: for the
// nodes per cell of each degree, so that every loop has a fixed length the compiler unrolls
// and vectorises.
template <int D>
void MatrixFreeElasticityOperator::applyCells(const double* x, double* y) const {
  switch (ds_.space().nodesPerCell()) {
    case D + 1: return applyCellsOf<D, D + 1>(x, y);                          // P1
    case (D + 1) * (D + 2) / 2: return applyCellsOf<D, (D + 1) * (D + 2) / 2>(x, y);  // P2
    case (D + 1) * (D + 2) * (D + 3) / 6: return applyCellsOf<D, (D + 1) * (D + 2) * (D + 3) / 6>(x, y);  // P3
    default: throw Error("MatrixFreeElasticityOperator: no cell kernel for this degree");
  }
}

// Per quadrature point, the displacement gradient is taken in reference coordinates first
// (G = sum_a x_a dphi_a^T, then grad u = G J^-1) and the stress is mapped back once
// (S = sigma J^-T, then y_a += S dphi_a): two passes over the nodes instead of mapping every
// node's gradient to physical coordinates.
template <int D, int NPC>
void MatrixFreeElasticityOperator::applyCellsOf(const double* x, double* y) const {
  const long long numCells = static_cast<long long>(cellNodes_.size()) / NPC;
  double xe[NPC][D], ye[NPC][D];
  for (long long cell = 0; cell < numCells; ++cell) {
    const int* nodes = &cellNodes_[cell * NPC];
    const double* geometry = &cellGeometry_[cell * (1 + D * D)];
    const double volume = geometry[0];
    const double* Jinv = geometry + 1;  // Jinv[s * D + e] = d xi_s / d x_e
    const double lambda = lambda_[bodies_.indexOf(cell)], mu = mu_[bodies_.indexOf(cell)];
    for (int a = 0; a < NPC; ++a)
      for (int c = 0; c < D; ++c) {
        const int dof = D * nodes[a] + c;
        xe[a][c] = fixed_[dof] ? 0.0 : x[dof];
        ye[a][c] = 0.0;
      }
    for (int q = 0; q < numPoints_; ++q) {
      const double* dphi = &gradients_[q * NPC * D];  // dphi[a * D + s] = d phi_a / d xi_s
      double G[D][D] = {};
      for (int a = 0; a < NPC; ++a)
        for (int c = 0; c < D; ++c)
          for (int s = 0; s < D; ++s) G[c][s] += xe[a][c] * dphi[a * D + s];
      double gradU[D][D] = {};  // gradU[c][e] = d u_c / d x_e
      for (int c = 0; c < D; ++c)
        for (int e = 0; e < D; ++e)
          for (int s = 0; s < D; ++s) gradU[c][e] += G[c][s] * Jinv[s * D + e];
      double trace = 0.0;
      for (int c = 0; c < D; ++c) trace += gradU[c][c];
      const double w = weights_[q] * volume;
      double sigma[D][D];
      for (int c = 0; c < D; ++c)
        for (int e = 0; e < D; ++e)
          sigma[c][e] = w * (mu * (gradU[c][e] + gradU[e][c]) + (c == e ? lambda * trace : 0.0));
      double S[D][D] = {};  // S[c][s] = sum_e sigma[c][e] d xi_s / d x_e
      for (int c = 0; c < D; ++c)
        for (int s = 0; s < D; ++s)
          for (int e = 0; e < D; ++e) S[c][s] += sigma[c][e] * Jinv[s * D + e];
      for (int a = 0; a < NPC; ++a)
        for (int c = 0; c < D; ++c)
          for (int s = 0; s < D; ++s) ye[a][c] += S[c][s] * dphi[a * D + s];
    }
    for (int a = 0; a < NPC; ++a)
      for (int c = 0; c < D; ++c) {
        const int dof = D * nodes[a] + c;
        if (!fixed_[dof]) y[dof] += ye[a][c];
      }
  }
}

// d += the diagonal entries of the local cells' element matrices, prescribed DOFs left out.
template <int D>
void MatrixFreeElasticityOperator::diagonalOfCells(double* d) const {
  const int npc = ds_.space().nodesPerCell();
  const long long numCells = static_cast<long long>(cellNodes_.size()) / npc;
  for (long long cell = 0; cell < numCells; ++cell) {
    const int* nodes = &cellNodes_[cell * npc];
    const double* geometry = &cellGeometry_[cell * (1 + D * D)];
    const double* Jinv = geometry + 1;
    const double lambda = lambda_[bodies_.indexOf(cell)], mu = mu_[bodies_.indexOf(cell)];
    for (int q = 0; q < numPoints_; ++q) {
      const double* dphi = &gradients_[q * npc * D];
      const double w = weights_[q] * geometry[0];
      for (int a = 0; a < npc; ++a) {
        double g[D], squared = 0.0;
        for (int e = 0; e < D; ++e) {
          g[e] = 0.0;
          for (int s = 0; s < D; ++s) g[e] += dphi[a * D + s] * Jinv[s * D + e];
          squared += g[e] * g[e];
        }
        for (int c = 0; c < D; ++c) {
          const int dof = D * nodes[a] + c;
          if (!fixed_[dof]) d[dof] += w * (mu * (squared + g[c] * g[c]) + lambda * g[c] * g[c]);
        }
      }
    }
  }
}

void MatrixFreeElasticityOperator::getLocalDiagCopy(Vector& diagonal) const {
  Vector overlapDiagonal(ds_.overlapDofMap());
  {
    auto d = overlapDiagonal.getDataNonConst();
    if (ds_.dim() == 2)
      diagonalOfCells<2>(d.getRawPtr());
    else
      diagonalOfCells<3>(d.getRawPtr());
  }
  diagonal.putScalar(0.0);
  diagonal.doExport(overlapDiagonal, *toOverlap_, Tpetra::ADD);
  auto out = diagonal.getDataNonConst();
  for (LocalOrdinal i : ownedFixed_) out[i] = 1.0;
}

void MatrixFreeElasticityOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                         Scalar beta) const {
  const std::size_t numVectors = X.getNumVectors();
  if (xOverlap_.is_null() || xOverlap_->getNumVectors() != numVectors) {
    xOverlap_ = rcp(new MultiVector(ds_.overlapDofMap(), numVectors));
    yOverlap_ = rcp(new MultiVector(ds_.overlapDofMap(), numVectors));
    result_ = rcp(new MultiVector(ds_.ownedDofMap(), numVectors));
  }
  xOverlap_->doImport(X, *toOverlap_, Tpetra::INSERT);
  yOverlap_->putScalar(0.0);
  for (std::size_t j = 0; j < numVectors; ++j) {
    auto x = xOverlap_->getData(j);
    auto y = yOverlap_->getDataNonConst(j);
    if (ds_.dim() == 2)
      applyCells<2>(x.getRawPtr(), y.getRawPtr());
    else
      applyCells<3>(x.getRawPtr(), y.getRawPtr());
  }
  result_->putScalar(0.0);
  result_->doExport(*yOverlap_, *toOverlap_, Tpetra::ADD);
  for (std::size_t j = 0; j < numVectors; ++j) {  // the identity on prescribed DOFs
    auto in = X.getData(j);
    auto out = result_->getDataNonConst(j);
    for (LocalOrdinal i : ownedFixed_) out[i] = in[i];
  }
  Y.update(alpha, *result_, beta);
}

std::vector<char> MatrixFreeElasticityOperator::prescribedDofs() const {
  std::vector<char> prescribed(ds_.ownedDofMap()->getNodeNumElements(), 0);
  for (LocalOrdinal i : ownedFixed_) prescribed[i] = 1;
  return prescribed;
}

RCP<CrsMatrix> MatrixFreeElasticityOperator::selectedRows(const Vector& selected) const {
  const int dim = ds_.dim(), npc = ds_.space().nodesPerCell(), n = dim * npc;
  const Map& overlapDofs = *ds_.overlapDofMap();
  Vector overlapSelected(ds_.overlapDofMap());
  overlapSelected.doImport(selected, *toOverlap_, Tpetra::INSERT);
  const auto chosen = overlapSelected.getData();
  std::vector<GlobalOrdinal> ids(overlapDofs.getNodeNumElements());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = overlapDofs.getGlobalElement(i);
  SummedRows rows(std::move(ids));
  // The element matrices of the cells that hold a selected DOF, prescribed rows and columns
  // left out as in the symmetric elimination.
  std::vector<double> vertexCoords((dim + 1) * dim), Ke;
  const auto dofOf = [&](const int* nodes, int a) { return dim * nodes[a / dim] + a % dim; };
  for (long long cell = 0; cell < ds_.mesh().numCells(); ++cell) {
    const int* nodes = &cellNodes_[cell * npc];
    bool touched = false;
    for (int a = 0; a < n && !touched; ++a) touched = chosen[dofOf(nodes, a)] != 0.0;
    if (!touched) continue;
    ds_.mesh().cellVertexCoordinates(cell, vertexCoords.data());
    elasticityStiffness(ds_.space().basis(), vertexCoords.data(), bodies_.of(cell).material, Ke);
    for (int a = 0; a < n; ++a) {
      const int row = dofOf(nodes, a);
      if (chosen[row] == 0.0 || fixed_[row]) continue;
      for (int b = 0; b < n; ++b)
        if (!fixed_[dofOf(nodes, b)]) rows.add(row, overlapDofs.getGlobalElement(dofOf(nodes, b)), Ke[a * n + b]);
    }
  }
  for (LocalOrdinal i : ownedFixed_)  // the unit diagonal of a prescribed DOF, from its owner
    if (chosen[i] != 0.0) rows.add(i, overlapDofs.getGlobalElement(i), 1.0);
  return rows.onOwners(ds_.ownedDofMap());
}

std::size_t MatrixFreeElasticityOperator::bytes() const {
  std::size_t work = 0;
  for (const auto& v : {xOverlap_, yOverlap_, result_})
    if (!v.is_null()) work += v->getLocalLength() * v->getNumVectors() * sizeof(double);
  return weights_.capacity() * sizeof(double) + gradients_.capacity() * sizeof(double) +
         cellNodes_.capacity() * sizeof(int) + cellGeometry_.capacity() * sizeof(double) + fixed_.capacity() +
         ownedFixed_.capacity() * sizeof(LocalOrdinal) + bodies_.bytes() + work;
}

}  // namespace signorini
