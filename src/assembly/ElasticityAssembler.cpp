#include "assembly/ElasticityAssembler.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include <Kokkos_DualView.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/CellBodies.hpp"
#include "assembly/MeshPieces.hpp"
#include "assembly/MortarConstraints.hpp"
#include "assembly/OverlapStiffness.hpp"
#include "assembly/SummedRows.hpp"
#include "core/Collectives.hpp"
#include "fe/ElasticityElement.hpp"
#include "signorini/core/Error.hpp"

#include "assembly/ContactMultiplierBasis.hpp"

namespace signorini {
namespace {

using FEGraph = Tpetra::FECrsGraph<LocalOrdinal, GlobalOrdinal, Node>;
using FEMatrix = Tpetra::FECrsMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Export = Tpetra::Export<LocalOrdinal, GlobalOrdinal, Node>;

// Prescribed displacements, indexed by space DOF (dim * space node + component).
struct DirichletData {
  std::vector<char> fixed;
  std::vector<double> value;
};

DirichletData dirichletData(const DistributedSpace& ds, const ProblemDefinition& problem) {
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim();
  DirichletData data{std::vector<char>(dim * space.numNodes(), 0),
                     std::vector<double>(dim * space.numNodes(), 0.0)};
  for (const BoundaryField& bc : problem.dirichlet) {
    const int tag = ds.mesh().tag(bc.boundary);
    for (long long node : ds.boundaryNodes(tag)) {  // also the ghosts fixed by other ranks' facets
      const double* x = &space.nodeCoordinates()[dim * node];
      for (int c = 0; c < dim; ++c) {
        if (!bc.components[c]) continue;
        data.fixed[dim * node + c] = 1;
        data.value[dim * node + c] = (*bc.components[c])(x, dim);
      }
    }
  }
  return data;
}

// Local indices of each space DOF (dim * space node + component) in the stiffness matrix's
// rows and columns and in the overlap vector's map.
struct LocalIndices {
  std::vector<LocalOrdinal> row, column, entry;
};
// Without a matrix (K null), the vector's alone.
LocalIndices localIndices(const DistributedSpace& ds, const OverlapStiffness* K, const Vector& overlapVector) {
  const int dim = ds.dim();
  const std::size_t numDofs = dim * ds.space().numNodes();
  LocalIndices local{std::vector<LocalOrdinal>(K ? numDofs : 0), std::vector<LocalOrdinal>(K ? numDofs : 0),
                     std::vector<LocalOrdinal>(numDofs)};
  const Map& entries = *overlapVector.getMap();
  for (std::size_t i = 0; i < numDofs; ++i) {
    local.entry[i] = entries.getLocalElement(dim * ds.globalNode(i / dim) + i % dim);
    if (!K) continue;
    local.row[i] = K->row(i);
    local.column[i] = K->column(i);
  }
  return local;
}

// Symmetric elimination of prescribed DOFs inside one element: their known values move to
// the right-hand side of the free DOFs, their rows and columns are zeroed. The unit
// diagonal and the prescribed value are set once, by the owner, after assembly.
void eliminatePrescribed(const std::vector<char>& fixed, const std::vector<double>& value,
                         int n, std::vector<double>& Ke, std::vector<double>& Fe) {
  for (int j = 0; j < n; ++j) {
    if (!fixed[j]) continue;
    for (int i = 0; i < n; ++i) {
      if (!fixed[i]) Fe[i] -= Ke[i * n + j] * value[j];
    }
  }
  for (int j = 0; j < n; ++j) {
    if (!fixed[j]) continue;
    Fe[j] = 0.0;
    for (int i = 0; i < n; ++i) Ke[i * n + j] = Ke[j * n + i] = 0.0;
  }
}

// A contact node whose displacement in the obstacle direction is prescribed cannot move: its
// constraint is harmless while the prescribed displacement leaves the gap g + n_o . u_D open,
// and contradicts the prescription where it closes or crosses it (the multiplier would move
// a prescribed DOF). Those are refused, on every rank, with the first such node.
void checkPrescribedContactNodes(const DistributedSpace& ds, const ContactPair& pair, const DirichletData& dirichlet,
                                 const std::vector<long long>& contactNodes) {
  const int dim = ds.dim();
  long long closed = 0;
  GlobalOrdinal first = std::numeric_limits<GlobalOrdinal>::max();
  double where[4] = {0, 0, 0, 0};  // coordinates and gap of this rank's first closed node
  for (long long node : contactNodes) {
    bool prescribed = true;
    double normalDisplacement = 0;
    for (int c = 0; c < dim; ++c) {
      if (pair.obstacleDirection[c] == 0.0) continue;
      prescribed = prescribed && dirichlet.fixed[dim * node + c];
      normalDisplacement += pair.obstacleDirection[c] * dirichlet.value[dim * node + c];
    }
    const double* x = &ds.space().nodeCoordinates()[dim * node];
    const double gap = prescribed ? pair.gap(x, dim) + normalDisplacement : 1.0;
    if (!prescribed || gap > 0) continue;
    ++closed;
    if (ds.globalNode(node) < first) {
      first = ds.globalNode(node);
      std::copy(x, x + dim, where);
      where[3] = gap;
    }
  }
  const Comm& comm = *ds.comm();
  const long long total = sumOverRanks(comm, closed);
  if (total == 0) return;
  const GlobalOrdinal firstGlobal = minOverRanks(comm, first);
  double located[4] = {0, 0, 0, 0}, mine[4] = {0, 0, 0, 0};
  if (first == firstGlobal) std::copy(where, where + 4, mine);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 4, mine, located);
  std::ostringstream message;
  message << pair.path() << ": " << total << " node(s) of the contact boundary \"" << pair.boundary
          << "\" have their displacement towards the obstacle prescribed (Problem/Dirichlet) so that the gap "
          << "closes or is crossed, first at (";
  for (int c = 0; c < dim; ++c) message << (c ? ", " : "") << located[c];
  message << "), where g + n.u = " << located[3] << ": a prescribed node cannot also be held by the contact; "
          << "take these nodes out of one of the two boundaries, or prescribe a displacement that leaves the gap open";
  throw InputError(message.str());
}

struct ContactConstraints {
  RCP<CrsMatrix> A;
  RCP<Vector> d;
};

// Row first + i: -n_o . u(x) <= g(x) at the pair's i-th owned contact node x, only the
// nonzero components of n_o.
ContactConstraints nodalConstraints(const DistributedSpace& ds, const ContactPair& pair,
                                    const OwnedContactNodes& contact, std::size_t pairIndex,
                                    const RCP<const Map>& constraintMap) {
  const int dim = ds.dim();
  auto A = rcp(new CrsMatrix(constraintMap, dim));
  auto d = rcp(new Vector(constraintMap));
  auto dData = d->getDataNonConst();
  std::vector<GlobalOrdinal> cols(dim);
  std::vector<double> vals(dim);
  for (std::size_t i = contact.pairStart[pairIndex]; i < contact.pairStart[pairIndex + 1]; ++i) {
    const long long node = contact.nodes[i];
    int count = 0;
    for (int c = 0; c < dim; ++c)
      if (pair.obstacleDirection[c] != 0.0) {
        cols[count] = dim * ds.globalNode(node) + c;
        vals[count++] = -pair.obstacleDirection[c];
      }
    A->insertGlobalValues(contact.first + i, count, vals.data(), cols.data());
    dData[i] = pair.gap(&ds.space().nodeCoordinates()[dim * node], dim);
  }
  A->fillComplete(ds.ownedDofMap(), constraintMap);
  return {A, d};
}

// The graph of the weighted-gap rows: each contact node's row holds the DOFs, in the
// obstacle direction, of the nodes of the contact facets around it that its multiplier
// function couples to (all of them but for the dual basis). Rows: the owned
// constraints, then the others this rank's facets touch (FECrsGraph wants the owned rows
// as a prefix).
struct WeightedGapGraph {
  RCP<FEGraph> graph;
  RCP<const Map> overlapRows;
};
WeightedGapGraph weightedGapGraph(const DistributedSpace& ds, const ContactMultiplierBasis& psi,
                                  const std::vector<std::pair<long long, int>>& facets,
                                  const std::vector<long long>& constraintOf, const std::vector<int>& components,
                                  const RCP<const Map>& constraintMap) {
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim();
  auto owned = constraintMap->getNodeElementList();
  std::vector<GlobalOrdinal> rows(owned.begin(), owned.end()), ghosts;
  std::map<GlobalOrdinal, std::vector<GlobalOrdinal>> columns;
  for (const auto& [cell, facet] : facets) {
    const long long* nodes = space.cellNodes(cell);
    for (int a : space.basis().facetNodes(facet)) {
      const long long row = constraintOf[nodes[a]];
      if (row < 0) throw Error("weighted gap: a contact node has no constraint");
      if (!constraintMap->isNodeGlobalElement(row)) ghosts.push_back(row);
      auto& cols = columns[row];
      for (int b : space.basis().facetNodes(facet))
        if (psi.couples(facet, a, b))
          for (int c : components) cols.push_back(dim * ds.globalNode(nodes[b]) + c);
    }
  }
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  rows.insert(rows.end(), ghosts.begin(), ghosts.end());
  auto overlapRows = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                 Teuchos::ArrayView<const GlobalOrdinal>(rows), 0, constraintMap->getComm()));
  Kokkos::DualView<std::size_t*, FEGraph::device_type> counts("entries per row", rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto& cols = columns[rows[i]];
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    counts.view_host()(i) = cols.size();
  }
  counts.modify_host();
  counts.sync_device();
  auto graph = rcp(new FEGraph(constraintMap, overlapRows, counts, Teuchos::null, ds.ownedDofMap(), constraintMap));
  graph->beginAssembly();
  for (const auto& [row, cols] : columns) graph->insertGlobalIndices(row, cols.size(), cols.data());
  graph->endAssembly();
  return {graph, overlapRows};
}

