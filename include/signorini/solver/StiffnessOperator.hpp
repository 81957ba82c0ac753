#pragma once
/// \file
/// A stiffness matrix Q that is applied without being stored (matrix-free), with the few
/// parts of it the preconditioners need: its diagonal, its prescribed DOFs and its rows on
/// the contact DOFs. A ContactQP whose Q is one of these needs no assembled Q for the
/// geometric multigrid (with MultigridInput::gridStiffness for a P_k space, k > 1) and the
/// contact correction.
#include <vector>

#include <Tpetra_Operator.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class StiffnessOperator : public Operator {
 public:
  /// diag(Q) on the owned DOFs (Q's row map). Collective.
  virtual void getLocalDiagCopy(Vector& diagonal) const = 0;

  /// 1 for each owned DOF (in Q's row map order) that is prescribed: its row and column are
  /// those of the identity, as symmetric elimination of a Dirichlet condition leaves them.
  virtual std::vector<char> prescribedDofs() const = 0;

  /// Q's rows at the DOFs where `selected` (on Q's domain map) is nonzero, with all their
  /// columns, as a matrix on Q's row, domain and range maps whose other rows are empty.
  /// Meant for few rows (the contact DOFs). Collective.
  virtual RCP<CrsMatrix> selectedRows(const Vector& selected) const = 0;
};

}  // namespace signorini
