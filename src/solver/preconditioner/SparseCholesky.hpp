#pragma once
// The Cholesky factorization of a symmetric positive definite matrix held on one rank, by
// SuiteSparse's CHOLMOD (fill-reducing ordering, supernodal where it pays). Why: the coarsest
// multigrid level is refactored at every Newton step, and KLU2's left-looking LU of a 3D grid
// takes several times longer than a Cholesky factorization with a nested-dissection ordering.
// The ordering and the symbolic analysis are kept while the sparsity pattern stays the same.
#include <memory>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  // A copy keeps the ordering and analysis for the next factor() and leaves this one usable.
  SparseCholesky(const SparseCholesky& other);
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factors A: square, on a one-rank communicator, its local column indices those of its
  // rows; only the entries on and below the diagonal are read (A is taken as symmetric).
  // Returns false, and keeps no factor, if A is not numerically positive definite.
  bool factor(const CrsMatrix& A);
  // X = A^-1 B for the last A factored (B and X on A's row map).
  void solve(const MultiVector& B, MultiVector& X) const;

 private:
  struct Cholmod;
  std::unique_ptr<Cholmod> cholmod_;
};

}  // namespace signorini
