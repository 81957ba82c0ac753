#include "solver/linear/StiffnessParts.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"

namespace signorini {

StiffnessParts::StiffnessParts(const ContactQP& qp)
    : matrix_(qp.Qmatrix()), stiffness_(Teuchos::rcp_dynamic_cast<const StiffnessOperator>(qp.Q)) {}

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
  return matrix_.is_null() ? stiffness_->prescribedDofs() : GeometricMultigridPreconditioner::prescribedRows(*matrix_);
}

RCP<const CrsMatrix> StiffnessParts::contactRows(const CrsMatrix& A) const {
  require();
  if (!matrix_.is_null()) return matrix_;
  return stiffness_->selectedRows(*contactDofIndicator(A));
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
