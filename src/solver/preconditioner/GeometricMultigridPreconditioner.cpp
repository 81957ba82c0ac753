#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Ifpack2_Chebyshev.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <TpetraExt_TripleMatrixMultiply.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>
#include <boost/sort/spreadsort/integer_sort.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/GeometricGrid.hpp"
#include "solver/preconditioner/ChebyshevSmoother.hpp"
#include "solver/preconditioner/GatheredDirectSolver.hpp"
#include "solver/preconditioner/JacobiEigenvalueEstimate.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"
#include "solver/preconditioner/RigidBodyModes.hpp"

namespace signorini {

using RowMatrix = Tpetra::RowMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Chebyshev = Ifpack2::Chebyshev<RowMatrix>;

struct GeometricMultigridPreconditioner::Level {
  RCP<const Map> dofMap;
  std::vector<double> coordinates;  // dim per owned node, in DOF map order
  std::vector<char> dirichlet;      // per owned DOF
  std::vector<int> bodies;          // per owned node: its body (MultigridInput::nodeBodies); empty: one
  RCP<CrsMatrix> A;                 // null on a fine level given as an operator
  RCP<const Operator> op;           // A, or the fine operator
  RCP<Operator> smoother;           // Ifpack2's Chebyshev of A, or a ChebyshevSmoother of op
  JacobiEigenvalueEstimate eigenvalue;  // of the smoother, kept across builds
  // From the next coarser level to this one; its transpose restricts by apply(TRANS), a local
  // transposed product and an export, as fast as an explicit R and without building one.
  RCP<CrsMatrix> P;
};

namespace {

// The coarse level's DOF map: the coarse vertices this rank owns, those at one of its fine
// nodes (atVertex: each fine node's coarse vertex, or -1), with their coordinates, Dirichlet
// flags and bodies (those of the fine nodes at them; none if the fine nodes have none).
// Collective.
RCP<const Map> coarseLevelMap(const GeometricGrid& coarse, int blockSize, const RCP<const Comm>& comm,
                              const std::vector<double>& fineCoordinates, const std::vector<char>& fineDirichlet,
                              const std::vector<int>& fineBodies, std::vector<long long>& atVertex,
                              std::vector<double>& coarseCoordinates, std::vector<char>& coarseDirichlet,
                              std::vector<int>& coarseBodies) {
  const int dim = coarse.dimension();
  const std::size_t numFine = fineCoordinates.size() / dim;
  std::vector<std::pair<long long, std::size_t>> owned;  // (coarse vertex, fine node)
  atVertex.assign(numFine, -1);
  for (std::size_t i = 0; i < numFine; ++i) {
    const double* x = &fineCoordinates[dim * i];
    atVertex[i] = coarse.vertexOfBodyAt(x, fineBodies.empty() ? -1 : fineBodies[i]);
    if (atVertex[i] >= 0) owned.emplace_back(atVertex[i], i);
  }
  std::sort(owned.begin(), owned.end());
  std::vector<GlobalOrdinal> dofs;
  dofs.reserve(blockSize * owned.size());
  coarseCoordinates.assign(dim * owned.size(), 0.0);
  coarseDirichlet.assign(blockSize * owned.size(), 0);
  coarseBodies.clear();
  for (std::size_t k = 0; k < owned.size(); ++k) {
    if (!fineBodies.empty()) coarseBodies.push_back(fineBodies[owned[k].second]);
    coarse.vertexCoordinates(owned[k].first, &coarseCoordinates[dim * k]);
    for (int c = 0; c < blockSize; ++c) {
      dofs.push_back(blockSize * owned[k].first + c);
      coarseDirichlet[blockSize * k + c] = fineDirichlet[blockSize * owned[k].second + c];
    }
  }
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto coarseMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(dofs), 0, comm));
  if (coarseMap->getGlobalNumElements() != static_cast<Tpetra::global_size_t>(blockSize * coarse.numVertices()))
    throw InputError("geometric multigrid: the mesh's nodes are not the vertices of a refinement of the " +
                     coarse.description() + "; use Preconditioner/hierarchy \"algebraic\"");
  return coarseMap;
}

// Each fine node's simplex in the columns of P: the positions of its coarse vertices in
// `usedVertices` (sorted), ascending, with their weights, those above 1e-12 only; and the
// position of the coarse vertex at the node (-1: none).
struct NodeSimplices {
  std::vector<std::size_t> first;  // node i's entries: first[i] .. first[i + 1]
  std::vector<LocalOrdinal> position;
  std::vector<double> weight;
  std::vector<LocalOrdinal> injection;