// Row j, for the multiplier function psi_j of contact node j: the integral over Gamma_c of
// psi_j (-n_o . u) <= the integral of psi_j g. Each rank integrates its own contact facets
// (every global facet is on one rank) into the rows of their nodes, owned or not, and the
// sums go to the owners.
ContactConstraints weightedGapConstraints(const DistributedSpace& ds, const ProblemDefinition& problem,
                                          std::size_t pairIndex, const RCP<const Map>& constraintMap) {
  const LagrangeSpace& space = ds.space();
  const ContactPair& pair = problem.contacts[pairIndex];
  const ContactMultiplierBasis psi(space.basis(), pair.formulation);
  const int dim = ds.dim(), npc = space.nodesPerCell();
  const auto facets = space.boundaryFacets(ds.mesh().tag(pair.boundary));
  const std::vector<long long> overlapConstraint = overlapNodeConstraints(ds, problem, pairIndex);
  std::vector<long long> constraintOf(space.numNodes(), -1);
  for (std::size_t i = 0; i < overlapConstraint.size(); ++i)
    constraintOf[ds.overlapSpaceNodes()[i]] = overlapConstraint[i];
  std::vector<int> components;
  for (int c = 0; c < dim; ++c)
    if (pair.obstacleDirection[c] != 0.0) components.push_back(c);

  const WeightedGapGraph pattern = weightedGapGraph(ds, psi, facets, constraintOf, components, constraintMap);
  auto A = rcp(new FEMatrix(pattern.graph));
  Vector dOverlap(pattern.overlapRows);
  std::vector<double> coords((dim + 1) * dim), psiValues, gapValues;
  FacetQuadrature rule;
  const int degree = std::max(2 * space.degree(), problem.loadQuadratureDegree);
  A->beginAssembly();
  for (const auto& [cell, facet] : facets) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    facetQuadrature(space.basis(), coords.data(), facet, degree, rule);
    gapValues.resize(rule.size());
    for (int q = 0; q < rule.size(); ++q) gapValues[q] = pair.gap(&rule.points[q * dim], dim);
    const long long* nodes = space.cellNodes(cell);
    const std::vector<int> facetNodes = space.basis().facetNodes(facet);
    for (int a : facetNodes) {
      const GlobalOrdinal row = constraintOf[nodes[a]];
      psiValues.resize(rule.size());
      double gap = 0;
      for (int q = 0; q < rule.size(); ++q) {
        psiValues[q] = psi.value(facet, a, &rule.phi[q * npc]);
        gap += rule.weights[q] * psiValues[q] * gapValues[q];
      }
      dOverlap.sumIntoGlobalValue(row, gap);
      for (int b : facetNodes) {
        if (!psi.couples(facet, a, b)) continue;
        double weight = 0;  // integral of psi_a N_b
        for (int q = 0; q < rule.size(); ++q) weight += rule.weights[q] * psiValues[q] * rule.phi[q * npc + b];
        for (int c : components) {
          const GlobalOrdinal col = dim * ds.globalNode(nodes[b]) + c;
          const double value = -pair.obstacleDirection[c] * weight;
          A->sumIntoGlobalValues(row, 1, &value, &col);
        }
      }
    }
  }
  A->endAssembly();
  auto d = rcp(new Vector(constraintMap));
  d->doExport(dOverlap, Export(pattern.overlapRows, constraintMap), Tpetra::ADD);
  return {A, d};
}

}  // namespace

