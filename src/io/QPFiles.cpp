#include "signorini/io/QPFiles.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <MatrixMarket_Tpetra.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/RootTask.hpp"
#include "signorini/core/Error.hpp"

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

}  // namespace

void writeQP(const ContactQP& qp, const std::string& directory) {
  const RCP<const CrsMatrix> Q = qp.Qmatrix();
  if (Q.is_null())
    throw InputError("writeQP needs Q as an assembled matrix (ContactQP::Q a CrsMatrix, or Qassembled); from the "
                     "command line, set Problem/stiffness: operator to \"assembled\"");
  if (qp.coordinates.is_null()) throw InputError("writeQP needs the node coordinates (ContactQP::coordinates)");
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
  Writer::writeDenseFile(directory + "/coords.mtx", qp.coordinates, "coords",
                         "node coordinates; DOF dim*node+c is component c of node node");
}

ContactQP readQP(const std::string& directory, const RCP<const Comm>& comm) {
  const QPSizes sizes = checkedSizes(directory, *comm);
  const auto file = [&](const char* name) { return directory + "/" + name; };
  // Whole nodes on every rank, an equal share of them; their DOFs contiguous, node-interlaced.
  RCP<const Map> nodeMap = rcp(new Map(sizes.nodes, 0, comm));
  const RCP<const Map> dofMap =
      rcp(new Map(sizes.n, sizes.dim * nodeMap->getNodeNumElements(), 0, comm));
  RCP<const Map> constraintMap = rcp(new Map(sizes.m, 0, comm));

  ContactQP qp;
  qp.blockSize = static_cast<int>(sizes.dim);
  qp.coordinates = readOrRefuse(file("coords.mtx"), [&] { return Reader::readDenseFile(file("coords.mtx"), comm, nodeMap); });
  RCP<const Map> noColumnMap;
  qp.Q = readOrRefuse(file("Q.mtx"),
                      [&] { return Reader::readSparseFile(file("Q.mtx"), dofMap, noColumnMap, dofMap, dofMap); });
  RCP<const Map> bMap = dofMap;
  qp.b = readOrRefuse(file("b.mtx"), [&] { return Reader::readVectorFile(file("b.mtx"), comm, bMap); });
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
  return qp;
}

}  // namespace signorini