  NodeSimplices(const std::vector<long long>& usedVertices, const std::vector<long long>& atVertex,
                const std::vector<long long>& vertices, const std::vector<double>& weights, int dim)
      : first(atVertex.size() + 1, 0), injection(atVertex.size(), -1) {
    const auto positionOf = [&](long long v) {
      return static_cast<LocalOrdinal>(std::lower_bound(usedVertices.begin(), usedVertices.end(), v) -
                                       usedVertices.begin());
    };
    position.reserve(vertices.size());
    weight.reserve(vertices.size());
    std::vector<std::pair<LocalOrdinal, double>> simplex;
    for (std::size_t i = 0; i < atVertex.size(); ++i) {
      simplex.clear();
      for (int k = 0; k <= dim; ++k)
        if (weights[(dim + 1) * i + k] > 1e-12)
          simplex.emplace_back(positionOf(vertices[(dim + 1) * i + k]), weights[(dim + 1) * i + k]);
      std::sort(simplex.begin(), simplex.end());
      for (const auto& [at, w] : simplex) {
        position.push_back(at);
        weight.push_back(w);
      }
      first[i + 1] = position.size();
      if (atVertex[i] >= 0) injection[i] = positionOf(atVertex[i]);
    }
  }
};

// P1 interpolation from the grid `coarse` to the owned fine nodes; fills the coarse level's
// DOF map (the coarse vertices at this rank's fine nodes), coordinates, Dirichlet flags and
// bodies. Collective.
RCP<CrsMatrix> interpolation(const GeometricGrid& coarse, int blockSize, const RCP<const Map>& fineMap,
                             const std::vector<double>& fineCoordinates, const std::vector<char>& fineDirichlet,
                             const std::vector<int>& fineBodies, RCP<const Map>& coarseMap,
                             std::vector<double>& coarseCoordinates, std::vector<char>& coarseDirichlet,
                             std::vector<int>& coarseBodies) {
  const int dim = coarse.dimension();
  const std::size_t numFine = fineCoordinates.size() / dim;
  const auto comm = fineMap->getComm();
  std::vector<long long> atVertex;
  coarseMap = coarseLevelMap(coarse, blockSize, comm, fineCoordinates, fineDirichlet, fineBodies, atVertex,
                             coarseCoordinates, coarseDirichlet, coarseBodies);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();

  // Every fine node's simplex and weights; the Dirichlet flags of the coarse DOFs they use.
  std::vector<long long> vertices(numFine * (dim + 1));
  std::vector<double> weights(numFine * (dim + 1));
  for (std::size_t i = 0; i < numFine; ++i)
    coarse.interpolationInBody(&fineCoordinates[dim * i], fineBodies.empty() ? -1 : fineBodies[i],
                               &vertices[(dim + 1) * i], &weights[(dim + 1) * i]);
  std::vector<long long> usedVertices(vertices);
  for (long long v : atVertex)
    if (v >= 0) usedVertices.push_back(v);
  boost::sort::spreadsort::integer_sort(usedVertices.begin(), usedVertices.end());
  usedVertices.erase(std::unique(usedVertices.begin(), usedVertices.end()), usedVertices.end());
  std::vector<GlobalOrdinal> used;  // P's column map: all components of the used vertices, sorted
  used.reserve(blockSize * usedVertices.size());
  for (long long v : usedVertices)
    for (int c = 0; c < blockSize; ++c) used.push_back(blockSize * v + c);
  auto usedMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(used), 0, comm));
  const auto toUsed = rcp(new Import(coarseMap, usedMap));
  Vector flags(coarseMap), usedFlags(usedMap);
  {
    auto f = flags.getDataNonConst();
    for (std::size_t k = 0; k < coarseDirichlet.size(); ++k) f[k] = coarseDirichlet[k];
  }
  usedFlags.doImport(flags, *toUsed, Tpetra::INSERT);
  auto usedData = usedFlags.getData();
  const NodeSimplices simplices(usedVertices, atVertex, vertices, weights, dim);

  // P's rows in local CSR form, straight into the arrays Tpetra keeps; the import above is
  // its column import. Component c of a row's node takes component c of its coarse vertices,
  // but for the coarse DOFs that are Dirichlet; a Dirichlet fine DOF injects its coarse one.
  const std::size_t numFineDofs = fineMap->getNodeNumElements();
  const auto forEachEntry = [&](std::size_t r, auto&& entry) {
    const std::size_t i = r / blockSize;
    const int c = static_cast<int>(r % blockSize);
    if (fineDirichlet[r]) {
      if (simplices.injection[i] >= 0) entry(blockSize * simplices.injection[i] + c, 1.0);
      return;
    }
    for (std::size_t k = simplices.first[i]; k < simplices.first[i + 1]; ++k) {
      const LocalOrdinal col = blockSize * simplices.position[k] + c;
      if (usedData[col] == 0.0) entry(col, simplices.weight[k]);
    }
  };
  using Graph = CrsMatrix::local_graph_device_type;
  typename Graph::row_map_type::non_const_type rowPointers("P row pointers", numFineDofs + 1);
  for (std::size_t r = 0; r < numFineDofs; ++r) {
    std::size_t count = 0;
    forEachEntry(r, [&](LocalOrdinal, double) { ++count; });
    rowPointers(r + 1) = rowPointers(r) + count;
  }
  typename Graph::entries_type::non_const_type columns("P columns", rowPointers(numFineDofs));
  typename CrsMatrix::local_matrix_device_type::values_type values("P values", rowPointers(numFineDofs));
  for (std::size_t r = 0; r < numFineDofs; ++r) {
    std::size_t e = rowPointers(r);
    forEachEntry(r, [&](LocalOrdinal col, double w) {
      columns(e) = col;
      values(e++) = w;
    });
  }
  auto P = rcp(new CrsMatrix(fineMap, usedMap, rowPointers, columns, values));
  P->expertStaticFillComplete(coarseMap, fineMap, toUsed);
  return P;
}

}  // namespace

