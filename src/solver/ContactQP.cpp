#include "signorini/solver/ContactQP.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "solver/preconditioner/RigidBodyModes.hpp"

namespace signorini {

RCP<const CrsMatrix> ContactQP::Qmatrix() const {
  return Qassembled.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q) : Qassembled;
}

RCP<const MultiVector> ContactQP::nearNullspace() const {
  if (!nullspace.is_null() || coordinates.is_null()) return nullspace;
  if (static_cast<int>(coordinates->getNumVectors()) != blockSize) return Teuchos::null;
  return rigidBodyModes(Q->getDomainMap(), *coordinates);
}

}  // namespace signorini