namespace {

// Whether each space node of this rank may carry a constraint of the pair: every node of its
// contact boundary against a rigid obstacle, the nodes that the master boundary covers
// against another body (refused if there are none).
std::vector<char> constrainableNodes(const DistributedSpace& ds, const ContactPair& pair) {
  std::vector<char> result(ds.space().numNodes(), pair.masterBoundary.empty());
  if (pair.masterBoundary.empty()) return result;
  const std::vector<char> covered = coveredSlaveNodes(ds, pair);
  for (std::size_t i = 0; i < covered.size(); ++i) result[ds.overlapSpaceNodes()[i]] = covered[i];
  if (maxOverRanks(*ds.comm(), static_cast<double>(std::count(covered.begin(), covered.end(), 1))) == 0)
    throw InputError(pair.path() + ": the master boundary \"" + pair.masterBoundary + "\" covers no node of the contact "
                     "boundary \"" + pair.boundary + "\": no facet of it faces the contact boundary");
  return result;
}

}  // namespace

// One constraint per contact node of each pair (against another body, per node that the master
// boundary covers), numbered pair after pair on each rank and in the order of the renumbered
// nodes within a pair. Ranks own contiguous node ranges in rank order, so a rank's constraints
// start after the contact nodes of the ranks before it.
OwnedContactNodes ownedContactNodes(const DistributedSpace& ds, const ProblemDefinition& problem) {
  OwnedContactNodes result;
  result.pairStart.push_back(0);
  for (const ContactPair& pair : problem.contacts) {
    const auto begin = result.nodes.size();
    const std::vector<char> constrainable = constrainableNodes(ds, pair);
    for (long long node : ds.boundaryNodes(ds.mesh().tag(pair.boundary)))
      if (ds.ownsNode(node) && constrainable[node]) result.nodes.push_back(node);
    std::sort(result.nodes.begin() + begin, result.nodes.end(),
              [&](long long a, long long b) { return ds.globalNode(a) < ds.globalNode(b); });
    result.pairStart.push_back(result.nodes.size());
  }
  const long long count = static_cast<long long>(result.nodes.size());
  long long upTo = 0;
  Teuchos::scan(*ds.comm(), Teuchos::REDUCE_SUM, 1, &count, &upTo);
  result.first = upTo - count;
  Teuchos::reduceAll(*ds.comm(), Teuchos::REDUCE_SUM, 1, &count, &result.numGlobal);
  return result;
}