namespace {

// The entries of `next` that differ from `previous`, as a matrix holding only them, when the
// two share one graph (BarrierHessianOperator assembles every H on Q's): between Newton
// steps only A^T D A on the contact DOFs changes. Null, on every rank, otherwise. Collective.
RCP<CrsMatrix> changedEntries(const CrsMatrix& previous, const CrsMatrix& next) {
  if (!onEveryRank(*next.getComm(), previous.getCrsGraph() == next.getCrsGraph())) return Teuchos::null;
  const auto before = previous.getLocalMatrixHost(), after = next.getLocalMatrixHost();
  const LocalOrdinal rows = static_cast<LocalOrdinal>(after.numRows());
  Teuchos::Array<std::size_t> counts(rows, 0);  // Tpetra 13.2 matrices cannot grow past these
  for (LocalOrdinal row = 0; row < rows; ++row)
    for (auto e = after.graph.row_map(row); e < after.graph.row_map(row + 1); ++e)
      counts[row] += after.values(e) != before.values(e);
  auto change = rcp(new CrsMatrix(next.getRowMap(), counts()));
  std::vector<GlobalOrdinal> columns;
  std::vector<double> values;
  for (LocalOrdinal row = 0; row < rows; ++row) {
    columns.clear();
    values.clear();
    for (auto e = after.graph.row_map(row); e < after.graph.row_map(row + 1); ++e)
      if (after.values(e) != before.values(e)) {
        columns.push_back(next.getColMap()->getGlobalElement(after.graph.entries(e)));
        values.push_back(after.values(e) - before.values(e));
      }
    if (!columns.empty())
      change->insertGlobalValues(next.getRowMap()->getGlobalElement(row),
                                 Teuchos::ArrayView<const GlobalOrdinal>(columns),
                                 Teuchos::ArrayView<const double>(values));
  }
  change->fillComplete(next.getDomainMap(), next.getRangeMap());
  return change;
}

// P^T C P for a change C with few nonzero rows, from the rows of P that C touches: Tpetra's
// triple product transposes and traverses the whole of P, which made the Galerkin update of
// a few contact rows cost nearly as much as a full product. Collective.
RCP<CrsMatrix> galerkinProductOfChange(const RCP<const CrsMatrix>& P, const RCP<const CrsMatrix>& change) {
  // The DOFs the change touches (its nonzero rows and their columns), each given one owner.
  std::vector<GlobalOrdinal> touched;
  const auto local = change->getLocalMatrixHost();
  for (LocalOrdinal row = 0; row < static_cast<LocalOrdinal>(local.numRows()); ++row) {
    const auto begin = local.graph.row_map(row), end = local.graph.row_map(row + 1);
    if (begin == end) continue;
    touched.push_back(change->getRowMap()->getGlobalElement(row));
    for (auto e = begin; e < end; ++e) touched.push_back(change->getColMap()->getGlobalElement(local.graph.entries(e)));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  const RCP<const Map> overlapping = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                                 Teuchos::ArrayView<const GlobalOrdinal>(touched), 0, change->getComm()));
  const RCP<const Map> D = Tpetra::createOneToOne(overlapping);
  const Import toD(P->getRowMap(), D);
  const auto Pd = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(P, toD, P->getDomainMap(), D);
  const auto Cd = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(change, toD, D, D);
  auto coarse = rcp(new CrsMatrix(P->getDomainMap(), 0));
  Tpetra::TripleMatrixMultiply::MultiplyRAP(*Pd, true, *Cd, false, *Pd, false, *coarse);
  return coarse;
}

// A += change, where change's entries lie in A's pattern; false, on every rank, when some do
// not (A is then partly updated: the caller rebuilds it). Collective.
bool addInPattern(CrsMatrix& A, const CrsMatrix& change) {
  A.resumeFill();
  bool fits = true;
  for (LocalOrdinal row = 0; row < static_cast<LocalOrdinal>(change.getNodeNumRows()); ++row) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    change.getLocalRowView(row, cols, vals);
    if (cols.extent(0) == 0) continue;
    std::vector<GlobalOrdinal> globalCols(cols.extent(0));
    std::vector<double> rowValues(cols.extent(0));
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      globalCols[k] = change.getColMap()->getGlobalElement(cols(k));
      rowValues[k] = vals(k);
    }
    const LocalOrdinal added = A.sumIntoGlobalValues(change.getRowMap()->getGlobalElement(row),
                                                     Teuchos::ArrayView<const GlobalOrdinal>(globalCols),
                                                     Teuchos::ArrayView<const double>(rowValues));
    if (added != static_cast<LocalOrdinal>(globalCols.size())) fits = false;
  }
  A.fillComplete(A.getDomainMap(), A.getRangeMap());
  return onEveryRank(*A.getComm(), fits);
}

