#include "support/ActiveSetReference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/LocalDirectSolver.hpp"
#include "support/TestProblems.hpp"

namespace signorini::testing {

// Each constraint must act on one unknown (a row of A with one entry), as contact
// constraints with an axis-aligned obstacle direction do: then an active constraint fixes
// its unknown, and the system of an active set is Q with those unknowns eliminated
// symmetrically, which is SPD. It is solved by a sparse Cholesky factorization (CHOLMOD).
ReferenceSolution activeSetSolve(const ContactQP& qp, int maxIterations) {
  const auto Q = Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q);
  if (Q.is_null()) throw Error("activeSetSolve needs Q as a CrsMatrix");
  const auto comm = Q->getComm();
  if (comm->getSize() != 1) throw Error("activeSetSolve needs a one-rank communicator");
  const std::size_t n = Q->getGlobalNumRows(), m = qp.A->getGlobalNumRows();

  std::vector<GlobalOrdinal> unknown(m);
  std::vector<double> coefficient(m);
  for (std::size_t i = 0; i < m; ++i) {
    if (qp.A->getNumEntriesInGlobalRow(i) != 1) throw Error("activeSetSolve: a row of A has several entries");
    CrsMatrix::nonconst_global_inds_host_view_type col("c", 1);
    CrsMatrix::nonconst_values_host_view_type val("v", 1);
    std::size_t count = 0;
    qp.A->getGlobalRowCopy(i, col, val, count);
    unknown[i] = col(0);
    coefficient[i] = val(0);
  }
  const double c = Q->getFrobeniusNorm() / std::sqrt(static_cast<double>(n));  // balances y and A v - d
  auto d = qp.d->getData();
  auto b = qp.b->getData();
  std::vector<char> active(m, 0);
  ReferenceSolution result;
  result.v = rcp(new Vector(Q->getDomainMap()));

  LocalDirectSolver solver;  // every active set's matrix has Q's pattern: one analysis
  for (int it = 1; it <= maxIterations; ++it) {
    std::vector<char> fixed(n, 0);
    std::vector<double> value(n, 0.0);
    for (std::size_t i = 0; i < m; ++i)
      if (active[i]) {
        fixed[unknown[i]] = 1;
        value[unknown[i]] = d[i] / coefficient[i];
      }
    Teuchos::Array<std::size_t> counts(n);
    for (std::size_t r = 0; r < n; ++r) counts[r] = Q->getNumEntriesInGlobalRow(r);
    auto K = rcp(new CrsMatrix(Q->getRowMap(), counts()));
    auto rhs = rcp(new MultiVector(Q->getRowMap(), 1)), x = rcp(new MultiVector(Q->getRowMap(), 1));
    auto r = rhs->getDataNonConst(0);
    for (std::size_t row = 0; row < n; ++row) {
      CrsMatrix::nonconst_global_inds_host_view_type cols("c", counts[row]);
      CrsMatrix::nonconst_values_host_view_type vals("v", counts[row]);
      std::size_t count = 0;
      Q->getGlobalRowCopy(row, cols, vals, count);
      r[row] = fixed[row] ? value[row] : b[row];
      for (std::size_t k = 0; k < count; ++k) {
        const GlobalOrdinal col = cols(k);
        if (fixed[row] || fixed[col]) {
          if (!fixed[row]) r[row] -= vals(k) * value[col];
          vals(k) = col == static_cast<GlobalOrdinal>(row) ? 1.0 : 0.0;
        }
      }
      K->insertGlobalValues(row, count, vals.data(), cols.data());
    }
    K->fillComplete();
    solver.factor(K);
    if (!solver.cholesky()) throw Error("activeSetSolve: the system of an active set is not positive definite");
    solver.solve(*rhs, *x);
    {
      auto v = result.v->getDataNonConst();
      auto xd = x->getData(0);
      for (std::size_t i = 0; i < n; ++i) v[i] = xd[i];
    }

    // Multipliers from the rows of the fixed unknowns: (Q v - b)_j + a_i y_i = 0.
    Vector residual(Q->getRangeMap()), Av(qp.A->getRangeMap());
    Q->apply(*result.v, residual);
    residual.update(-1.0, *qp.b, 1.0);
    qp.A->apply(*result.v, Av);
    auto res = residual.getData();
    auto avd = Av.getData();
    bool changed = false;
    long long count = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const double y = active[i] ? -res[unknown[i]] / coefficient[i] : 0.0;
      const char now = y + c * (avd[i] - d[i]) > 0 ? 1 : 0;
      changed |= now != active[i];
      active[i] = now;
      count += now;
    }
    result.iterations = it;
    result.active = count;
    if (!changed) {
      result.converged = true;
      break;
    }
  }
  Vector Qv(Q->getRangeMap());
  Q->apply(*result.v, Qv);
  result.objective = 0.5 * Qv.dot(*result.v) - qp.b->dot(*result.v);
  return result;
}