std::vector<long long> overlapNodeConstraints(const DistributedSpace& ds, const ProblemDefinition& problem,
                                              std::size_t pair) {
  const OwnedContactNodes contact = ownedContactNodes(ds, problem);
  // Constraint + 1 at owned nodes, 0 elsewhere (ids are exact in a double below 2^53).
  Vector owned(ds.ownedNodeMap()), overlap(ds.overlapNodeMap());
  for (std::size_t k = contact.pairStart[pair]; k < contact.pairStart[pair + 1]; ++k)
    owned.replaceGlobalValue(ds.globalNode(contact.nodes[k]), static_cast<double>(contact.first + k + 1));
  overlap.doImport(owned, Import(ds.ownedNodeMap(), ds.overlapNodeMap()), Tpetra::INSERT);
  auto values = overlap.getData();
  std::vector<long long> constraint(values.size());
  for (std::size_t i = 0; i < constraint.size(); ++i) constraint[i] = static_cast<long long>(values[i]) - 1;
  return constraint;
}

namespace {

// The weights of one pair's contact nodes, on the owned node map.
RCP<Vector> ownedNodeWeights(const DistributedSpace& ds, const ContactPair& pair) {
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim(), npc = space.nodesPerCell();
  const bool weighted = isWeightedGap(pair.formulation);
  const ContactMultiplierBasis psi(space.basis(), pair.formulation);
  Vector overlap(ds.overlapNodeMap());
  auto owned = rcp(new Vector(ds.ownedNodeMap()));
  std::vector<double> coords((dim + 1) * dim), w;
  FacetQuadrature rule;
  for (const auto& [cell, facet] : space.boundaryFacets(ds.mesh().tag(pair.boundary))) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    if (weighted) {  // the integrals of psi
      facetQuadrature(space.basis(), coords.data(), facet, space.degree(), rule);
      w.assign(npc, 0.0);
      for (int a : space.basis().facetNodes(facet))
        for (int q = 0; q < rule.size(); ++q) w[a] += rule.weights[q] * psi.value(facet, a, &rule.phi[q * npc]);
    } else {
      facetLumpedMass(space.basis(), coords.data(), facet, w);
    }
    const long long* nodes = space.cellNodes(cell);
    for (int a = 0; a < npc; ++a)
      if (w[a] != 0.0) overlap.sumIntoGlobalValue(ds.globalNode(nodes[a]), w[a]);
  }
  owned->doExport(overlap, Export(ds.overlapNodeMap(), ds.ownedNodeMap()), Tpetra::ADD);
  return owned;
}

}  // namespace