// The Chebyshev parameters read here and by Ifpack2, in the types they are read with: a whole
// number given for a real parameter ("ratio eigenvalue" = 20) is that number; any other type
// is an InputError naming the parameter, where Teuchos would stop inside Ifpack2.
void checkSmootherTypes(Teuchos::ParameterList& smoother) {
  const std::string where = "Solver/Preconditioner/Ifpack2/";
  for (const char* name : {"chebyshev: ratio eigenvalue", "chebyshev: boost factor", "chebyshev: max eigenvalue",
                           "chebyshev: min eigenvalue"}) {
    if (smoother.isType<int>(name)) smoother.set(name, static_cast<double>(smoother.get<int>(name)));
    if (smoother.isParameter(name) && !smoother.isType<double>(name))
      throw InputError(where + name + ": must be a number");
  }
  for (const char* name : {"chebyshev: degree", "chebyshev: eigenvalue max iterations"})
    if (smoother.isParameter(name) && !smoother.isType<int>(name))
      throw InputError(where + name + ": must be a whole number");
}

}  // namespace

Teuchos::ParameterList GeometricMultigridPreconditioner::defaultSmootherParameters() {
  Teuchos::ParameterList p("smoother");
  p.set("chebyshev: degree", 2);
  p.set("chebyshev: ratio eigenvalue", 7.0);
  // Lanczos steps for the largest eigenvalue of D^-1 A. Against an 80-step estimate, 15 steps
  // reach 99.4% of it at 2D nx = 400 and 99.99% at 3D nx = 40 on the finest level, where 30
  // power iterations reach 98.4% and 98.6%; an underestimate makes the CG count per Newton
  // system grow with the mesh (doc/algorithms.md).
  p.set("chebyshev: eigenvalue max iterations", 15);
  // Ifpack2's: the smoothers (Ifpack2's and ChebyshevSmoother) take our estimate as the max
  // eigenvalue and smooth on [estimate / ratio, boost * estimate].
  p.set("chebyshev: boost factor", 1.1);
  return p;
}

GeometricMultigridPreconditioner::GeometricMultigridPreconditioner(
    const GeometricGrid& grid, const RCP<const Map>& dofMap, const std::vector<char>& prescribed,
    const MultiVector& coordinates, int blockSize, long long coarsestSize, long long directSolveSize,
    const Teuchos::ParameterList& smoother, const Teuchos::ParameterList& muelu, int eigenvalueUpdateSteps,
    const std::vector<int>& nodeBodies)
    : smoother_(defaultSmootherParameters()), eigenvalueUpdateSteps_(eigenvalueUpdateSteps) {
  smoother_.setParameters(smoother);
  checkSmootherTypes(smoother_);
  // One step is the Rayleigh quotient of the start: at 2D nx = 800 CG then did not converge.
  if (eigenvalueUpdateSteps == 1 || eigenvalueUpdateSteps == 2 || eigenvalueUpdateSteps < 0)
    throw Error("GeometricMultigridPreconditioner: eigenvalue update steps must be 0 (fresh estimates) or at "
                "least 3");
  const int dim = grid.dimension();
  if (static_cast<int>(coordinates.getNumVectors()) != dim || blockSize < 1 ||
      dofMap->getNodeNumElements() != blockSize * coordinates.getLocalLength() ||
      prescribed.size() != dofMap->getNodeNumElements() ||
      (!nodeBodies.empty() && nodeBodies.size() != coordinates.getLocalLength()))
    throw Error("GeometricMultigridPreconditioner: coordinates, block size, DOF map and prescribed DOFs do not match");

  auto fine = std::make_shared<Level>();
  fine->dofMap = dofMap;
  fine->coordinates.resize(dim * coordinates.getLocalLength());
  for (int c = 0; c < dim; ++c) {
    auto x = coordinates.getData(c);
    for (std::size_t i = 0; i < coordinates.getLocalLength(); ++i) fine->coordinates[dim * i + c] = x[i];
  }
  fine->dirichlet = prescribed;
  fine->bodies = nodeBodies;
  levels_.push_back(fine);

  // A P_k space (more nodes than the grid's vertices, or a grid that refines its cells) goes
  // to P1 on that grid first.
  isP1_ = !grid.refinesFineCells() &&
          dofMap->getGlobalNumElements() == static_cast<Tpetra::global_size_t>(blockSize * grid.numVertices());
  std::shared_ptr<const GeometricGrid> owner;  // keeps `next` alive
  const GeometricGrid* next = isP1_ ? (owner = grid.coarser()).get() : &grid;
  // A coarse grid the direct solver takes is the last: its exact solve is the best coarse
  // correction. The fine space always gets its levels: it may be P_k, denser to factor.
  auto goesOn = [&] {
    const auto aboveSize = static_cast<long long>(levels_.back()->dofMap->getGlobalNumElements());
    return next && blockSize * next->numVertices() >= coarsestSize && (levels_.size() == 1 || aboveSize > directSolveSize);
  };
  for (; goesOn(); owner = next->coarser(), next = owner.get()) {
    auto coarse = std::make_shared<Level>();
    const Level& above = *levels_.back();
    levels_.back()->P = interpolation(*next, blockSize, above.dofMap, above.coordinates, above.dirichlet, above.bodies,
                                      coarse->dofMap, coarse->coordinates, coarse->dirichlet, coarse->bodies);
    levels_.push_back(coarse);
  }

  geometricLevels_ = static_cast<int>(levels_.size()) - 1;
  const Level& coarsest = *levels_.back();
  directCoarsest_ = static_cast<long long>(coarsest.dofMap->getGlobalNumElements()) <= directSolveSize;
  if (directCoarsest_) {
    coarse_ = std::make_unique<GatheredDirectSolver>();
    return;
  }
  // The coarsest level's rigid body modes and coordinates for MueLu.
  RCP<const MultiVector> nullspace, coarseCoordinates;
  if (levels_.size() == 1) {
    coarseCoordinates = Teuchos::rcpFromRef(coordinates);
  } else {
    std::vector<GlobalOrdinal> nodes;
    for (std::size_t k = 0; k < coarsest.dofMap->getNodeNumElements(); k += blockSize)
      nodes.push_back(coarsest.dofMap->getGlobalElement(k) / blockSize);
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    auto nodeMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(nodes), 0, coarsest.dofMap->getComm()));
    auto x = rcp(new MultiVector(nodeMap, dim));
    for (int c = 0; c < dim; ++c) {
      auto data = x->getDataNonConst(c);
      for (std::size_t i = 0; i < nodes.size(); ++i) data[i] = coarsest.coordinates[dim * i + c];
    }
    coarseCoordinates = x;
  }
  if (blockSize == dim) nullspace = rigidBodyModes(coarsest.dofMap, *coarseCoordinates);
  coarse_ = std::make_unique<MueLuPreconditioner>(muelu, blockSize, nullspace, coarseCoordinates);
}

