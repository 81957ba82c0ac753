#include "signorini/io/QPFiles.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <MatrixMarket_Tpetra.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/RootTask.hpp"
#include "io/QPCells.hpp"
#include "io/QPNodeDistribution.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/solver/SimplexGrid.hpp"

namespace signorini {
namespace {

using Reader = Tpetra::MatrixMarket::Reader<CrsMatrix>;
using Writer = Tpetra::MatrixMarket::Writer<CrsMatrix>;

// The rows and columns a Matrix Market file declares (its first line that is not a comment).
struct Size {
  long long rows = 0, columns = 0;
};

Size declaredSize(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot be opened (a QP directory holds Q.mtx, b.mtx, A.mtx, d.mtx and "
                            "coords.mtx; see doc/qp-format.md)");
  std::string line;
  if (!std::getline(in, line) || line.rfind("%%MatrixMarket", 0) != 0)
    throw InputError(path + ": not a Matrix Market file (no %%MatrixMarket banner)");
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '%') {
      Size size;
      std::istringstream(line) >> size.rows >> size.columns;
      if (size.rows > 0 && size.columns > 0) return size;
      break;
    }
  throw InputError(path + ": no size line");
}

// The sizes of the five files, checked against each other on rank 0 and known on every rank.
struct QPSizes {
  long long nodes = 0, dim = 0, n = 0, m = 0;
};

QPSizes checkedSizes(const std::string& directory, const Comm& comm) {
  long long values[4] = {0, 0, 0, 0};
  detail::runOnRoot(comm, [&] {
    const auto file = [&](const char* name) { return directory + "/" + name; };
    const Size coords = declaredSize(file("coords.mtx")), Q = declaredSize(file("Q.mtx")),
               b = declaredSize(file("b.mtx")), A = declaredSize(file("A.mtx")), d = declaredSize(file("d.mtx"));
    if (coords.columns < 2 || coords.columns > 3)
      throw InputError(file("coords.mtx") + ": " + std::to_string(coords.columns) +
                       " coordinates per node; 2 or 3 expected (one row per node)");
    const long long n = coords.rows * coords.columns;
    const auto expect = [&](const char* name, const Size& size, long long rows, long long columns,
                            const std::string& why) {
      if (size.rows != rows || size.columns != columns)
        throw InputError(file(name) + ": " + std::to_string(size.rows) + " x " + std::to_string(size.columns) +
                         ", expected " + std::to_string(rows) + " x " + std::to_string(columns) + " (" + why + ")");
    };
    const std::string unknowns = std::to_string(coords.rows) + " nodes of coords.mtx times " +
                                 std::to_string(coords.columns) + " components";
    expect("Q.mtx", Q, n, n, unknowns);
    expect("b.mtx", b, n, 1, unknowns);
    expect("A.mtx", A, d.rows, n, "the rows of d.mtx, the " + unknowns);
    expect("d.mtx", d, A.rows, 1, "a column");
    values[0] = coords.rows;
    values[1] = coords.columns;
    values[2] = n;
    values[3] = d.rows;
  });
  Teuchos::broadcast(comm, 0, 4, values);
  return {values[0], values[1], values[2], values[3]};
}

// Runs a Tpetra reader, its failure an InputError naming the file.
template <class Read>
auto readOrRefuse(const std::string& path, Read read) {
  try {
    return read();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path + ": " + e.what());
  }
}

// A map that puts each constraint on the rank of its row's first unknown, as the program's own
// problems place nodal constraints, so that A's products need no communication for them: the
// owners of all m constraints are gathered on every rank (m is a surface's count), and each
// rank takes its own. Collective.
RCP<const Map> constraintsWithTheirNodes(const CrsMatrix& A, const Map& unknowns) {
  const Map& rows = *A.getRowMap();
  const auto count = static_cast<LocalOrdinal>(rows.getNodeNumElements());
  Teuchos::Array<GlobalOrdinal> first(count);
  for (LocalOrdinal i = 0; i < count; ++i) {
    CrsMatrix::local_inds_host_view_type columns;
    CrsMatrix::values_host_view_type values;
    A.getLocalRowView(i, columns, values);
    first[i] = columns.extent(0) > 0 ? A.getColMap()->getGlobalElement(columns(0)) : unknowns.getMinGlobalIndex();
  }
  Teuchos::Array<int> owners(count);
  unknowns.getRemoteIndexList(first(), owners());
  Vector owner(A.getRowMap());
  {
    auto o = owner.getDataNonConst();
    for (LocalOrdinal i = 0; i < count; ++i) o[i] = owners[i];
  }
  const RCP<const Map> everywhere = Tpetra::createLocalMapWithNode<LocalOrdinal, GlobalOrdinal, Node>(
      rows.getGlobalNumElements(), A.getComm());
  Vector all(everywhere);
  all.doImport(owner, Import(A.getRowMap(), everywhere), Tpetra::INSERT);
  Teuchos::Array<GlobalOrdinal> mine;
  auto a = all.getData();
  const int rank = A.getComm()->getRank();
  for (std::size_t g = 0; g < all.getLocalLength(); ++g)
    if (static_cast<int>(a[g]) == rank) mine.push_back(everywhere->getGlobalElement(static_cast<LocalOrdinal>(g)));
  return rcp(new Map(rows.getGlobalNumElements(), mine(), 0, A.getComm()));
}

