#include "solver/preconditioner/LocalDirectSolver.hpp"

#include <vector>

#include <Amesos2.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/SparseCholesky.hpp"

namespace signorini {

struct LocalDirectSolver::LU {
  RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver;
};

LocalDirectSolver::LocalDirectSolver() : cholesky_(std::make_unique<SparseCholesky>()) {}

LocalDirectSolver::LocalDirectSolver(const LocalDirectSolver& other)
    : cholesky_(std::make_unique<SparseCholesky>(*other.cholesky_)) {}

LocalDirectSolver::~LocalDirectSolver() = default;

namespace {

// A with its row map as column map. Both factorizations need it: SparseCholesky reads local
// column indices as row indices, and Amesos2 13.2's KLU2 solves wrongly with another column
// map even on one rank.
RCP<CrsMatrix> withRowsAsColumns(const RCP<CrsMatrix>& A) {
  const RCP<const Map> rows = A->getRowMap(), columns = A->getColMap();
  if (columns->isSameAs(*rows)) return A;
  auto copy = rcp(new CrsMatrix(rows, rows, A->getNodeMaxNumRowEntries()));
  std::vector<LocalOrdinal> cols;
  for (LocalOrdinal row = 0; row < static_cast<LocalOrdinal>(rows->getNodeNumElements()); ++row) {
    CrsMatrix::local_inds_host_view_type indices;
    CrsMatrix::values_host_view_type values;
    A->getLocalRowView(row, indices, values);
    cols.resize(indices.extent(0));
    for (std::size_t k = 0; k < cols.size(); ++k) {
      cols[k] = rows->getLocalElement(columns->getGlobalElement(indices(k)));
      if (cols[k] == Teuchos::OrdinalTraits<LocalOrdinal>::invalid())
        throw Error("LocalDirectSolver: a column of the matrix is not one of its rows");
    }
    copy->insertLocalValues(row, Teuchos::ArrayView<const LocalOrdinal>(cols),
                            Teuchos::ArrayView<const Scalar>(values.data(), values.extent(0)));
  }
  copy->fillComplete(A->getDomainMap(), A->getRangeMap());
  return copy;
}

}  // namespace

void LocalDirectSolver::factor(const RCP<CrsMatrix>& matrix) {
  lu_.reset();
  const RCP<CrsMatrix> A = withRowsAsColumns(matrix);
  if (cholesky_->factor(*A)) return;
  lu_ = std::make_unique<LU>();
  lu_->solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", A);
  lu_->solver->symbolicFactorization().numericFactorization();
}

bool LocalDirectSolver::cholesky() const { return !lu_; }

void LocalDirectSolver::solve(const MultiVector& B, MultiVector& X) const {
  if (lu_)
    lu_->solver->solve(Teuchos::ptrFromRef(X), Teuchos::ptrFromRef(B));
  else
    cholesky_->solve(B, X);
}

}  // namespace signorini
