#include "signorini/assembly/ContactPressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Kokkos_DualView.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "fe/ElasticityElement.hpp"
#include "fe/LagrangeBasis.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/KrylovSolver.hpp"

#include "assembly/ContactMultiplierBasis.hpp"

namespace signorini {
namespace {

using FEGraph = Tpetra::FECrsGraph<LocalOrdinal, GlobalOrdinal, Node>;
using FEMatrix = Tpetra::FECrsMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;

constexpr double kSolveTolerance = 1e-13;

// P M P + (I - P) for a 0/1 diagonal P: M on the selected rows and columns, identity on the rest.
class RestrictedOperator : public Operator {
 public:
  RestrictedOperator(const RCP<const CrsMatrix>& M, const RCP<const Vector>& selected)
      : M_(M), selected_(selected) {}
  RCP<const Map> getDomainMap() const override { return M_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return M_->getRangeMap(); }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             Scalar alpha = Teuchos::ScalarTraits<Scalar>::one(),
             Scalar beta = Teuchos::ScalarTraits<Scalar>::zero()) const override {
    MultiVector PX(X.getMap(), X.getNumVectors()), MPX(Y.getMap(), X.getNumVectors());
    for (std::size_t k = 0; k < X.getNumVectors(); ++k)
      PX.getVectorNonConst(k)->elementWiseMultiply(1.0, *selected_, *X.getVector(k), 0.0);
    M_->apply(PX, MPX, mode);
    for (std::size_t k = 0; k < X.getNumVectors(); ++k) {
      const RCP<Vector> column = MPX.getVectorNonConst(k);
      column->elementWiseMultiply(1.0, *selected_, *column, 0.0);  // P M P x
    }
    MPX.update(1.0, X, -1.0, PX, 1.0);                         // + (I - P) x
    Y.update(alpha, MPX, beta);
  }

 private:
  RCP<const CrsMatrix> M_;
  RCP<const Vector> selected_;
};

using Facets = std::vector<std::pair<long long, int>>;

// The constraints of the contact facets' nodes on this rank: the owned ones, then the
// ghosts' in ascending order (FECrsGraph wants the owned map as a prefix). Between bodies,
// the nodes that the master boundary does not cover have none.
std::vector<GlobalOrdinal> overlapConstraintRows(const LagrangeSpace& space, const Facets& facets,
                                                 const std::vector<long long>& constraintOfNode,
                                                 const Map& constraintMap, bool betweenBodies) {
  auto owned = constraintMap.getNodeElementList();
  std::vector<GlobalOrdinal> rows(owned.begin(), owned.end()), ghosts;
  for (const auto& [cell, facet] : facets)
    for (int a : space.basis().facetNodes(facet)) {
      const long long k = constraintOfNode[space.cellNodes(cell)[a]];
      if (k < 0 && betweenBodies) continue;
      if (k < 0) throw Error("contact pressure: a contact facet node has no constraint");
      if (!constraintMap.isNodeGlobalElement(k)) ghosts.push_back(k);
    }
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  rows.insert(rows.end(), ghosts.begin(), ghosts.end());
  return rows;
}

// The boundary mass matrix's graph: every pair of constrained nodes of a contact facet; an
// owned constraint with no facet on any rank (cannot happen for nodes of contact facets) keeps
// a diagonal. columns[i]: the sorted columns of overlap row i.
RCP<FEGraph> boundaryMassGraph(const LagrangeSpace& space, const Facets& facets, const std::vector<int>& overlapIndex,
                               const std::vector<GlobalOrdinal>& rows, const RCP<const Map>& constraintMap,
                               const RCP<const Map>& overlapMap, std::vector<std::vector<GlobalOrdinal>>& columns) {
  columns.assign(rows.size(), {});
  for (const auto& [cell, facet] : facets) {
    const auto nodes = space.basis().facetNodes(facet);
    for (int a : nodes)
      for (int b : nodes) {
        const int i = overlapIndex[space.cellNodes(cell)[a]], j = overlapIndex[space.cellNodes(cell)[b]];
        if (i >= 0 && j >= 0) columns[i].push_back(rows[j]);
      }
  }
  Kokkos::DualView<std::size_t*, FEGraph::device_type> counts("entries per row", rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto& c = columns[i];
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    counts.view_host()(i) = std::max<std::size_t>(c.size(), 1);
  }
  counts.modify_host();
  counts.sync_device();
  auto graph = rcp(new FEGraph(constraintMap, overlapMap, counts));
  graph->beginAssembly();
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (!columns[i].empty()) graph->insertGlobalIndices(rows[i], columns[i].size(), columns[i].data());
  for (std::size_t i = 0; i < constraintMap->getNodeNumElements(); ++i)
    if (columns[i].empty()) graph->insertGlobalIndices(rows[i], 1, &rows[i]);
  graph->endAssembly();
  return graph;
}

// The mass matrix of the contact facets' traces of the P_k basis, on graph; a unit diagonal
// for an owned row without facets.
RCP<CrsMatrix> boundaryMass(const DistributedSpace& ds, const Facets& facets, const std::vector<int>& overlapIndex,
                            const std::vector<GlobalOrdinal>& rows,
                            const std::vector<std::vector<GlobalOrdinal>>& columns, const RCP<FEGraph>& graph,
                            std::size_t numOwned) {
  const LagrangeSpace& space = ds.space();
  auto mass = rcp(new FEMatrix(graph));
  mass->beginAssembly();
  std::vector<double> coords((ds.dim() + 1) * ds.dim());
  FacetQuadrature rule;
  const int n = space.nodesPerCell();
  for (const auto& [cell, facet] : facets) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    facetQuadrature(space.basis(), coords.data(), facet, 2 * space.degree(), rule);
    const auto nodes = space.basis().facetNodes(facet);
    for (int a : nodes) {
      if (overlapIndex[space.cellNodes(cell)[a]] < 0) continue;  // no constraint
      const GlobalOrdinal row = rows[overlapIndex[space.cellNodes(cell)[a]]];
      for (int b : nodes) {
        if (overlapIndex[space.cellNodes(cell)[b]] < 0) continue;
        double value = 0;
        for (int q = 0; q < rule.size(); ++q) value += rule.weights[q] * rule.phi[q * n + a] * rule.phi[q * n + b];
        const GlobalOrdinal col = rows[overlapIndex[space.cellNodes(cell)[b]]];
        mass->sumIntoGlobalValues(row, 1, &value, &col);
      }
    }
  }
  const double one = 1.0;
  for (std::size_t i = 0; i < numOwned; ++i)
    if (columns[i].empty()) mass->sumIntoGlobalValues(rows[i], 1, &one, &rows[i]);
  mass->endAssembly();
  return mass;
}