RCP<Vector> contactNodeWeights(const DistributedSpace& ds, const ProblemDefinition& problem,
                               const RCP<const Map>& constraintMap, std::optional<std::size_t> onlyPair) {
  auto weights = rcp(new Vector(constraintMap));
  const OwnedContactNodes contact = ownedContactNodes(ds, problem);
  if (static_cast<long long>(constraintMap->getNodeNumElements()) != static_cast<long long>(contact.nodes.size()) ||
      (!contact.nodes.empty() && constraintMap->getMinGlobalIndex() != contact.first))
    throw Error("contact weights: the constraint map is not distributed like the contact nodes");
  // Constraint first + k belongs to the k-th owned contact node.
  for (std::size_t p = 0; p < problem.contacts.size(); ++p) {
    if (onlyPair && *onlyPair != p) continue;
    RCP<const Vector> pairWeights;
    if (problem.contacts[p].masterBoundary.empty()) {
      pairWeights = ownedNodeWeights(ds, problem.contacts[p]);
    } else {  // over the part that the master boundary covers, on the pair's rows
      const auto constraintOf = overlapNodeConstraints(ds, problem, p);
      pairWeights = mortarConstraints(ds, problem.contacts[p], constraintOf, constraintMap).weights;
    }
    auto in = pairWeights->getData();
    auto out = weights->getDataNonConst();
    for (std::size_t k = contact.pairStart[p]; k < contact.pairStart[p + 1]; ++k) {
      const LocalOrdinal row = constraintMap->getLocalElement(contact.first + k);
      out[row] = problem.contacts[p].masterBoundary.empty()
                     ? in[ds.ownedNodeMap()->getLocalElement(ds.globalNode(contact.nodes[k]))]
                     : in[row];
    }
  }
  return weights;
}

RCP<MatrixFreeElasticityOperator> matrixFreeStiffness(const std::shared_ptr<const DistributedSpace>& ds,
                                                      const ProblemDefinition& problem) {
  return rcp(new MatrixFreeElasticityOperator(ds, CellBodies(ds->mesh(), problem), dirichletData(*ds, problem).fixed));
}

RCP<CrsMatrix> assembleGridStiffness(const DistributedSpace& ds, const ProblemDefinition& problem,
                                     const GeometricGrid& grid) {
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim(), n = dim * (dim + 1);
  const std::vector<char> fixed = dirichletData(ds, problem).fixed;
  const CellBodies bodies(ds.mesh(), problem);
  // The grid's cells in each mesh cell, as local nodes: the cell itself, or its split at the
  // nodes. Their nodes are the grid's vertices.
  const LagrangeBasis linear(dim, 1);
  const std::vector<std::array<int, 4>> pieces =
      grid.refinesFineCells() ? space.basis().subSimplices() : linear.subSimplices();
  const long long numVertexNodes = grid.refinesFineCells() ? space.numNodes() : ds.mesh().numVertices();
  std::vector<long long> gridVertex(numVertexNodes);
  const MeshPieces& apart = meshPieces(ds);  // bodies meshed apart may have nodes at one place
  for (long long v = 0; v < numVertexNodes; ++v) {
    const double* x = &space.nodeCoordinates()[dim * v];
    gridVertex[v] = apart.count > 1 ? grid.vertexOfBodyAt(x, apart.ofSpaceNode[v]) : grid.vertexAt(x);
    if (gridVertex[v] < 0) throw Error("assembleGridStiffness: a mesh node is not a vertex of " + grid.description());
  }
  std::vector<GlobalOrdinal> rowIds(dim * numVertexNodes);
  for (std::size_t i = 0; i < rowIds.size(); ++i) rowIds[i] = dim * gridVertex[i / dim] + i % dim;
  SummedRows rows(std::move(rowIds));
  std::vector<double> vertexCoords((dim + 1) * dim), Ke;
  long long vertices[4];
  const auto dof = [&](int a) { return dim * vertices[a / dim] + a % dim; };
  for (long long cell = 0; cell < ds.mesh().numCells(); ++cell)
    for (const auto& piece : pieces) {
      for (int v = 0; v <= dim; ++v) {
        vertices[v] = space.cellNodes(cell)[piece[v]];
        std::copy_n(&space.nodeCoordinates()[dim * vertices[v]], dim, &vertexCoords[dim * v]);
      }
      elasticityStiffness(linear, vertexCoords.data(), bodies.of(cell).material, Ke);
      for (int a = 0; a < n; ++a) {
        if (fixed[dof(a)]) continue;
        for (int b = 0; b < n; ++b)
          if (!fixed[dof(b)]) rows.add(dof(a), dim * gridVertex[vertices[b / dim]] + b % dim, Ke[a * n + b]);
      }
    }
  for (long long v = 0; v < numVertexNodes; ++v)
    for (int c = 0; c < dim; ++c)
      if (ds.ownsNode(v) && fixed[dim * v + c]) rows.add(dim * v + c, dim * gridVertex[v] + c, 1.0);
  return rows.onOwners(ds.comm());
}

