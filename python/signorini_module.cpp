// The Python module `signorini`: a contact QP from scipy and numpy arrays, solved by the
// interior point solver, with v, the multipliers and the summary back as numpy arrays and a
// dict. Each MPI rank passes its own rows (contiguous blocks in rank order); on one rank, the
// whole problem.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/signorini.hpp"

namespace py = pybind11;
using namespace signorini;

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<long long, py::array::c_style | py::array::forcecast>;

RCP<const Comm> world() { return Tpetra::getDefaultComm(); }

// A map of `local` entries on this rank, contiguous in rank order.
RCP<const Map> contiguousMap(std::size_t local) {
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), local, 0, world()));
}

// This rank's rows of a scipy sparse matrix (columns global) on `rows`, completed with the
// domain `columns`.
RCP<CrsMatrix> rowsOf(const py::object& matrix, const RCP<const Map>& rows, const RCP<const Map>& columns) {
  const py::object csr = matrix.attr("tocsr")();
  const auto shape = csr.attr("shape").cast<std::pair<long long, long long>>();
  const auto start = csr.attr("indptr").cast<IndexArray>(), index = csr.attr("indices").cast<IndexArray>();
  const auto value = csr.attr("data").cast<DoubleArray>();
  Teuchos::Array<std::size_t> entries(shape.first);
  for (long long i = 0; i < shape.first; ++i) entries[i] = start.at(i + 1) - start.at(i);
  auto matrixOut = rcp(new CrsMatrix(rows, entries()));
  std::vector<GlobalOrdinal> cols;
  for (long long i = 0; i < shape.first; ++i) {
    const long long begin = start.at(i), end = start.at(i + 1);
    cols.assign(index.data() + begin, index.data() + end);
    matrixOut->insertGlobalValues(rows->getGlobalElement(i), Teuchos::ArrayView<const GlobalOrdinal>(cols),
                                  Teuchos::ArrayView<const double>(value.data() + begin, end - begin));
  }
  matrixOut->fillComplete(columns, rows);
  return matrixOut;
}

RCP<Vector> vectorOf(const DoubleArray& values, const RCP<const Map>& map) {
  auto v = rcp(new Vector(map));
  std::copy(values.data(), values.data() + values.shape(0), v->getDataNonConst().getRawPtr());
  return v;
}

py::array_t<double> arrayOf(const Vector& v) {
  auto data = v.getData();
  return py::array_t<double>(static_cast<py::ssize_t>(data.size()), data.getRawPtr());
}

std::pair<long long, long long> shapeOf(const py::object& matrix) {
  return matrix.attr("shape").cast<std::pair<long long, long long>>();
}

// What does not fit in this rank's input, or "" (n: the unknowns of all ranks).
std::string inputProblem(const py::object& Q, const DoubleArray& b, const py::object& A, const DoubleArray& d,
                         const py::object& coordinates, const py::object& cells, long long n) {
  const auto [qRows, qColumns] = shapeOf(Q);
  const auto [aRows, aColumns] = shapeOf(A);
  const auto count = std::to_string(qRows);
  if (qColumns != n) return "Q has " + std::to_string(qColumns) + " columns, expected " + std::to_string(n) +
                            " (the rows of all ranks: each passes its rows, all columns)";
  if (b.ndim() != 1 || b.shape(0) != qRows) return "b must be a vector of " + count + " entries on this rank (Q's rows)";
  if (aColumns != n) return "A has " + std::to_string(aColumns) + " columns, expected Q's " + std::to_string(n);
  if (d.ndim() != 1 || d.shape(0) != aRows)
    return "d must be a vector of " + std::to_string(aRows) + " entries on this rank (A's rows)";
  if (coordinates.is_none()) return cells.is_none() ? "" : "cells need the node coordinates";
  const auto x = coordinates.cast<DoubleArray>();
  if (x.ndim() != 2 || (x.shape(1) != 2 && x.shape(1) != 3))
    return "coordinates must be an array of shape (nodes, 2) or (nodes, 3)";
  const long long dim = x.shape(1);
  if (x.shape(0) * dim != qRows)
    return "coordinates give " + std::to_string(x.shape(0)) + " nodes on this rank, but Q has " + count +
           " rows here: pass whole nodes, " + std::to_string(dim) + " unknowns each, interlaced";
  if (cells.is_none()) return "";
  const auto c = cells.cast<IndexArray>();
  if (c.ndim() != 2 || c.shape(1) != dim + 1)
    return "cells must be an array of shape (cells, " + std::to_string(dim + 1) + ")";
  for (py::ssize_t k = 0; k < c.size(); ++k)
    if (c.data()[k] < 0 || c.data()[k] >= n / dim)
      return "cells name node " + std::to_string(c.data()[k]) + ", outside 0 .. " + std::to_string(n / dim - 1);
  return "";
}

