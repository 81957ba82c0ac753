#pragma once
// A multigrid preconditioner built from an assembled matrix: what the Newton system solver
// needs of MueLu's algebraic hierarchy and of the geometric one alike.
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class MultilevelPreconditioner {
 public:
  virtual ~MultilevelPreconditioner() = default;
  // Builds the hierarchy for A. With `reuse`, a hierarchy built before for a matrix of the
  // same pattern may be refreshed instead of rebuilt.
  virtual void compute(const RCP<CrsMatrix>& A, bool reuse = false) = 0;
  // A, the matrix of the last build, had `change` (the entries that changed, by how much, on
  // A's row map) added to its values in place: the hierarchy is updated for it. By default
  // this is compute(A, reuse).
  virtual void update(const RCP<CrsMatrix>& A, const CrsMatrix& change, bool reuse = false) {
    (void)change;
    compute(A, reuse);
  }
  // One cycle, an approximate inverse of the last A computed.
  virtual RCP<Operator> getOperator() const = 0;
  // The entries of each level's matrix in the last build, finest first, the levels of a
  // coarse solver that is a hierarchy itself included; empty where there are no levels.
  // Collective.
  virtual std::vector<long long> levelNonzeros() const { return {}; }
};

}  // namespace signorini