namespace {

// One cell's local DOFs as the element routines see them: vertex coordinates, and per DOF
// (dim * local node + component) its overlap row, column and load entry, and its Dirichlet
// data. Looked up once per DOF (localIndices), not for each of the (dim * npc)^2 entries.
class CellDofs {
 public:
  CellDofs(const DistributedSpace& ds, const DirichletData& dirichlet, const LocalIndices& local, bool withMatrix)
      : ds_(ds), dirichlet_(dirichlet), local_(local), withMatrix_(withMatrix) {
    const int n = ds.dim() * ds.space().nodesPerCell();
    vertexCoords.resize((ds.dim() + 1) * ds.dim());
    rows.resize(n);
    cols.resize(n);
    entries.resize(n);
    fixed.resize(n);
    value.resize(n);
  }
  void gather(long long cell) {
    const int dim = ds_.dim();
    ds_.mesh().cellVertexCoordinates(cell, vertexCoords.data());
    const long long* nodes = ds_.space().cellNodes(cell);
    for (int i = 0; i < ds_.space().nodesPerCell(); ++i)
      for (int c = 0; c < dim; ++c) {
        const long long spaceDof = dim * nodes[i] + c;
        if (withMatrix_) {
          rows[dim * i + c] = local_.row[spaceDof];
          cols[dim * i + c] = local_.column[spaceDof];
        }
        entries[dim * i + c] = local_.entry[spaceDof];
        fixed[dim * i + c] = dirichlet_.fixed[spaceDof];
        value[dim * i + c] = dirichlet_.value[spaceDof];
      }
  }

  std::vector<double> vertexCoords, value;
  std::vector<LocalOrdinal> rows, cols, entries;
  std::vector<char> fixed;

