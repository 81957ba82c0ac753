#include "support/ActiveSetReference.hpp"

#include <Amesos2.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace signorini::testing {

ReferenceSolution activeSetSolve(const ContactQP& qp, int maxIterations) {
  const auto Q = qp.Qmatrix();
  const auto comm = Q->getComm();
  const std::size_t n = Q->getGlobalNumRows(), m = qp.A->getGlobalNumRows();
  const double c = Q->getFrobeniusNorm() / std::sqrt(static_cast<double>(n));  // balances y and A v - d

  std::vector<double> y(m, 0.0), Av(m, 0.0);
  auto d = qp.d->getData();
  std::vector<char> active(m, 0);
  ReferenceSolution result;
  result.v = rcp(new Vector(Q->getDomainMap()));

  for (int it = 1; it <= maxIterations; ++it) {
    // KKT system of the active set: [Q A_act^T; A_act 0] [v; y_act] = [b; d_act].
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < m; ++i)
      if (active[i]) rows.push_back(i);
    const std::size_t size = n + rows.size();
    auto map = rcp(new Map(size, 0, comm));
    auto K = rcp(new CrsMatrix(map, 0));
    for (std::size_t r = 0; r < n; ++r) {
      CrsMatrix::nonconst_global_inds_host_view_type cols("c", Q->getNumEntriesInGlobalRow(r));
      CrsMatrix::nonconst_values_host_view_type vals("v", cols.extent(0));
      std::size_t count = 0;
      Q->getGlobalRowCopy(r, cols, vals, count);
      K->insertGlobalValues(r, count, vals.data(), cols.data());
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      CrsMatrix::nonconst_global_inds_host_view_type cols("c", qp.A->getNumEntriesInGlobalRow(rows[k]));
      CrsMatrix::nonconst_values_host_view_type vals("v", cols.extent(0));
      std::size_t count = 0;
      qp.A->getGlobalRowCopy(rows[k], cols, vals, count);
      const GlobalOrdinal row = n + k;
      K->insertGlobalValues(row, count, vals.data(), cols.data());
      for (std::size_t j = 0; j < count; ++j) K->insertGlobalValues(cols(j), 1, &vals(j), &row);
    }
    K->fillComplete();
    auto rhs = rcp(new MultiVector(map, 1)), x = rcp(new MultiVector(map, 1));
    {
      auto r = rhs->getDataNonConst(0);
      auto b = qp.b->getData();
      for (std::size_t i = 0; i < n; ++i) r[i] = b[i];
      for (std::size_t k = 0; k < rows.size(); ++k) r[n + k] = d[rows[k]];
    }
    auto solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", K, x, rhs);
    solver->symbolicFactorization().numericFactorization().solve();

    auto xd = x->getData(0);
    {
      auto v = result.v->getDataNonConst();
      for (std::size_t i = 0; i < n; ++i) v[i] = xd[i];
    }
    std::fill(y.begin(), y.end(), 0.0);
    // Q v - b + A^T y = 0 with y >= 0 (y = -lambda in the paper's sign).
    for (std::size_t k = 0; k < rows.size(); ++k) y[rows[k]] = xd[n + k];
    Vector AvVec(qp.A->getRangeMap());
    qp.A->apply(*result.v, AvVec);
    auto avd = AvVec.getData();
    bool changed = false;
    long long count = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const char now = y[i] + c * (avd[i] - d[i]) > 0 ? 1 : 0;
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