// Every rank stops if one's input does not fit, none waits in a collective call for it.
void agreeOnInput(const Comm& comm, const std::string& problem) {
  int bad = problem.empty() ? 0 : 1, anyBad = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, bad, Teuchos::outArg(anyBad));
  if (anyBad) throw InputError(problem.empty() ? "the input of another rank does not fit (its error says what)" : problem);
}

// Node coordinates (this rank's nodes, one row each) and, with `cells`, the SimplexGrid of
// those P1 cells (global node numbers; the cells this rank's nodes belong to).
MultigridInput multigridOf(const py::object& coordinates, const py::object& cells) {
  MultigridInput multigrid;
  if (coordinates.is_none()) return multigrid;
  const auto x = coordinates.cast<DoubleArray>();
  const int dim = static_cast<int>(x.shape(1));
  multigrid.blockSize = dim;
  const RCP<const Map> nodes = contiguousMap(x.shape(0));
  auto X = rcp(new MultiVector(nodes, dim));
  for (int c = 0; c < dim; ++c) {
    auto column = X->getDataNonConst(c);
    for (py::ssize_t i = 0; i < x.shape(0); ++i) column[i] = x.at(i, c);
  }
  multigrid.coordinates = X;
  if (cells.is_none()) return multigrid;
  const auto cellArray = cells.cast<IndexArray>();
  std::vector<long long> cellList(cellArray.data(), cellArray.data() + cellArray.size());
  std::vector<long long> vertexIds = cellList;
  std::sort(vertexIds.begin(), vertexIds.end());
  vertexIds.erase(std::unique(vertexIds.begin(), vertexIds.end()), vertexIds.end());
  // The coordinates of the cells' vertices, wherever their nodes live.
  std::vector<GlobalOrdinal> ids(vertexIds.begin(), vertexIds.end());
  const RCP<const Map> cellNodes = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                               Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, world()));
  MultiVector gathered(cellNodes, dim);
  gathered.doImport(*X, Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node>(nodes, cellNodes), Tpetra::INSERT);
  std::vector<double> vertexCoordinates(vertexIds.size() * dim);
  for (int c = 0; c < dim; ++c) {
    auto column = gathered.getData(c);
    for (std::size_t v = 0; v < vertexIds.size(); ++v) vertexCoordinates[dim * v + c] = column[v];
  }
  multigrid.grid = std::make_shared<SimplexGrid>(world(), dim, std::move(vertexIds), std::move(vertexCoordinates),
                                                 std::move(cellList));
  return multigrid;
}

// A Python dict of parameters as a Teuchos list: dicts are sublists, bool, int, float and
// str values parameters of that type.
Teuchos::ParameterList parameterList(const py::dict& values, const std::string& name) {
  Teuchos::ParameterList list(name);
  for (const auto& [key, value] : values) {
    const std::string k = py::str(key);
    if (py::isinstance<py::dict>(value)) list.set(k, parameterList(value.cast<py::dict>(), k));
    else if (py::isinstance<py::bool_>(value)) list.set(k, value.cast<bool>());
    else if (py::isinstance<py::int_>(value)) list.set(k, value.cast<int>());
    else if (py::isinstance<py::float_>(value)) list.set(k, value.cast<double>());
    else if (py::isinstance<py::str>(value)) list.set(k, value.cast<std::string>());
    else throw InputError("parameter \"" + k + "\": a bool, int, float, str or dict expected");
  }
  return list;
}

