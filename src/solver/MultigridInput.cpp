#include "signorini/solver/MultigridInput.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Collectives.hpp"
#include "solver/preconditioner/RigidBodyModes.hpp"

namespace signorini {

RCP<const CrsMatrix> assembledStiffness(const ContactQP& qp, const MultigridInput& multigrid) {
  return multigrid.assembledQ.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q) : multigrid.assembledQ;
}

RCP<const MultiVector> MultigridInput::nearNullspace(const ContactQP& qp) const {
  if (!nullspace.is_null() || coordinates.is_null()) return nullspace;
  // The modes need the coordinates' rows to be the nodes of Q's DOFs, blockSize each, on
  // every rank; coordinates laid out otherwise give none.
  const bool aligned = static_cast<int>(coordinates->getNumVectors()) == blockSize &&
                       qp.Q->getDomainMap()->getNodeNumElements() == blockSize * coordinates->getLocalLength();
  if (!onEveryRank(*qp.Q->getDomainMap()->getComm(), aligned)) return Teuchos::null;
  return rigidBodyModes(qp.Q->getDomainMap(), *coordinates);
}

}  // namespace signorini
