#include "solver/preconditioner/JacobiEigenvalueEstimate.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// A pseudo-random value in [-0.5, 0.5) of a global id: Ifpack2's own estimates start from a
// random vector seeded from std::rand's state, so the smoothers, and the truncated Newton
// steps with them, changed from run to run and with the rank count.
double startValue(GlobalOrdinal id) {
  const double t = std::sin(12.9898 * static_cast<double>(id) + 0.5) * 43758.5453;
  return t - std::floor(t) - 0.5;
}

}  // namespace

void JacobiEigenvalueEstimate::allocate(const RCP<const Map>& map) {
  if (!diagonal_.is_null() && diagonal_->getMap()->isSameAs(*map)) return;
  diagonal_ = rcp(new Vector(map, false));
  inverseDiagonal_ = rcp(new Vector(map, false));
  product_ = rcp(new Vector(map, false));
  ritz_ = Teuchos::null;
  graph_ = Teuchos::null;
}

void JacobiEigenvalueEstimate::setDiagonal(const Vector& diagonal) {
  allocate(diagonal.getMap());
  graph_ = Teuchos::null;
  diagonal_->assign(diagonal);
  inverseDiagonal_->reciprocal(*diagonal_);
}

void JacobiEigenvalueEstimate::setMatrix(const CrsMatrix& A) {
  allocate(A.getRowMap());
  if (graph_ != A.getCrsGraph()) {
    graph_ = A.getCrsGraph();
    offsets_ = Offsets(Kokkos::view_alloc(Kokkos::WithoutInitializing, "diagonal offsets"), A.getNodeNumRows());
    graph_->getLocalDiagOffsets(offsets_);
  }
  A.getLocalDiagCopy(*diagonal_, offsets_);
  inverseDiagonal_->reciprocal(*diagonal_);
}

void JacobiEigenvalueEstimate::startFromLast(const CrsMatrix& change) {
  if (ritz_.is_null()) return;
  auto r = ritz_->getDataNonConst();
  const Map& map = *ritz_->getMap();
  std::vector<std::pair<std::size_t, double>> added;
  for (std::size_t row = 0; row < change.getNodeNumRows(); ++row)
    if (change.getNumEntriesInLocalRow(static_cast<LocalOrdinal>(row)) > 0)
      added.emplace_back(row, startValue(map.getGlobalElement(static_cast<LocalOrdinal>(row))));
  const Comm& comm = *map.getComm();
  const double addedSize = std::sqrt(sumOverEntries(comm, added.size(), [&](std::size_t k) {
    return added[k].second * added[k].second;
  }));
  if (addedSize == 0.0) return;
  const double scale = ritz_->norm2() / addedSize;
  for (const auto& [row, value] : added) r[row] += scale * value;
}