// D^-1/2 for D the diagonal of M: symmetric Jacobi scaling, D^-1/2 M D^-1/2 has unit diagonal.
RCP<Vector> jacobiScaling(const CrsMatrix& M) {
  auto scaling = rcp(new Vector(M.getRowMap()));
  M.getLocalDiagCopy(*scaling);
  auto s = scaling->getDataNonConst();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(s.size()); ++i) {
    if (!(s[i] > 0)) throw Error("contact pressure: the boundary mass matrix has a non-positive diagonal");
    s[i] = 1.0 / std::sqrt(s[i]);
  }
  return scaling;
}

// Without contact there are no constraints; nodal is the trivial basis.
ContactFormulation formulationOf(const ProblemDefinition& problem, std::size_t pair) {
  return pair < problem.contacts.size() ? problem.contacts[pair].formulation : ContactFormulation::nodal;
}

}  // namespace

struct ContactPressure::MultiplierBasis : ContactMultiplierBasis {
  using ContactMultiplierBasis::ContactMultiplierBasis;
};

ContactPressure::ContactPressure(const FiniteElementSpace& feSpace, const ProblemDefinition& problem,
                                 const RCP<const Map>& constraintMap, std::size_t pair)
    : space_(feSpace),
      multipliers_(std::make_shared<MultiplierBasis>(distributedSpace(feSpace).space().basis(),
                                                     formulationOf(problem, pair))),
      weightedGap_(isWeightedGap(formulationOf(problem, pair))),
      betweenBodies_(pair < problem.contacts.size() && !problem.contacts[pair].masterBoundary.empty()),
      constraintMap_(constraintMap) {
  const DistributedSpace& ds = distributedSpace(feSpace);
  const LagrangeSpace& space = ds.space();
  if (pair < problem.contacts.size()) {
    facets_ = space.boundaryFacets(ds.mesh().tag(problem.contacts[pair].boundary));
    overlapNodeConstraint_ = overlapNodeConstraints(ds, problem, pair);
  } else {
    if (!problem.contacts.empty()) throw Error("contact pressure: the problem has no contact pair " + std::to_string(pair));
    overlapNodeConstraint_.assign(ds.overlapSpaceNodes().size(), -1);
  }
  // The pair's constraints: those of its owned nodes (owned nodes come first in the overlap).
  pairRows_ = rcp(new Vector(constraintMap));
  for (std::size_t i = 0; i < ds.ownedNodeMap()->getNodeNumElements(); ++i)
    if (overlapNodeConstraint_[i] >= 0) pairRows_->replaceGlobalValue(overlapNodeConstraint_[i], 1.0);
  const auto& overlapNodes = ds.overlapSpaceNodes();
  std::vector<long long> constraintOfNode(space.numNodes(), -1);
  for (std::size_t i = 0; i < overlapNodes.size(); ++i) constraintOfNode[overlapNodes[i]] = overlapNodeConstraint_[i];
  const std::vector<GlobalOrdinal> rows = overlapConstraintRows(space, facets_, constraintOfNode, *constraintMap, betweenBodies_);
  overlapMap_ = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                            Teuchos::ArrayView<const GlobalOrdinal>(rows), 0, constraintMap->getComm()));
  overlapIndex_.assign(space.numNodes(), -1);
  for (long long node = 0; node < space.numNodes(); ++node)
    if (constraintOfNode[node] >= 0 && overlapMap_->isNodeGlobalElement(constraintOfNode[node]))
      overlapIndex_[node] = overlapMap_->getLocalElement(constraintOfNode[node]);

  std::vector<std::vector<GlobalOrdinal>> columns;
  const RCP<FEGraph> graph = boundaryMassGraph(space, facets_, overlapIndex_, rows, constraintMap, overlapMap_, columns);
  mass_ = boundaryMass(ds, facets_, overlapIndex_, rows, columns, graph, constraintMap->getNodeNumElements());
  scaling_ = jacobiScaling(*mass_);
  lumpedWeights_ = contactNodeWeights(ds, problem, constraintMap, pair);
  scaledMass_ = rcp(new CrsMatrix(*mass_, Teuchos::Copy));
  scaledMass_->leftScale(*scaling_);
  scaledMass_->rightScale(*scaling_);
  patchSum_ = rcp(new CrsMatrix(*mass_, Teuchos::Copy));
  patchSum_->resumeFill();
  patchSum_->setAllToScalar(1.0);
  patchSum_->fillComplete(mass_->getDomainMap(), mass_->getRangeMap());
}