// A copy of `v` on every rank. Collective.
RCP<MultiVector> everywhere(const MultiVector& v) {
  const RCP<const Map> all = rcp(new Map(v.getGlobalLength(), 0, v.getMap()->getComm(), Tpetra::LocallyReplicated));
  auto copy = rcp(new MultiVector(all, v.getNumVectors()));
  copy->doImport(v, Import(v.getMap(), all), Tpetra::INSERT);
  return copy;
}

// Of `cells` (dim + 1 node numbers each, of the sorted `vertices` at `vertexCoordinates`),
// those that hold this rank's nodes: every cell with one of them as a vertex, so that the
// grid has all their edges, and for a node that is no vertex (of a P2 or P3 space) the cell
// that the grid of all cells locates it in. Collective.
std::vector<long long> cellsHoldingNodes(int dim, const std::vector<long long>& cells,
                                         const std::vector<long long>& vertices,
                                         const std::vector<double>& vertexCoordinates, const MultiVector& coordinates) {
  const Map& nodes = *coordinates.getMap();
  const std::size_t corners = dim + 1, numCells = cells.size() / corners;
  std::vector<char> taken(numCells, 0);
  for (std::size_t c = 0; c < numCells; ++c)
    for (std::size_t k = 0; k < corners && !taken[c]; ++k) taken[c] = nodes.isNodeGlobalElement(cells[corners * c + k]);
  std::vector<std::size_t> inside;  // local nodes that are no vertex
  for (std::size_t i = 0; i < coordinates.getLocalLength(); ++i)
    if (!std::binary_search(vertices.begin(), vertices.end(), nodes.getGlobalElement(i))) inside.push_back(i);
  if (sumOverRanks(*nodes.getComm(), static_cast<long long>(inside.size())) > 0) {
    const SimplexGrid all(nodes.getComm(), dim, vertices, vertexCoordinates, cells, SimplexGrid::Outside::error,
                          SimplexGrid::CoarseGrids::none);
    std::map<std::vector<long long>, long long> cellOf;  // sorted vertices -> cell
    for (std::size_t c = 0; c < numCells; ++c) {
      std::vector<long long> key(cells.begin() + corners * c, cells.begin() + corners * (c + 1));
      std::sort(key.begin(), key.end());
      cellOf[key] = static_cast<long long>(c);
    }
    long long holding[4];
    double x[3], weights[4];
    for (std::size_t i : inside) {
      for (int k = 0; k < dim; ++k) x[k] = coordinates.getData(k)[i];
      all.interpolation(x, holding, weights);
      std::vector<long long> key(holding, holding + corners);
      std::sort(key.begin(), key.end());
      taken[cellOf.at(key)] = 1;
    }
  }
  std::vector<long long> mine;
  for (std::size_t c = 0; c < numCells; ++c)
    if (taken[c]) mine.insert(mine.end(), cells.begin() + corners * c, cells.begin() + corners * (c + 1));
  return mine;
}

