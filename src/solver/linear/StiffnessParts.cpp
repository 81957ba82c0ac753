#include "solver/linear/StiffnessParts.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

StiffnessParts::StiffnessParts(const ContactQP& qp, const MultigridInput& multigrid)
    : matrix_(assembledStiffness(qp, multigrid)), stiffness_(Teuchos::rcp_dynamic_cast<const StiffnessOperator>(qp.Q)) {}

void StiffnessParts::require() const {
  if (!available())
    throw InputError("the preconditioner needs Q as an assembled matrix or as a StiffnessOperator");
}

RCP<Vector> StiffnessParts::diagonal() const {
  require();
  if (!matrix_.is_null()) {
    auto d = rcp(new Vector(matrix_->getRowMap()));
    matrix_->getLocalDiagCopy(*d);
    return d;
  }
  auto d = rcp(new Vector(stiffness_->getRangeMap()));
  stiffness_->getLocalDiagCopy(*d);
  return d;
}

std::vector<char> StiffnessParts::prescribedDofs() const {
  require();
  return matrix_.is_null() ? stiffness_->prescribedDofs() : prescribedRows(*matrix_);
}

RCP<const CrsMatrix> StiffnessParts::contactRows(const CrsMatrix& A) const {
  require();
  if (!matrix_.is_null()) return matrix_;
  return stiffness_->selectedRows(*contactDofIndicator(A));
}

std::vector<char> prescribedRows(const CrsMatrix& Q) {
  const auto local = Q.getLocalMatrixHost();
  const Map &rows = *Q.getRowMap(), &columns = *Q.getColMap();
  const auto numRows = static_cast<LocalOrdinal>(local.numRows());
  std::vector<char> prescribed(numRows, 0);
  for (LocalOrdinal row = 0; row < numRows; ++row) {
    const LocalOrdinal self = columns.getLocalElement(rows.getGlobalElement(row));
    bool coupled = false;
    for (auto e = local.graph.row_map(row); e < local.graph.row_map(row + 1) && !coupled; ++e)
      coupled = local.values(e) != 0.0 && local.graph.entries(e) != self;
    prescribed[row] = !coupled;
  }
  return prescribed;
}

RCP<Vector> contactDofIndicator(const CrsMatrix& A) {
  Vector onColumns(A.getColMap());
  {
    const auto a = A.getLocalMatrixHost();
    auto c = onColumns.getDataNonConst();
    for (std::size_t e = 0; e < a.graph.entries.extent(0); ++e) c[a.graph.entries(e)] = 1.0;
  }
  auto onDomain = rcp(new Vector(A.getDomainMap()));
  onDomain->doExport(onColumns, Export(A.getColMap(), A.getDomainMap()), Tpetra::ADD);
  return onDomain;
}

}  // namespace signorini
