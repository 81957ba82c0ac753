#include "solver/preconditioner/SparseCholesky.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <cholmod.h>
#include <dlfcn.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

struct SparseCholesky::Cholmod {
  Cholmod() {
    cholmod_start(&common);
    common.print = 0;  // failures are reported by status, in an exception
    common.quick_return_if_not_posdef = true;
    // Supernodal pays for its dense-block overhead only on fuller factors than CHOLMOD's
    // default (40 flops per entry of L) assumes: on the family's coarsest matrices, simplicial
    // factors the fastest with 45 flops per entry, supernodal with 105.
    common.supernodal_switch = 80;
  }
  ~Cholmod() {
    freeFactor();
    for (cholmod_dense** d : {&solution, &workY, &workE}) cholmod_free_dense(d, &common);
    cholmod_finish(&common);
  }
  void freeFactor() {
    if (factor) cholmod_free_factor(&factor, &common);
  }
  void check(const char* call) const {
    if (common.status < CHOLMOD_OK)
      throw Error(std::string("SparseCholesky: CHOLMOD's ") + call + " failed (status " +
                  std::to_string(common.status) + ")");
  }

  cholmod_common common;
  cholmod_factor* factor = nullptr;
  // The pattern the factor was analysed for, in CHOLMOD's compressed-column form: a CSR
  // matrix's rows are the columns of its transpose, the same matrix when it is symmetric.
  std::vector<int> columnStart, rowIndex;
  // Solve workspace, reused between solves.
  std::vector<double> rhs;
  cholmod_dense *solution = nullptr, *workY = nullptr, *workE = nullptr;
};

namespace {

// CHOLMOD factors small matrices as L D L^T, which succeeds on indefinite matrices too: their
// D has a pivot <= 0. (The supernodal L L^T stops at the first one, with CHOLMOD_NOT_POSDEF.)
bool positivePivots(const cholmod_factor& L) {
  if (L.is_super || L.is_ll) return true;
  const int* start = static_cast<const int*>(L.p);
  const double* values = static_cast<const double*>(L.x);
  for (std::size_t j = 0; j < L.n; ++j)
    if (!(values[start[j]] > 0.0)) return false;  // D(j) leads column j
  return true;
}

// CHOLMOD's supernodal factorization opens OpenMP parallel regions. Each MPI rank already has
// a core of its own, so the threads only oversubscribe the cores, and on the coarse matrices
// factored here they cost more than they gain. While an object of this class lives, OpenMP
// regions run on one thread (max-active-levels 0); the caller's setting comes back after.
// The OpenMP runtime is the one CHOLMOD loaded, looked up at run time: none, nothing to do.
class OneThreadPerRank {
 public:
  OneThreadPerRank() {
    get_ = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
    set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
    if (!get_ || !set_) return;
    saved_ = get_();
    set_(0);
  }
  ~OneThreadPerRank() {
    if (get_ && set_) set_(saved_);
  }
  OneThreadPerRank(const OneThreadPerRank&) = delete;
  OneThreadPerRank& operator=(const OneThreadPerRank&) = delete;

 private:
  int (*get_)() = nullptr;
  void (*set_)(int) = nullptr;
  int saved_ = 1;
};

}  // namespace

SparseCholesky::SparseCholesky() : cholmod_(std::make_unique<Cholmod>()) {}

SparseCholesky::SparseCholesky(const SparseCholesky& other) : SparseCholesky() {
  Cholmod& c = *cholmod_;
  const Cholmod& from = *other.cholmod_;
  if (!from.factor) return;
  c.factor = cholmod_copy_factor(from.factor, &c.common);
  c.check("copy_factor");
  c.columnStart = from.columnStart;
  c.rowIndex = from.rowIndex;
}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::factor(const CrsMatrix& A) {
  if (A.getRowMap()->getComm()->getSize() != 1)
    throw Error("SparseCholesky: the matrix must be on a one-rank communicator");
  const auto local = A.getLocalMatrixHost();
  const std::size_t n = local.numRows();
  if (local.numCols() != static_cast<LocalOrdinal>(n)) throw Error("SparseCholesky: the matrix is not square");
  if (local.nnz() > std::numeric_limits<int>::max())
    throw Error("SparseCholesky: more nonzeros than CHOLMOD's int indices hold");
  Cholmod& c = *cholmod_;
  const auto& rowMap = local.graph.row_map;
  const auto& entries = local.graph.entries;
  const bool samePattern = c.factor && c.columnStart.size() == n + 1 &&
                           std::equal(c.columnStart.begin(), c.columnStart.end(), rowMap.data()) &&
                           std::equal(c.rowIndex.begin(), c.rowIndex.end(), entries.data());
  if (!samePattern) {
    c.freeFactor();
    c.columnStart.assign(rowMap.data(), rowMap.data() + n + 1);
    c.rowIndex.assign(entries.data(), entries.data() + rowMap(n));
  }
  cholmod_sparse view{};
  view.nrow = view.ncol = n;
  view.nzmax = c.rowIndex.size();
  view.p = c.columnStart.data();
  view.i = c.rowIndex.data();
  view.x = const_cast<double*>(local.values.data());  // read only
  view.stype = 1;  // the upper triangle of the transpose: the lower one of A's rows
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = A.getCrsGraph()->isSorted();
  view.packed = 1;
  const OneThreadPerRank oneThread;
  if (!c.factor) {
    c.factor = cholmod_analyze(&view, &c.common);
    c.check("analyze");
  }
  cholmod_factorize(&view, c.factor, &c.common);
  if (c.common.status != CHOLMOD_NOT_POSDEF) c.check("factorize");
  if (c.common.status == CHOLMOD_NOT_POSDEF || !positivePivots(*c.factor)) {
    c.freeFactor();
    return false;
  }
  return true;
}

void SparseCholesky::solve(const MultiVector& B, MultiVector& X) const {
  Cholmod& c = *cholmod_;
  if (!c.factor) throw Error("SparseCholesky::solve called without a factorization");
  const std::size_t n = B.getLocalLength(), k = B.getNumVectors();
  c.rhs.resize(n * k);
  for (std::size_t j = 0; j < k; ++j) {
    auto column = B.getData(j);
    std::copy(column.begin(), column.end(), c.rhs.begin() + j * n);
  }
  cholmod_dense rhs{};
  rhs.nrow = n;
  rhs.ncol = k;
  rhs.d = n;
  rhs.nzmax = n * k;
  rhs.x = c.rhs.data();
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_solve2(CHOLMOD_A, c.factor, &rhs, nullptr, &c.solution, nullptr, &c.workY, &c.workE, &c.common);
  c.check("solve");
  const double* x = static_cast<const double*>(c.solution->x);
  for (std::size_t j = 0; j < k; ++j) {
    auto column = X.getDataNonConst(j);
    std::copy(x + j * c.solution->d, x + j * c.solution->d + n, column.begin());
  }
}

}  // namespace signorini