RCP<Vector> ContactPressure::nodalValues(const Vector& coefficients) const {
  auto values = rcp(new Vector(constraintMap_));
  // The dual basis's coefficients are the pressure's local means, shown as its nodal values
  // (the nodal values of sum_a c_a psi_a oscillate, psi_a being negative near other nodes).
  if (!multipliers_->transformed() || multipliers_->biorthogonal()) {
    values->assign(coefficients);
    return values;
  }
  // The value at node b of sum_a c_a psi_a is sum_a c_a T_ab, the same from every facet of b.
  const LagrangeSpace& space = distributedSpace(space_).space();
  const std::vector<double> c = overlapValues(coefficients);
  Vector here(overlapMap_);
  for (const auto& [cell, facet] : facets_) {
    const auto nodes = space.basis().facetNodes(facet);
    for (int b : nodes) {
      if (overlapIndex_[space.cellNodes(cell)[b]] < 0) continue;  // no constraint
      double value = 0;
      for (int a : nodes)
        if (overlapIndex_[space.cellNodes(cell)[a]] >= 0)
          value += c[overlapIndex_[space.cellNodes(cell)[a]]] * multipliers_->coefficient(facet, a, b);
      here.replaceLocalValue(overlapIndex_[space.cellNodes(cell)[b]], value);
    }
  }
  values->doExport(here, Export(overlapMap_, constraintMap_), Tpetra::REPLACE);
  return values;
}