void GeometricMultigridPreconditioner::keepAlgebraicLevels() {
  if (directCoarsest_ || !cycle_.is_null()) return;
  algebraicBelow_.reset(static_cast<MueLuPreconditioner*>(coarse_.release()));
}

GeometricMultigridPreconditioner::~GeometricMultigridPreconditioner() = default;

std::vector<long long> GeometricMultigridPreconditioner::levelSizes() const {
  std::vector<long long> sizes;
  for (const auto& level : levels_) sizes.push_back(static_cast<long long>(level->dofMap->getGlobalNumElements()));
  return sizes;
}

RCP<const CrsMatrix> GeometricMultigridPreconditioner::prolongator(int level) const {
  if (level < 0 || level + 1 >= static_cast<int>(levels_.size()))
    throw Error("GeometricMultigridPreconditioner::prolongator: no level " + std::to_string(level));
  return levels_[level]->P;
}

namespace {

// One V-cycle over the levels: Chebyshev before and after each coarse correction (restricted
// by P's transpose, prolongated by P), the coarse operator (a direct solve or MueLu) at the
// bottom.
class VCycle : public Operator {
 public:
  VCycle(std::vector<RCP<const Operator>> A, std::vector<RCP<const Operator>> S, std::vector<RCP<CrsMatrix>> P,
         RCP<const Operator> coarse)
      : A_(std::move(A)), S_(std::move(S)), P_(std::move(P)), coarse_(std::move(coarse)) {}

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha, Scalar beta) const override {
    const std::size_t numVectors = X.getNumVectors();
    if (work_.empty() || work_[0].x->getNumVectors() != numVectors) {
      work_.clear();
      for (std::size_t l = 0; l < A_.size(); ++l)
        work_.push_back({rcp(new MultiVector(A_[l]->getRangeMap(), numVectors)),
                         rcp(new MultiVector(A_[l]->getRangeMap(), numVectors)),
                         rcp(new MultiVector(A_[l]->getRangeMap(), numVectors))});
    }
    work_[0].b->assign(X);
    cycle(0);
    Y.update(alpha, *work_[0].x, beta);
  }
  RCP<const Map> getDomainMap() const override { return A_[0]->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return A_[0]->getRangeMap(); }

 private:
  struct Work {
    RCP<MultiVector> b, x, r;
  };

  void cycle(std::size_t l) const {
    Work& w = work_[l];
    if (l + 1 == A_.size()) {
      coarse_->apply(*w.b, *w.x);
      return;
    }
    S_[l]->apply(*w.b, *w.x);
    residual(l);
    P_[l]->apply(*w.r, *work_[l + 1].b, Teuchos::TRANS);
    cycle(l + 1);
    P_[l]->apply(*work_[l + 1].x, *w.x, Teuchos::NO_TRANS, 1.0, 1.0);
    residual(l);
    S_[l]->apply(*w.r, *w.x, Teuchos::NO_TRANS, 1.0, 1.0);
  }