namespace {

// The displacements of a QP's nodes on rank 0, keyed by the node's coordinates (rounded far
// below the mesh spacing): the rank count renumbers the nodes, not their places. Collective.
std::map<std::array<long long, 3>, std::array<double, 3>> displacementsByPlace(const MultigridInput& multigrid, const Vector& v) {
  const RCP<const Comm> comm = v.getMap()->getComm();
  const bool root = comm->getRank() == 0;
  const auto gatherToRoot = [&](const MultiVector& x) {
    const auto n = static_cast<GlobalOrdinal>(x.getGlobalLength());
    const RCP<const Map> onRoot = rcp(new Map(n, root ? static_cast<std::size_t>(n) : 0, 0, comm));
    MultiVector gathered(onRoot, x.getNumVectors());
    gathered.doImport(x, Import(x.getMap(), onRoot), Tpetra::INSERT);
    return gathered;
  };
  const MultiVector coordinates = gatherToRoot(*multigrid.coordinates), displacements = gatherToRoot(v);
  std::map<std::array<long long, 3>, std::array<double, 3>> byPlace;
  const int dim = multigrid.blockSize;
  for (std::size_t node = 0; node < coordinates.getLocalLength(); ++node) {
    std::array<long long, 3> place{0, 0, 0};
    std::array<double, 3> u{0, 0, 0};
    for (int c = 0; c < dim; ++c) {
      place[c] = std::llround(coordinates.getData(c)[node] * 1e9);
      u[c] = displacements.getData(0)[dim * node + c];
    }
    byPlace[place] = u;
  }
  return byPlace;
}

}  // namespace

double differenceToReference(const Teuchos::ParameterList& problem, const MultigridInput& multigrid, const Vector& v) {
  const auto mine = displacementsByPlace(multigrid, v);
  double difference = 0;
  if (v.getMap()->getComm()->getRank() == 0) {
    Teuchos::ParameterList assembled = problem;
    assembled.set("stiffness: operator", "assembled");  // the reference factors Q
    const AssembledProblem serial = buildSerial(assembled);
    const ReferenceSolution reference = activeSetSolve(serial.qp);
    const auto theirs = displacementsByPlace(serial.multigrid, *reference.v);
    double largest = 0;
    for (const auto& [place, u] : theirs) {
      const auto found = mine.find(place);
      for (int c = 0; c < 3; ++c) {
        largest = std::max(largest, std::abs(u[c]));
        difference = std::max(difference, found == mine.end() ? std::numeric_limits<double>::infinity()
                                                              : std::abs(found->second[c] - u[c]));
      }
    }
    difference = reference.converged && mine.size() == theirs.size()
                     ? difference / std::max(largest, std::numeric_limits<double>::min())
                     : std::numeric_limits<double>::infinity();
  }
  Teuchos::broadcast(*v.getMap()->getComm(), 0, 1, &difference);
  return difference;
}

}  // namespace signorini::testing