double JacobiEigenvalueEstimate::estimate(const Operator& A, int steps) {
  if (diagonal_.is_null()) throw Error("JacobiEigenvalueEstimate::estimate called before setMatrix() or setDiagonal()");
  const auto map = diagonal_->getMap();
  const std::size_t n = map->getNodeNumElements();
  const Comm& comm = *map->getComm();
  if (ritz_.is_null()) {
    ritz_ = rcp(new Vector(map, false));
    auto r = ritz_->getDataNonConst();
    for (std::size_t i = 0; i < n; ++i) r[i] = startValue(map->getGlobalElement(static_cast<LocalOrdinal>(i)));
  }
  // The Lanczos vectors live for this call only: kept, they were the largest part of the
  // hierarchy's memory beside the matrices (15 vectors on the fine level for the first estimate).
  MultiVector basis(map, steps, false);
  const auto d = diagonal_->getData(), dInverse = inverseDiagonal_->getData();
  {  // q_0 = D^-1/2 ritz / ||ritz||: unit length in the D norm
    const double scale = 1.0 / ritz_->norm2();
    const auto r = ritz_->getData();
    auto q = basis.getDataNonConst(0);
    for (std::size_t i = 0; i < n; ++i) q[i] = scale * r[i] / std::sqrt(d[i]);
  }
  std::vector<double> alpha, beta;
  for (int k = 0; k < steps; ++k) {
    const auto q = basis.getVector(k);
    A.apply(*q, *product_);
    alpha.push_back(q->dot(*product_));  // <D^-1 A q, q>_D
    // w = D^-1 A q - alpha q_k - beta q_k-1, written over A q, with its D norm.
    const auto qk = q->getData();
    auto w = product_->getDataNonConst();
    const double a = alpha.back(), b = k > 0 ? beta.back() : 0.0;
    const Teuchos::ArrayRCP<const double> previous = k > 0 ? basis.getData(k - 1) : qk;
    const double wNorm = std::sqrt(std::max(sumOverEntries(comm, n, [&](std::size_t i) {
      w[i] = dInverse[i] * w[i] - a * qk[i] - b * previous[i];
      return d[i] * w[i] * w[i];
    }), 0.0));
    if (k + 1 == steps || wNorm <= 1e-12 * std::abs(a)) break;  // the Krylov space is invariant
    beta.push_back(wNorm);
    auto next = basis.getDataNonConst(k + 1);
    for (std::size_t i = 0; i < n; ++i) next[i] = w[i] / wNorm;
  }
  // Eigenpairs of the Lanczos tridiagonal matrix, ascending.
  const int m = static_cast<int>(alpha.size());
  beta.resize(std::max(m - 1, 1));
  std::vector<double> work(std::max(1, 2 * m - 2)), eigenvectors(m * m);
  int info = 0;
  Teuchos::LAPACK<int, double>().STEQR('I', m, alpha.data(), beta.data(), eigenvectors.data(), m, work.data(), &info);
  if (info != 0) throw Error("JacobiEigenvalueEstimate: the Lanczos tridiagonal eigenvalue problem failed");
  // The Ritz vector of the largest value, scaled by D^1/2.
  auto r = ritz_->getDataNonConst();
  std::fill(r.begin(), r.end(), 0.0);
  for (int k = 0; k < m; ++k) {
    const double s = eigenvectors[(m - 1) * m + k];
    const auto q = basis.getData(k);
    for (std::size_t i = 0; i < n; ++i) r[i] += s * q[i];
  }
  for (std::size_t i = 0; i < n; ++i) r[i] *= std::sqrt(d[i]);
  return alpha.back();
}

double jacobiGershgorinBound(const CrsMatrix& C) {
  Vector rowDiagonal(C.getRowMap()), columnDiagonal(C.getColMap());
  C.getLocalDiagCopy(rowDiagonal);
  const RCP<const Import> importer = C.getCrsGraph()->getImporter();
  if (importer.is_null())
    columnDiagonal.assign(rowDiagonal);
  else
    columnDiagonal.doImport(rowDiagonal, *importer, Tpetra::INSERT);
  const auto local = C.getLocalMatrixHost();
  const auto ofRow = rowDiagonal.getData(), ofColumn = columnDiagonal.getData();
  double bound = 0.0;
  for (LocalOrdinal row = 0; row < static_cast<LocalOrdinal>(local.numRows()); ++row) {
    if (!(ofRow[row] > 0.0)) continue;
    double rowSum = 0.0, scaledSum = 0.0;
    for (auto e = local.graph.row_map(row); e < local.graph.row_map(row + 1); ++e) {
      const double entry = std::fabs(local.values(e)), other = ofColumn[local.graph.entries(e)];
      rowSum += entry;
      if (other > 0.0) scaledSum += entry / std::sqrt(ofRow[row] * other);
    }
    bound = std::max(bound, std::min(rowSum / ofRow[row], scaledSum));
  }
  return maxOverRanks(*C.getComm(), bound);
}

}  // namespace signorini
