#include "signorini/solver/ContactQP.hpp"

#include <Tpetra_CrsMatrix.hpp>

namespace signorini {

RCP<const CrsMatrix> ContactQP::Qmatrix() const {
  return Qassembled.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q) : Qassembled;
}

}  // namespace signorini