 private:
  const DistributedSpace& ds_;
  const DirichletData& dirichlet_;
  const LocalIndices& local_;
  const bool withMatrix_;
};

// Element stiffness (into K if given) and body force load (into bOverlap) of every local
// cell, prescribed DOFs eliminated symmetrically.
void assembleCells(const DistributedSpace& ds, const ProblemDefinition& problem, CellDofs& cell,
                   OverlapStiffness* K, Vector& bOverlap) {
  const int dim = ds.dim(), npc = ds.space().nodesPerCell(), n = dim * npc;
  const CellBodies bodies(ds.mesh(), problem);
  // Expressions are evaluated at every quadrature point of every cell: skip the zero ones.
  std::vector<std::vector<char>> zeroForce(bodies.numBodies(), std::vector<char>(dim));
  for (int b = 0; b < bodies.numBodies(); ++b)
    for (int c = 0; c < dim; ++c) zeroForce[b][c] = bodies.body(b).bodyForce[c].isConstantZero();
  int body = 0;  // of the cell being assembled
  const auto force = [&](int count, const double* x, double* f) {
    for (int c = 0; c < dim; ++c)
      if (!zeroForce[body][c]) bodies.body(body).bodyForce[c].evaluate(count, x, dim, f + c * count);
  };
  std::vector<double> Ke, Fe;
  auto bData = bOverlap.getDataNonConst();
  for (long long c = 0; c < ds.mesh().numCells(); ++c) {
    cell.gather(c);
    body = bodies.indexOf(c);
    elasticityStiffness(ds.space().basis(), cell.vertexCoords.data(), bodies.body(body).material, Ke);
    bodyForceLoad(ds.space().basis(), cell.vertexCoords.data(), force, problem.loadQuadratureDegree, Fe);
    eliminatePrescribed(cell.fixed, cell.value, n, Ke, Fe);
    if (K) K->addElementMatrix(dim, npc, cell.rows.data(), cell.cols.data(), Ke.data());
    for (int i = 0; i < n; ++i) bData[cell.entries[i]] += Fe[i];
  }
}

// The tractions' loads on the free DOFs of their boundaries' facets, into bOverlap.
void addTractions(const DistributedSpace& ds, const ProblemDefinition& problem, CellDofs& cell, Vector& bOverlap) {
  const int dim = ds.dim(), n = dim * ds.space().nodesPerCell();
  std::vector<double> Fe;
  auto bData = bOverlap.getDataNonConst();
  for (const BoundaryField& bc : problem.traction) {
    const auto traction = [&](int count, const double* x, double* t) {
      for (int c = 0; c < dim; ++c)
        if (bc.components[c]) bc.components[c]->evaluate(count, x, dim, t + c * count);
    };
    for (const auto& [c, facet] : ds.space().boundaryFacets(ds.mesh().tag(bc.boundary))) {
      cell.gather(c);
      facetTractionLoad(ds.space().basis(), cell.vertexCoords.data(), facet, traction, problem.loadQuadratureDegree,
                        Fe);
      for (int i = 0; i < n; ++i)
        if (!cell.fixed[i]) bData[cell.entries[i]] += Fe[i];
    }
  }
}

// The owners' part of the elimination: a unit diagonal in K and the prescribed value in b
// for each prescribed DOF; b summed from bOverlap onto the owned DOFs first.
RCP<Vector> prescribeOnOwners(const DistributedSpace& ds, const DirichletData& dirichlet, OverlapStiffness* K,
                              const Vector& bOverlap) {
  const int dim = ds.dim();
  const auto& overlap = ds.overlapSpaceNodes();
  const std::size_t numOwned = ds.ownedNodeMap()->getNodeNumElements();
  auto b = rcp(new Vector(ds.ownedDofMap()));
  b->doExport(bOverlap, Export(ds.overlapDofMap(), ds.ownedDofMap()), Tpetra::ADD);
  auto data = b->getDataNonConst();
  for (std::size_t i = 0; i < numOwned; ++i)
    for (int c = 0; c < dim; ++c) {
      const long long spaceDof = dim * overlap[i] + c;
      if (!dirichlet.fixed[spaceDof]) continue;
      if (K) K->add(K->row(spaceDof), K->column(spaceDof), 1.0);
      data[dim * i + c] = dirichlet.value[spaceDof];
    }
  return b;
}

// The rows of several pairs' constraints, each on the whole constraint map with only its own
// rows filled, in one matrix and one vector.
ContactConstraints stackedRows(const std::vector<ContactConstraints>& pairs, const DistributedSpace& ds,
                               const RCP<const Map>& constraintMap) {
  std::size_t widest = 0;
  for (const ContactConstraints& pair : pairs) widest = std::max(widest, pair.A->getNodeMaxNumRowEntries());
  ContactConstraints all{rcp(new CrsMatrix(constraintMap, widest)), rcp(new Vector(constraintMap))};
  std::vector<GlobalOrdinal> cols(widest);
  std::vector<double> vals(widest);
  for (const ContactConstraints& pair : pairs) {
    all.d->update(1.0, *pair.d, 1.0);
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(constraintMap->getNodeNumElements()); ++i) {
      const GlobalOrdinal row = constraintMap->getGlobalElement(i);
      std::size_t count = 0;
      pair.A->getGlobalRowCopy(row, cols, vals, count);
      if (count > 0) all.A->insertGlobalValues(row, count, vals.data(), cols.data());
    }
  }
  all.A->fillComplete(ds.ownedDofMap(), constraintMap);
  return all;
}