RCP<Vector> ContactPressure::loadedNodes(const Vector& active) const {
  const LagrangeSpace& space = distributedSpace(space_).space();
  const std::vector<double> activeHere = overlapValues(active);
  Vector loadedHere(overlapMap_);
  for (const auto& [cell, facet] : facets_) {
    const auto nodes = space.basis().facetNodes(facet);
    bool loaded = false;
    for (int a : nodes) {
      const int i = overlapIndex_[space.cellNodes(cell)[a]];
      loaded = loaded || (i >= 0 && activeHere[i] != 0.0);
    }
    if (loaded)
      for (int a : nodes)
        if (overlapIndex_[space.cellNodes(cell)[a]] >= 0) loadedHere.replaceLocalValue(overlapIndex_[space.cellNodes(cell)[a]], 1.0);
  }
  auto loaded = rcp(new Vector(constraintMap_));
  loaded->doExport(loadedHere, Export(overlapMap_, constraintMap_), Tpetra::ADD);
  auto data = loaded->getDataNonConst();
  for (auto& x : data) x = x > 0 ? 1.0 : 0.0;
  return loaded;
}

int ContactPressure::dim() const { return space_.dim(); }

// The nodes of the contact facets, constrained or not (between bodies the master boundary
// may cover the contact boundary in part, and the rows move the nodes it leaves out too).
RCP<Vector> ContactPressure::contactBoundaryDofs() const {
  const DistributedSpace& ds = distributedSpace(space_);
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim();
  const auto& overlapNodes = ds.overlapSpaceNodes();
  std::vector<LocalOrdinal> overlapIndex(space.numNodes(), -1);
  for (std::size_t i = 0; i < overlapNodes.size(); ++i) overlapIndex[overlapNodes[i]] = static_cast<LocalOrdinal>(i);
  Vector here(ds.overlapDofMap());
  for (const auto& [cell, facet] : facets_)
    for (int a : space.basis().facetNodes(facet))
      for (int c = 0; c < dim; ++c) here.replaceLocalValue(dim * overlapIndex[space.cellNodes(cell)[a]] + c, 1.0);
  auto dofs = rcp(new Vector(ds.ownedDofMap()));
  dofs->doExport(here, Export(ds.overlapDofMap(), ds.ownedDofMap()), Tpetra::ADD);
  for (auto& x : dofs->getDataNonConst()) x = x > 0 ? 1.0 : 0.0;
  return dofs;
}

RCP<Vector> ContactPressure::pressure(const Vector& lambda, const Vector& active) const {
  const RCP<const Vector> loaded = loadedNodes(active);
  if (weightedGap_) {  // -lambda: the pressure's coefficients in the basis psi
    auto p = nodalValues(lambda);
    p->elementWiseMultiply(-1.0, *loaded, *p, 0.0);
    return p;
  }
  auto rhs = rcp(new Vector(constraintMap_));
  rhs->elementWiseMultiply(-1.0, *scaling_, lambda, 0.0);
  rhs->elementWiseMultiply(1.0, *loaded, *rhs, 0.0);
  auto q = rcp(new Vector(constraintMap_));
  if (rhs->normInf() > 0) {
    auto M = rcp(new RestrictedOperator(scaledMass_, loaded));
    const KrylovResult r = KrylovSolver().solve(M, Teuchos::null, rhs, q, kSolveTolerance, 1000);
    if (!r.converged)
      throw Error("contact pressure: CG on the boundary mass matrix stopped at relative residual " +
                  std::to_string(r.relativeResidual) + " after " + std::to_string(r.iterations) + " iterations");
  }
  q->elementWiseMultiply(1.0, *scaling_, *q, 0.0);
  return q;
}

RCP<Vector> ContactPressure::lumpedPressure(const Vector& lambda, const Vector& active) const {
  if (weightedGap_) return pressure(lambda, active);
  auto p = rcp(new Vector(constraintMap_));
  const RCP<const Vector> loaded = loadedNodes(active);
  auto out = p->getDataNonConst();
  auto l = lambda.getData(), w = lumpedWeights_->getData(), on = loaded->getData();
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < out.size(); ++i) out[i] = on[i] != 0 ? -l[i] / w[i] : 0.0;
  return p;
}

// P1 nodal forces oscillate from node to node in 3D, where boundary vertices differ in
// valence, and the patch average removes that; in 2D every boundary vertex has two facets and
// the lumped pressure is the better; HRZ weights do not suit P2/P3.
RCP<Vector> ContactPressure::recover(PressureRecovery how, const Vector& lambda, const Vector& active) const {
  if (how == PressureRecovery::Auto)
    how = space_.degree() > 1 ? PressureRecovery::Consistent
          : space_.dim() == 3 ? PressureRecovery::Patch
                              : PressureRecovery::Lumped;
  switch (how) {
    case PressureRecovery::Lumped:
      return lumpedPressure(lambda, active);
    case PressureRecovery::Patch:
      return patchPressure(lambda, active);
    default:
      return pressure(lambda, active);
  }
}