  void residual(std::size_t l) const {
    Work& w = work_[l];
    A_[l]->apply(*w.x, *w.r);
    w.r->update(1.0, *w.b, -1.0);
  }

  std::vector<RCP<const Operator>> A_, S_;
  std::vector<RCP<CrsMatrix>> P_;
  RCP<const Operator> coarse_;
  mutable std::vector<Work> work_;
};

}  // namespace

void GeometricMultigridPreconditioner::compute(const RCP<CrsMatrix>& A, bool reuse) {
  // After the first build, the coarse matrices are updated with the Galerkin products of what
  // changed in A alone (a few rows: A^T D A on the contact DOFs), not recomputed: the full
  // products were 0.9 s of a 1.6 s setup at 3D nx = 64.
  RCP<CrsMatrix> change;
  if (levels_.size() > 1 && !levels_[0]->A.is_null()) {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: Galerkin products"));
    change = changedEntries(*levels_[0]->A, *A);
  }
  build(A, change, reuse);
}

void GeometricMultigridPreconditioner::update(const RCP<CrsMatrix>& A, const CrsMatrix& change, bool reuse) {
  if (levels_[0]->A.is_null()) throw Error("GeometricMultigridPreconditioner::update called before compute()");
  build(A, Teuchos::rcpFromRef(change), reuse);
}

void GeometricMultigridPreconditioner::build(const RCP<CrsMatrix>& A, RCP<const CrsMatrix> change, bool reuse) {
  levels_[0]->A = A;
  levels_[0]->op = A;
  lastTerm_ = Teuchos::null;  // the first coarse matrix is no longer of the form P^T (Q + C) P
  buildFrom(0, change, reuse);
}

void GeometricMultigridPreconditioner::setFineStiffness(const RCP<const CrsMatrix>& Q) {
  fineStiffness_ = Q;
  firstCoarseStiffness_ = Teuchos::null;
}

void GeometricMultigridPreconditioner::setGridStiffness(const CrsMatrix& gridStiffness) {
  if (isP1_ || levels_.size() < 2)
    throw Error("GeometricMultigridPreconditioner::setGridStiffness needs a P_k fine space, k > 1, with a level below");
  const RCP<const Map>& first = levels_[1]->dofMap;
  if (gridStiffness.getGlobalNumRows() != first->getGlobalNumElements())
    throw Error("GeometricMultigridPreconditioner::setGridStiffness: the matrix is not on the grid's vertices");
  firstCoarseStiffness_ = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(
      Teuchos::rcpFromRef(gridStiffness), Import(gridStiffness.getRowMap(), first), first, first);
  fineStiffness_ = Teuchos::null;
}

RCP<CrsMatrix> GeometricMultigridPreconditioner::firstCoarseStiffness() const {
  if (!firstCoarseStiffness_.is_null()) return rcp(new CrsMatrix(*firstCoarseStiffness_, Teuchos::Copy));
  if (fineStiffness_.is_null())
    throw Error("GeometricMultigridPreconditioner::computeForSum needs setFineStiffness() or setGridStiffness() first");
  const Level& fine = *levels_[0];
  auto PtQP = rcp(new CrsMatrix(fine.P->getDomainMap(), 0));
  Tpetra::TripleMatrixMultiply::MultiplyRAP(*fine.P, true, *fineStiffness_, false, *fine.P, false, *PtQP);
  return PtQP;
}

// C's entries lie in Q's pattern, so those of P^T C P lie in P^T Q P's: they are summed into
// it in place. Tpetra's sum of two matrices, which builds a third, took longer than the
// product P^T Q P itself.
RCP<CrsMatrix> GeometricMultigridPreconditioner::firstCoarseMatrix(const RCP<const CrsMatrix>& C) const {
  const RCP<CrsMatrix> term = galerkinProductOfChange(levels_[0]->P, C);
  const RCP<CrsMatrix> sum = firstCoarseStiffness();
  if (addInPattern(*sum, *term)) return sum;
  return Tpetra::MatrixMatrix::add(1.0, false, *firstCoarseStiffness(), 1.0, false, *term);
}

void GeometricMultigridPreconditioner::computeForSum(const RCP<const Operator>& H, const Vector& diagonal,
                                                     const RCP<const CrsMatrix>& C, bool reuse) {
  if (levels_.size() < 2)
    throw Error("GeometricMultigridPreconditioner::computeForSum needs a geometric level below the fine one");
  Level& fine = *levels_[0];
  Level& first = *levels_[1];
  RCP<const CrsMatrix> change, coarseChange;  // what changed in C since the last call, and its product
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: Galerkin products"));
    change = changeOfTerm(*C);
    if (!change.is_null() && !first.A.is_null()) {
      const RCP<CrsMatrix> product = galerkinProductOfChange(fine.P, change);
      if (addInPattern(*first.A, *product)) coarseChange = product;
    }
    if (coarseChange.is_null()) {  // P^T Q P + P^T C P afresh
      first.A = firstCoarseMatrix(C);
      change = Teuchos::null;
    }
    rememberTerm(C);
  }
  fine.A = Teuchos::null;
  fine.op = H;
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: smoothers"));
    fine.eigenvalue.setDiagonal(diagonal);
    ChebyshevSmoother::Parameters p;
    p.degree = smoother_.get<int>("chebyshev: degree");
    p.eigenvalueRatio = smoother_.get<double>("chebyshev: ratio eigenvalue");
    p.boostFactor = smoother_.get<double>("chebyshev: boost factor");
    p.maxEigenvalue = maxEigenvalueOfSum(fine, *C, change);
    fine.smoother = rcp(new ChebyshevSmoother(H, fine.eigenvalue.inverseDiagonal(), p));
  }
  buildFrom(1, coarseChange, reuse);
}

