#include "signorini/solver/ContactQP.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Collectives.hpp"
#include "solver/preconditioner/RigidBodyModes.hpp"

namespace signorini {

RCP<const CrsMatrix> ContactQP::Qmatrix() const {
  return Qassembled.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q) : Qassembled;
}

RCP<const MultiVector> ContactQP::nearNullspace() const {
  if (!nullspace.is_null() || coordinates.is_null()) return nullspace;
  // The modes need the coordinates' rows to be the nodes of Q's DOFs, blockSize each, on
  // every rank; coordinates laid out otherwise give none.
  const bool aligned = static_cast<int>(coordinates->getNumVectors()) == blockSize &&
                       Q->getDomainMap()->getNodeNumElements() == blockSize * coordinates->getLocalLength();
  if (!onEveryRank(*Q->getDomainMap()->getComm(), aligned)) return Teuchos::null;
  return rigidBodyModes(Q->getDomainMap(), *coordinates);
}

}  // namespace signorini
