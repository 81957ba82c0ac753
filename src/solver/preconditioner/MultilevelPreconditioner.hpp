#pragma once
// A multigrid preconditioner built from an assembled matrix: what the Newton system solver
// needs of MueLu's algebraic hierarchy and of the geometric one alike.
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class MultilevelPreconditioner {
 public:
  virtual ~MultilevelPreconditioner() = default;
  // Builds the hierarchy for A. With `reuse`, a hierarchy built before for a matrix of the
  // same pattern may be refreshed instead of rebuilt.
  virtual void compute(const RCP<CrsMatrix>& A, bool reuse = false) = 0;
  // One cycle, an approximate inverse of the last A computed.
  virtual RCP<Operator> getOperator() const = 0;
};

}  // namespace signorini