// C - (the last C) on C's graph, as a matrix; null when there is no last C on that graph.
RCP<const CrsMatrix> GeometricMultigridPreconditioner::changeOfTerm(const CrsMatrix& C) const {
  const auto local = C.getLocalMatrixHost();
  const bool comparable = !lastTerm_.is_null() && lastTerm_ == C.getCrsGraph() &&
                          lastTermValues_.size() == local.values.extent(0);
  if (!onEveryRank(*C.getComm(), comparable)) return Teuchos::null;
  typename CrsMatrix::local_matrix_device_type::values_type values("change of C", local.values.extent(0));
  for (std::size_t e = 0; e < lastTermValues_.size(); ++e) values(e) = local.values(e) - lastTermValues_[e];
  auto change = rcp(new CrsMatrix(C.getCrsGraph(), values));
  change->fillComplete(C.getDomainMap(), C.getRangeMap());
  return change;
}

void GeometricMultigridPreconditioner::rememberTerm(const RCP<const CrsMatrix>& C) {
  const auto values = C->getLocalMatrixHost().values;
  lastTerm_ = C->getCrsGraph();
  lastTermValues_.assign(values.data(), values.data() + values.extent(0));
}

double GeometricMultigridPreconditioner::maxEigenvalue(Level& level, const RCP<const CrsMatrix>& change) {
  if (smoother_.isParameter("chebyshev: max eigenvalue")) return smoother_.get<double>("chebyshev: max eigenvalue");
  int steps = smoother_.get<int>("chebyshev: eigenvalue max iterations");
  if (!change.is_null() && level.eigenvalue.hasRitzVector() && eigenvalueUpdateSteps_ > 0) {
    level.eigenvalue.startFromLast(*change);
    steps = eigenvalueUpdateSteps_;
  } else {
    level.eigenvalue.startFresh();
  }
  return level.eigenvalue.estimate(*level.op, steps);
}

void GeometricMultigridPreconditioner::setFineStiffnessOperator(const RCP<const Operator>& Q,
                                                                const Vector& diagonalOfQ) {
  fineOperator_ = Q;
  fineOperatorDiagonal_ = rcp(new Vector(diagonalOfQ, Teuchos::Copy));
  fineOperatorEigenvalue_ = 0.0;
}

double GeometricMultigridPreconditioner::maxEigenvalueOfSum(Level& fine, const CrsMatrix& C,
                                                            const RCP<const CrsMatrix>& change) {
  if (fineOperator_.is_null() || smoother_.isParameter("chebyshev: max eigenvalue"))
    return maxEigenvalue(fine, change);
  if (fineOperatorEigenvalue_ == 0.0) {
    JacobiEigenvalueEstimate ofQ;
    ofQ.setDiagonal(*fineOperatorDiagonal_);
    fineOperatorEigenvalue_ = ofQ.estimate(*fineOperator_, smoother_.get<int>("chebyshev: eigenvalue max iterations"));
  }
  // The smoother damps up to boost x lambda_Q: where that covers the bound max(lambda_Q,
  // gamma_C) on H's eigenvalues, H needs no estimate of its own.
  if (jacobiGershgorinBound(C) > smoother_.get<double>("chebyshev: boost factor") * fineOperatorEigenvalue_)
    return maxEigenvalue(fine, change);
  return fineOperatorEigenvalue_;
}

void GeometricMultigridPreconditioner::buildFrom(std::size_t top, RCP<const CrsMatrix> change, bool reuse) {
  levels_[top]->op = levels_[top]->A;
  for (std::size_t l = top; l + 1 < levels_.size(); ++l) change = buildLevel(l, change);
  if (algebraicBelow_ && algebraicLevels_ == 0) {
    const std::size_t last = levels_.size() - 1;
    appendAlgebraicLevels();
    for (std::size_t l = last; l + 1 < levels_.size(); ++l) buildSmoother(l, Teuchos::null);
  }
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: coarsest level"));
    coarse_->compute(levels_.back()->A, reuse && !cycle_.is_null());
  }
  std::vector<RCP<const Operator>> operators, smoothers;
  std::vector<RCP<CrsMatrix>> prolongators;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    operators.push_back(levels_[l]->op);
    if (l + 1 == levels_.size()) break;
    smoothers.push_back(levels_[l]->smoother);
    prolongators.push_back(levels_[l]->P);
  }
  cycle_ = rcp(new VCycle(operators, smoothers, prolongators, coarse_->getOperator()));
}

