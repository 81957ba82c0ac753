#include "support/ActiveSetReference.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/LocalDirectSolver.hpp"

namespace signorini::testing {

// Each constraint must act on one unknown (a row of A with one entry), as contact
// constraints with an axis-aligned obstacle direction do: then an active constraint fixes
// its unknown, and the system of an active set is Q with those unknowns eliminated
// symmetrically, which is SPD. It is solved by a sparse Cholesky factorization (CHOLMOD).
ReferenceSolution activeSetSolve(const ContactQP& qp, int maxIterations) {
  const auto Q = qp.Qmatrix();
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

}  // namespace signorini::testing
