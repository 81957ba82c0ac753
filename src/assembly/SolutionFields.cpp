#include "assembly/SolutionFields.hpp"

#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/CellBodies.hpp"
#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "fe/ElasticityElement.hpp"

namespace signorini {
namespace {

// sigma: the dim x dim stress; in 2D the out-of-plane stress follows the material's plane
// strain or plane stress assumption.
double vonMises(const double* s, int dim, const IsotropicMaterial& material) {
  double sxx = s[0], syy, szz, sxy, syz = 0, szx = 0;
  if (dim == 2) {
    syy = s[3];
    sxy = s[1];
    szz = material.planeStrain ? material.poissonRatio * (sxx + syy) : 0.0;
  } else {
    syy = s[4];
    szz = s[8];
    sxy = s[1];
    syz = s[5];
    szx = s[2];
  }
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                   3.0 * (sxy * sxy + syz * syz + szx * szx));
}

// The von Mises stress at each local cell's centroid, u on the overlap DOF map.
std::vector<double> cellVonMises(const DistributedSpace& ds, const CellBodies& bodies, const Vector& u) {
  const int dim = ds.dim();
  const LagrangeSpace& space = ds.space();
  const auto& overlap = ds.overlapSpaceNodes();
  const int npc = space.nodesPerCell();
  std::vector<int> localIndex(space.numNodes(), -1);
  for (std::size_t i = 0; i < overlap.size(); ++i) localIndex[overlap[i]] = static_cast<int>(i);
  auto ud = u.getData();
  std::vector<double> coords((dim + 1) * dim), local(dim * npc), sigma(dim * dim), mises;
  double centroid[3];
  for (int i = 0; i < dim; ++i) centroid[i] = 1.0 / (dim + 1);
  for (long long cell = 0; cell < ds.mesh().numCells(); ++cell) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    const long long* nodes = space.cellNodes(cell);
    for (int i = 0; i < npc; ++i)
      for (int c = 0; c < dim; ++c) local[dim * i + c] = ud[dim * localIndex[nodes[i]] + c];
    const IsotropicMaterial& material = bodies.of(cell).material;
    cellStress(space.basis(), coords.data(), material, local.data(), centroid, sigma.data());
    mises.push_back(vonMises(sigma.data(), dim, material));
  }
  return mises;
}

// (d - A v)_j / integral psi_j at the overlap nodes of pair `pair`'s constraints, 0 elsewhere.
std::vector<double> weightedGaps(const DistributedSpace& ds, const ProblemDefinition& problem, std::size_t pair,
                                 const CrsMatrix& A, const Vector& d, const Vector& v) {
  Vector slack(A.getRangeMap());
  A.apply(v, slack);
  slack.update(1.0, d, -1.0);
  const RCP<const Vector> weights = contactNodeWeights(ds, problem, A.getRangeMap(), pair);
  auto sd = slack.getDataNonConst();
  auto wd = weights->getData();
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < sd.size(); ++i) sd[i] = wd[i] != 0 ? sd[i] / wd[i] : 0.0;
  const std::vector<long long> constraintOf = overlapNodeConstraints(ds, problem, pair);
  std::vector<GlobalOrdinal> ids;
  for (long long k : constraintOf)
    if (k >= 0) ids.push_back(k);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto here = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, ds.comm()));
  Vector slackHere(here);
  slackHere.doImport(slack, Import(A.getRangeMap(), here), Tpetra::INSERT);
  auto s = slackHere.getData();
  std::vector<double> gaps(constraintOf.size(), 0.0);
  for (std::size_t i = 0, next = 0; i < constraintOf.size(); ++i)
    if (constraintOf[i] >= 0) gaps[i] = s[next++];
  return gaps;
}

}  // namespace

SolutionFields solutionFields(const DistributedSpace& ds, const ProblemDefinition& problem, const CrsMatrix& A,
                              const Vector& d, const Vector& v, const Vector& lambda) {
  const int dim = ds.dim();
  const auto& overlap = ds.overlapSpaceNodes();
  const Import toOverlap(ds.ownedDofMap(), ds.overlapDofMap());
  Vector u(ds.overlapDofMap()), force(ds.ownedDofMap()), forceHere(ds.overlapDofMap());
  u.doImport(v, toOverlap, Tpetra::INSERT);
  A.apply(lambda, force, Teuchos::TRANS);
  forceHere.doImport(force, toOverlap, Tpetra::INSERT);

  SolutionFields fields;
  auto ud = u.getData();
  auto fd = forceHere.getData();
  fields.displacement.assign(ud.begin(), ud.end());
  // The pair of each node: the first whose contact (or master) boundary holds it; its obstacle
  // direction is the node's normal, and a rigid obstacle's gap function gives its gap.
  const auto& pairs = problem.contacts;
  std::vector<int> pairOf(ds.space().numNodes(), -1);
  for (std::size_t p = pairs.size(); p-- > 0;)
    for (const std::string& side : {pairs[p].boundary, pairs[p].masterBoundary})
      if (!side.empty())
        for (long long node : ds.boundaryNodes(ds.mesh().tag(side))) pairOf[node] = static_cast<int>(p);
  fields.gap.assign(overlap.size(), 0.0);
  for (std::size_t i = 0; i < overlap.size(); ++i) {
    const int p = pairOf[overlap[i]];
    const std::array<double, 3> n = p < 0 ? std::array<double, 3>{} : pairs[p].obstacleDirection;
    double normalForce = 0, normalDisplacement = 0;
    for (int c = 0; c < dim; ++c) {
      normalForce += fd[dim * i + c] * n[c];
      normalDisplacement += ud[dim * i + c] * n[c];
    }
    fields.normalContactForce.push_back(normalForce);
    const double* x = &ds.space().nodeCoordinates()[dim * overlap[i]];
    if (p >= 0 && pairs[p].masterBoundary.empty()) fields.gap[i] = pairs[p].gap(x, dim) + normalDisplacement;
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) {  // between bodies: from A and d
    if (pairs[p].masterBoundary.empty()) continue;
    const std::vector<double> gaps = weightedGaps(ds, problem, p, A, d, v);
    for (std::size_t i = 0; i < overlap.size(); ++i)
      if (pairOf[overlap[i]] == static_cast<int>(p)) fields.gap[i] = gaps[i];
  }
  fields.vonMisesStress = cellVonMises(ds, CellBodies(ds.mesh(), problem), u);
  return fields;
}

}  // namespace signorini