RCP<const CrsMatrix> GeometricMultigridPreconditioner::buildLevel(std::size_t l, RCP<const CrsMatrix> change) {
  Level& level = *levels_[l];
  RCP<CrsMatrix> coarseA;
  const RCP<const CrsMatrix> levelChange = change;
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: Galerkin products"));
    if (!change.is_null() && !change->getRowMap()->isSameAs(*level.P->getRowMap())) change = Teuchos::null;
    if (!change.is_null()) {
      const RCP<CrsMatrix> coarseChange = galerkinProductOfChange(level.P, change);
      change = addInPattern(*levels_[l + 1]->A, *coarseChange) ? coarseChange : Teuchos::null;
      if (!change.is_null()) coarseA = levels_[l + 1]->A;
    }
    if (coarseA.is_null()) {
      coarseA = rcp(new CrsMatrix(level.P->getDomainMap(), 0));
      Tpetra::TripleMatrixMultiply::MultiplyRAP(*level.P, true, *level.A, false, *level.P, false, *coarseA);
    }
  }
  levels_[l + 1]->A = coarseA;
  levels_[l + 1]->op = coarseA;
  buildSmoother(l, levelChange);
  return change;
}

void GeometricMultigridPreconditioner::buildSmoother(std::size_t l, const RCP<const CrsMatrix>& levelChange) {
  Level& level = *levels_[l];
  Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: smoothers"));
  const auto chebyshev = rcp(new Chebyshev(level.A));
  Teuchos::ParameterList smoother = smoother_;
  level.eigenvalue.setMatrix(*level.A);
  smoother.set("chebyshev: max eigenvalue", maxEigenvalue(level, levelChange));
  // Each build makes a new smoother, whose matrix never changes. Told so, Ifpack2 13.2 skips
  // its own power method, which it otherwise runs in every compute() even when given the
  // max eigenvalue, and then ignores: a third of the setup time at 2D nx = 800. Given the
  // inverse diagonal, it does not extract the diagonal a second time; it reads that vector
  // by reference, which the level's next setMatrix() overwrites, so this smoother is valid
  // until the next build (as the cycle holding it is).
  if (!smoother.isParameter("chebyshev: assume matrix does not change"))
    smoother.set("chebyshev: assume matrix does not change", true);
  smoother.set("chebyshev: operator inv diagonal", level.eigenvalue.inverseDiagonal());
  chebyshev->setParameters(smoother);
  chebyshev->initialize();
  chebyshev->compute();
  level.smoother = chebyshev;
}

void GeometricMultigridPreconditioner::appendAlgebraicLevels() {
  Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup: algebraic levels"));
  algebraicBelow_->compute(levels_.back()->A);
  for (const MueLuPreconditioner::CoarseLevel& level : algebraicBelow_->coarseLevels()) {
    levels_.back()->P = level.P;
    auto coarse = std::make_shared<Level>();
    coarse->dofMap = level.P->getDomainMap();
    coarse->A = level.A;
    coarse->op = level.A;
    levels_.push_back(coarse);
  }
  algebraicLevels_ = static_cast<int>(levels_.size()) - 1 - geometricLevels_;
  coarse_ = std::make_unique<GatheredDirectSolver>();
}

void GeometricMultigridPreconditioner::refreshAlgebraicLevels() {
  if (algebraicLevels_ == 0) return;
  levels_.resize(geometricLevels_ + 1);
  Level& coarsest = *levels_.back();
  coarsest.P = Teuchos::null;
  coarsest.smoother = Teuchos::null;
  algebraicLevels_ = 0;
}

RCP<const CrsMatrix> GeometricMultigridPreconditioner::levelMatrix(int level) const {
  if (level < 0 || level >= static_cast<int>(levels_.size()) || levels_[level]->A.is_null())
    throw Error("GeometricMultigridPreconditioner::levelMatrix: no such level, or it is not assembled (no build "
                "yet, or a fine level given as an operator)");
  return levels_[level]->A;
}

std::vector<long long> GeometricMultigridPreconditioner::levelNonzeros() const {
  if (cycle_.is_null()) return {};
  std::vector<long long> nonzeros;
  for (const auto& level : levels_) {
    const RCP<const CrsMatrix> A = level->A.is_null() && level == levels_.front() ? fineStiffness_ : RCP<const CrsMatrix>(level->A);
    nonzeros.push_back(A.is_null() ? 0 : static_cast<long long>(A->getGlobalNumEntries()));
  }
  const std::vector<long long> below = coarse_ ? coarse_->levelNonzeros() : std::vector<long long>();
  if (below.size() > 1) nonzeros.insert(nonzeros.end(), below.begin() + 1, below.end());  // its first is ours
  return nonzeros;
}

RCP<Operator> GeometricMultigridPreconditioner::getOperator() const {
  if (cycle_.is_null()) throw Error("GeometricMultigridPreconditioner::getOperator called before compute()");
  return cycle_;
}

}  // namespace signorini