// The P1 grid of cells.mtx (dim + 1 node numbers per cell), if the directory has one, with
// its Delaunay coarse grids: of a P2 or P3 space the P_k -> P1 step, of a P1 space the grids
// below it. Every rank reads all cells and node coordinates and keeps the cells that hold its
// nodes. Collective.
std::shared_ptr<const GeometricGrid> cellGrid(const std::string& path, const MultiVector& coordinates, int dim) {
  const RCP<const Comm> comm = coordinates.getMap()->getComm();
  int present = 0;
  detail::runOnRoot(*comm, [&] { present = std::filesystem::exists(path); });
  Teuchos::broadcast(*comm, 0, 1, &present);
  if (!present) return nullptr;
  RCP<const Map> uniform;
  const RCP<MultiVector> read = readOrRefuse(path, [&] { return Reader::readDenseFile(path, comm, uniform); });
  if (static_cast<int>(read->getNumVectors()) != dim + 1)
    throw InputError(path + ": " + std::to_string(read->getNumVectors()) + " columns; a cell of coords.mtx's " +
                     std::to_string(dim) + "D nodes has " + std::to_string(dim + 1) + " vertices");
  const RCP<MultiVector> allCells = everywhere(*read), allCoordinates = everywhere(coordinates);
  const long long numNodes = static_cast<long long>(allCoordinates->getLocalLength());
  std::vector<long long> cells, vertices;
  for (std::size_t c = 0; c < allCells->getLocalLength(); ++c)
    for (int k = 0; k <= dim; ++k) {
      const double node = allCells->getData(k)[c];
      if (node != std::floor(node) || node < 0 || node >= static_cast<double>(numNodes))
        throw InputError(path + ": row " + std::to_string(c + 1) + " names node " + std::to_string(node) +
                         "; nodes are numbered 0 to " + std::to_string(numNodes - 1) + " (coords.mtx's rows less 1)");
      cells.push_back(static_cast<long long>(node));
    }
  vertices = cells;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  const auto coordinatesOf = [&](const std::vector<long long>& nodes) {
    std::vector<double> x;
    for (long long node : nodes)
      for (int k = 0; k < dim; ++k) x.push_back(allCoordinates->getData(k)[node]);
    return x;
  };
  const std::vector<long long> mine = cellsHoldingNodes(dim, cells, vertices, coordinatesOf(vertices), coordinates);
  std::vector<long long> myVertices = mine;
  std::sort(myVertices.begin(), myVertices.end());
  myVertices.erase(std::unique(myVertices.begin(), myVertices.end()), myVertices.end());
  return std::make_shared<SimplexGrid>(comm, dim, myVertices, coordinatesOf(myVertices), mine);
}

}  // namespace

void writeQP(const ContactQP& qp, const MultigridInput& multigrid, const std::string& directory) {
  const RCP<const CrsMatrix> Q = assembledStiffness(qp, multigrid);
  if (Q.is_null())
    throw InputError("writeQP needs Q as an assembled matrix (ContactQP::Q a CrsMatrix, or "
                     "MultigridInput::assembledQ); from the command line, set Problem/stiffness: operator to "
                     "\"assembled\"");
  if (multigrid.coordinates.is_null())
    throw InputError("writeQP needs the node coordinates (MultigridInput::coordinates)");
  const Comm& comm = *Q->getComm();
  detail::runOnRoot(comm, [&] {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) throw OutputError("cannot create directory '" + directory + "': " + error.message());
  });
  Writer::writeSparseFile(directory + "/Q.mtx", Q, "Q", "stiffness, Dirichlet DOFs eliminated symmetrically");
  Writer::writeSparseFile(directory + "/A.mtx", qp.A, "A", "contact constraints A v <= d");
  Writer::writeDenseFile(directory + "/b.mtx", qp.b, "b", "load vector");
  Writer::writeDenseFile(directory + "/d.mtx", qp.d, "d", "contact gaps");
  Writer::writeDenseFile(directory + "/coords.mtx", multigrid.coordinates, "coords",
                         "node coordinates; DOF dim*node+c is component c of node node");
}

void detail::writeCells(const DistributedSpace& space, const std::string& directory) {
  const SimplexMesh& mesh = space.mesh();
  const int dim = space.dim();
  std::vector<GlobalOrdinal> ids;
  for (long long c = 0; c < mesh.numCells(); ++c) ids.push_back(space.globalCell(c));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const RCP<const Map> cellMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, space.comm()));
  auto cells = rcp(new MultiVector(cellMap, dim + 1));
  for (int k = 0; k <= dim; ++k) {
    auto column = cells->getDataNonConst(k);
    for (long long c = 0; c < mesh.numCells(); ++c)
      column[c] = static_cast<double>(space.globalNode(mesh.cells[(dim + 1) * c + k]));
  }
  Writer::writeDenseFile(directory + "/cells.mtx", cells, "cells",
                         "P1 cells of the mesh: the node numbers (from 0) of each cell's vertices");
}