py::dict summaryOf(const SolveResult& r) {
  py::dict kkt;
  kkt["stationarity"] = r.kkt.stationarity;
  kkt["complementarity"] = r.kkt.complementarity;
  kkt["primal_feasibility"] = r.kkt.primalFeasibility;
  kkt["dual_feasibility"] = r.kkt.dualFeasibility;
  py::dict s;
  s["status"] = toString(r.status);
  s["converged"] = r.converged();
  s["message"] = r.message;
  s["objective"] = r.objective;
  s["active_constraints"] = r.activeConstraints;
  s["outer_iterations"] = r.outerIterations;
  s["newton_steps"] = r.newtonSteps;
  s["krylov_iterations"] = r.krylovIterations;
  s["preconditioner_setups"] = r.preconditionerSetups;
  py::list nonzeros;
  for (long long count : r.multigridNonzeros) nonzeros.append(count);
  s["multigrid_nonzeros"] = nonzeros;
  s["operator_complexity"] = r.operatorComplexity();
  s["kkt"] = kkt;
  s["seconds"] = r.seconds;
  return s;
}

py::tuple solve(const py::object& Q, const DoubleArray& b, const py::object& A, const DoubleArray& d,
                const py::object& coordinates, const py::object& cells, const py::dict& parameters) {
  // This rank's rows: Q's and A's.
  const RCP<const Map> unknowns = contiguousMap(shapeOf(Q).first);
  const RCP<const Map> constraints = contiguousMap(shapeOf(A).first);
  agreeOnInput(*world(), inputProblem(Q, b, A, d, coordinates, cells, unknowns->getGlobalNumElements()));
  ContactQP qp;
  qp.Q = rowsOf(Q, unknowns, unknowns);
  qp.b = vectorOf(b, unknowns);
  qp.A = rowsOf(A, constraints, unknowns);
  qp.d = vectorOf(d, constraints);
  const MultigridInput multigrid = multigridOf(coordinates, cells);
  const SolveResult result = InteriorPointSolver(parameterList(parameters, "Solver")).solve(qp, multigrid);
  return py::make_tuple(arrayOf(*result.v), arrayOf(*result.lambda), summaryOf(result));
}

}  // namespace

PYBIND11_MODULE(signorini, m) {
  m.doc() = "Signorini: large contact problems, min 1/2 v^T Q v - b^T v subject to A v <= d, by interior "
            "point methods (doc/python.md)";
  // MPI and Kokkos for the interpreter's lifetime (Tpetra leaves an MPI it did not start running).
  if (!Tpetra::isInitialized()) {
    static int argc = 0;
    static char** argv = nullptr;
    Tpetra::initialize(&argc, &argv);
    py::module_::import("atexit").attr("register")(py::cpp_function([] { Tpetra::finalize(); }));
  }
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.attr("__version__") = kVersion;
  m.def("rank", [] { return world()->getRank(); }, "This process' MPI rank.");
  m.def("size", [] { return world()->getSize(); }, "The number of MPI ranks.");
  m.def("solve", &solve, py::arg("Q"), py::arg("b"), py::arg("A"), py::arg("d"), py::arg("coordinates") = py::none(),
        py::arg("cells") = py::none(), py::arg("parameters") = py::dict(),
        R"(Solves min 1/2 v^T Q v - b^T v subject to A v <= d; returns (v, multipliers, summary).

Q, A: scipy sparse matrices, this rank's rows, all columns; b, d: numpy vectors of this rank's
rows. coordinates: (nodes, dim) of this rank's nodes, their dim unknowns interlaced in Q's rows
(MueLu's block size and rigid body modes); cells: (cells, dim + 1) global node numbers of P1
cells of the mesh around this rank's nodes (the geometric P_k -> P1 multigrid step).
parameters: the "Solver" list as a dict (sublists as dicts), e.g. {"method": "primal"}.
multipliers: the paper's sign, <= 0, the contact forces' magnitudes on the constraints.)");
}