// The multipliers of the dual basis are nodal pressures, whose forces are their products with
// the integrals of psi: the same average applies, and removes the same oscillation.
RCP<Vector> ContactPressure::patchPressure(const Vector& lambda, const Vector& active) const {
  if (weightedGap_ && !multipliers_->biorthogonal()) return pressure(lambda, active);
  Vector force(constraintMap_), weight(constraintMap_), forceSum(constraintMap_), weightSum(constraintMap_);
  force.elementWiseMultiply(-1.0, active, lambda, 0.0);
  if (weightedGap_) force.elementWiseMultiply(1.0, force, *lumpedWeights_, 0.0);
  weight.elementWiseMultiply(1.0, active, *lumpedWeights_, 0.0);
  patchSum_->apply(force, forceSum);
  patchSum_->apply(weight, weightSum);
  auto p = rcp(new Vector(constraintMap_));
  auto out = p->getDataNonConst();
  auto a = active.getData();
  auto f = forceSum.getData();
  auto w = weightSum.getData();
  for (std::size_t i = 0; i < p->getLocalLength(); ++i) out[i] = a[i] != 0 && w[i] > 0 ? f[i] / w[i] : 0.0;
  return p;
}

std::vector<double> ContactPressure::overlapValues(const Vector& pressure) const {
  Vector overlap(overlapMap_);
  overlap.doImport(pressure, Import(constraintMap_, overlapMap_), Tpetra::INSERT);
  auto data = overlap.getData();
  return std::vector<double>(data.begin(), data.end());
}

template <class Visit>
void ContactPressure::forEachQuadraturePoint(const Vector& pressure, Visit&& visit) const {
  const DistributedSpace& ds = distributedSpace(space_);
  const LagrangeSpace& space = ds.space();
  const int dim = space_.dim(), n = space.nodesPerCell();
  const std::vector<double> values = overlapValues(pressure);
  std::vector<double> coords((dim + 1) * dim);
  FacetQuadrature rule;
  for (const auto& [cell, facet] : facets_) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    facetQuadrature(space.basis(), coords.data(), facet, 2 * space.degree() + 2, rule);
    const auto nodes = space.basis().facetNodes(facet);
    for (int q = 0; q < rule.size(); ++q) {
      double p = 0;
      for (int a : nodes)  // none where the node has no constraint
        if (overlapIndex_[space.cellNodes(cell)[a]] >= 0) p += rule.phi[q * n + a] * values[overlapIndex_[space.cellNodes(cell)[a]]];
      visit(&rule.points[q * dim], rule.weights[q], p);
    }
  }
}

std::vector<double> ContactPressure::overlapNodeValues(const Vector& values) const {
  const auto& overlapNodes = distributedSpace(space_).overlapSpaceNodes();
  std::vector<GlobalOrdinal> wanted;
  for (long long k : overlapNodeConstraint_)
    if (k >= 0) wanted.push_back(k);
  auto wantedMap = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                               Teuchos::ArrayView<const GlobalOrdinal>(wanted), 0, constraintMap_->getComm()));
  Vector here(wantedMap);
  here.doImport(values, Import(constraintMap_, wantedMap), Tpetra::INSERT);
  auto data = here.getData();
  std::vector<double> result(overlapNodes.size(), 0.0);
  std::size_t next = 0;
  for (std::size_t i = 0; i < overlapNodes.size(); ++i)
    if (overlapNodeConstraint_[i] >= 0) result[i] = data[next++];
  return result;
}

double ContactPressure::activeMeasure(const Vector& active) const { return lumpedWeights_->dot(active); }

ContactPressureSamples ContactPressure::samples(const Vector& pressure) const {
  ContactPressureSamples s;
  s.dim = space_.dim();
  forEachQuadraturePoint(pressure, [&](const double* x, double w, double p) {
    s.points.insert(s.points.end(), x, x + s.dim);
    s.weights.push_back(w);
    s.pressures.push_back(p);
  });
  return s;
}

}  // namespace signorini