// One pair's constraints, one per contact node, in the formulation it asks for, against the
// rigid obstacle (contact nodes whose displacement towards it is prescribed into contact are
// refused) or the master boundary of another body.
ContactConstraints pairConstraints(const DistributedSpace& ds, const ProblemDefinition& problem, std::size_t p,
                                   const DirichletData& dirichlet, const OwnedContactNodes& contact,
                                   const RCP<const Map>& constraintMap) {
  const ContactPair& pair = problem.contacts[p];
  if (!pair.masterBoundary.empty()) {
    const MortarRows rows = mortarConstraints(ds, pair, overlapNodeConstraints(ds, problem, p), constraintMap);
    return {rows.A, rows.d};
  }
  checkPrescribedContactNodes(
      ds, pair, dirichlet,
      std::vector<long long>(contact.nodes.begin() + contact.pairStart[p], contact.nodes.begin() + contact.pairStart[p + 1]));
  return isWeightedGap(pair.formulation) ? weightedGapConstraints(ds, problem, p, constraintMap)
                                         : nodalConstraints(ds, pair, contact, p, constraintMap);
}

// Every pair's constraints, pair after pair on each rank (ownedContactNodes).
ContactConstraints contactConstraints(const DistributedSpace& ds, const ProblemDefinition& problem,
                                      const DirichletData& dirichlet) {
  const OwnedContactNodes contact = ownedContactNodes(ds, problem);
  std::vector<GlobalOrdinal> ownedConstraints(contact.nodes.size());
  for (std::size_t k = 0; k < ownedConstraints.size(); ++k) ownedConstraints[k] = contact.first + k;
  auto constraintMap = rcp(new Map(contact.numGlobal, Teuchos::ArrayView<const GlobalOrdinal>(ownedConstraints),
                                   0, ds.comm()));
  if (problem.contacts.empty()) {  // no rows
    auto A = rcp(new CrsMatrix(constraintMap, 0));
    A->fillComplete(ds.ownedDofMap(), constraintMap);
    return {A, rcp(new Vector(constraintMap))};
  }
  std::vector<ContactConstraints> pairs;
  for (std::size_t p = 0; p < problem.contacts.size(); ++p)
    pairs.push_back(pairConstraints(ds, problem, p, dirichlet, contact, constraintMap));
  return pairs.size() == 1 ? pairs.front() : stackedRows(pairs, ds, constraintMap);
}

RCP<MultiVector> ownedNodeCoordinates(const DistributedSpace& ds) {
  const int dim = ds.dim();
  const auto& overlap = ds.overlapSpaceNodes();
  auto coordinates = rcp(new MultiVector(ds.ownedNodeMap(), dim));
  for (int c = 0; c < dim; ++c) {
    auto data = coordinates->getDataNonConst(c);
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(data.size()); ++i) data[i] = ds.space().nodeCoordinates()[dim * overlap[i] + c];
  }
  return coordinates;
}

}  // namespace

// Stiffness and loads cell by cell on the overlap, tractions on their facets, the owners'
// Dirichlet rows, then the contact constraints.
ContactQP assembleContactQP(const DistributedSpace& ds, const ProblemDefinition& problem, bool assembleStiffness) {
  const int dim = ds.dim();
  const DirichletData dirichlet = dirichletData(ds, problem);
  for (const Body& body : problem.bodies)
    if (body.bodyForce.size() != static_cast<std::size_t>(dim))
      throw InputError("Problem/Bodies/" + body.name + ": the body force needs " + std::to_string(dim) + " components");
  if (problem.body.bodyForce.size() != static_cast<std::size_t>(dim))
    throw InputError("Problem: the body force needs " + std::to_string(dim) + " components");

  std::optional<OverlapStiffness> K;
  if (assembleStiffness) K.emplace(ds);
  Vector bOverlap(ds.overlapDofMap());
  const LocalIndices local = localIndices(ds, K ? &*K : nullptr, bOverlap);
  CellDofs cell(ds, dirichlet, local, K.has_value());
  assembleCells(ds, problem, cell, K ? &*K : nullptr, bOverlap);
  addTractions(ds, problem, cell, bOverlap);

  ContactQP qp;
  qp.b = prescribeOnOwners(ds, dirichlet, K ? &*K : nullptr, bOverlap);
  if (K) qp.Q = K->sumOnOwners();
  const ContactConstraints constraints = contactConstraints(ds, problem, dirichlet);
  qp.A = constraints.A;
  qp.d = constraints.d;
  return qp;
}

MultigridInput meshMultigridInput(const DistributedSpace& ds) {
  MultigridInput multigrid;
  multigrid.blockSize = ds.dim();
  multigrid.coordinates = ownedNodeCoordinates(ds);
  const MeshPieces& pieces = meshPieces(ds);  // bodies meshed apart: the rigid body check takes each
  if (pieces.count > 1) multigrid.nodeBodies = pieces.ofOwnedNode;
  return multigrid;
}

}  // namespace signorini