namespace {

// The nodes of `owner` that are this rank's, and their unknowns, node-interlaced.
std::pair<RCP<const Map>, RCP<const Map>> ownedNodes(const std::vector<int>& owner, int dim, const RCP<const Comm>& comm) {
  Teuchos::Array<GlobalOrdinal> nodes, dofs;
  for (std::size_t v = 0; v < owner.size(); ++v)
    if (owner[v] == comm->getRank()) {
      nodes.push_back(static_cast<GlobalOrdinal>(v));
      for (int c = 0; c < dim; ++c) dofs.push_back(static_cast<GlobalOrdinal>(dim * v + c));
    }
  return {rcp(new Map(owner.size(), nodes(), 0, comm)), rcp(new Map(dim * owner.size(), dofs(), 0, comm))};
}

// Q, b and the coordinates moved to the ranks of `nodes` and `dofs`.
void moveNodes(QPFromFiles& files, const RCP<const Map>& nodes, const RCP<const Map>& dofs) {
  ContactQP& qp = files.qp;
  const Import byDof(qp.b->getMap(), dofs);
  auto Q = rcp(new CrsMatrix(dofs, 0));
  Q->doImport(*Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q), byDof, Tpetra::INSERT);
  Q->fillComplete(dofs, dofs);
  auto b = rcp(new Vector(dofs));
  b->doImport(*qp.b, byDof, Tpetra::INSERT);
  auto X = rcp(new MultiVector(nodes, files.multigrid.coordinates->getNumVectors()));
  X->doImport(*files.multigrid.coordinates, Import(files.multigrid.coordinates->getMap(), nodes), Tpetra::INSERT);
  qp.Q = Q;
  qp.b = b;
  files.multigrid.coordinates = X;
}

}  // namespace

QPFromFiles readQP(const std::string& directory, const RCP<const Comm>& comm, QPPartition partition) {
  const QPSizes sizes = checkedSizes(directory, *comm);
  const auto file = [&](const char* name) { return directory + "/" + name; };
  // Whole nodes on every rank, an equal share of them; their DOFs contiguous, node-interlaced.
  RCP<const Map> nodeMap = rcp(new Map(sizes.nodes, 0, comm));
  RCP<const Map> dofMap = rcp(new Map(sizes.n, sizes.dim * nodeMap->getNodeNumElements(), 0, comm));
  RCP<const Map> constraintMap = rcp(new Map(sizes.m, 0, comm));

  QPFromFiles files;
  ContactQP& qp = files.qp;
  MultigridInput& multigrid = files.multigrid;
  multigrid.blockSize = static_cast<int>(sizes.dim);
  multigrid.coordinates = readOrRefuse(file("coords.mtx"), [&] { return Reader::readDenseFile(file("coords.mtx"), comm, nodeMap); });
  RCP<const Map> noColumnMap;
  qp.Q = readOrRefuse(file("Q.mtx"),
                      [&] { return Reader::readSparseFile(file("Q.mtx"), dofMap, noColumnMap, dofMap, dofMap); });
  RCP<const Map> bMap = dofMap;
  qp.b = readOrRefuse(file("b.mtx"), [&] { return Reader::readVectorFile(file("b.mtx"), comm, bMap); });
  // Then, where METIS' parts pay, the nodes move to them.
  const detail::NodeDistribution distribution =
      detail::distributeNodes(*Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q), multigrid.blockSize, partition);
  files.repartitioned = distribution.repartitioned;
  files.crossRankCouplings = distribution.chosenCut;
  files.crossRankCouplingsInFileOrder = distribution.fileOrderCut;
  if (distribution.repartitioned) {
    std::tie(nodeMap, dofMap) = ownedNodes(distribution.owner, multigrid.blockSize, comm);
    moveNodes(files, nodeMap, dofMap);
  }
  RCP<const Map> noAColumnMap;
  const RCP<const CrsMatrix> evenA = readOrRefuse(file("A.mtx"), [&] {
    return Reader::readSparseFile(file("A.mtx"), constraintMap, noAColumnMap, dofMap, constraintMap);
  });
  const RCP<const Vector> evenD =
      readOrRefuse(file("d.mtx"), [&] { return Reader::readVectorFile(file("d.mtx"), comm, constraintMap); });
  // The constraints move to the ranks of their unknowns.
  const RCP<const Map> rows = constraintsWithTheirNodes(*evenA, *dofMap);
  const Import move(constraintMap, rows);
  auto A = rcp(new CrsMatrix(rows, 0));
  A->doImport(*evenA, move, Tpetra::INSERT);
  A->fillComplete(dofMap, rows);
  auto d = rcp(new Vector(rows));
  d->doImport(*evenD, move, Tpetra::INSERT);
  qp.A = A;
  qp.d = d;
  multigrid.grid = cellGrid(file("cells.mtx"), *multigrid.coordinates, multigrid.blockSize);
  return files;
}

}  // namespace signorini
