#pragma once
// What the preconditioners and scale estimates read of the stiffness Q besides its action:
// its diagonal, its prescribed DOFs and its rows on the contact DOFs, taken from Q assembled
// (assembledStiffness()) or, when Q is matrix-free, from its StiffnessOperator.
#include <vector>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"
#include "signorini/solver/StiffnessOperator.hpp"

namespace signorini {

class StiffnessParts {
 public:
  StiffnessParts(const ContactQP& qp, const MultigridInput& multigrid);

  // Whether Q is assembled or a StiffnessOperator (else nothing below is available).
  bool available() const { return !matrix_.is_null() || !stiffness_.is_null(); }

  // diag(Q) on Q's row map. Collective.
  RCP<Vector> diagonal() const;
  // 1 per owned DOF that is prescribed (a unit row and column).
  std::vector<char> prescribedDofs() const;
  // A matrix on Q's row map whose rows at the DOFs that A's rows use are Q's (Q itself when
  // assembled; only those rows when matrix-free). Collective.
  RCP<const CrsMatrix> contactRows(const CrsMatrix& A) const;

 private:
  RCP<const CrsMatrix> matrix_;
  RCP<const StiffnessOperator> stiffness_;
  void require() const;
};

// 1 for each owned row of Q with a diagonal entry only, as symmetric elimination leaves a
// Dirichlet DOF.
std::vector<char> prescribedRows(const CrsMatrix& Q);

// 1 on the DOFs (of A's domain map) that a row of A uses. Collective.
RCP<Vector> contactDofIndicator(const CrsMatrix& A);

}  // namespace signorini
