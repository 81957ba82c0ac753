#pragma once
// The direct solve of a matrix held on one rank: CHOLMOD's Cholesky factorization
// (SparseCholesky) where the matrix is positive definite, Amesos2's KLU2 LU where it is not.
// Both run on one-rank communicators (Debian's Amesos2 solvers are wrong on more than one
// rank). Why both: the matrices factored here (coarsest multigrid levels, the contact
// subspace of Q + A^T D A) are symmetric positive definite but for a caller's singular or
// indefinite input, which KLU2 still solves where it can.
#include <memory>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class SparseCholesky;

class LocalDirectSolver {
 public:
  LocalDirectSolver();
  ~LocalDirectSolver();
  // A copy keeps the Cholesky ordering and analysis for its next factor() and leaves this
  // one usable; it holds no LU factorization.
  LocalDirectSolver(const LocalDirectSolver& other);
  LocalDirectSolver& operator=(const LocalDirectSolver&) = delete;

  // Factors A: square, symmetric, on a one-rank communicator, every column one of its rows.
  // A matrix whose column map is not its row map is copied onto one that is first; the LU
  // factorization keeps a reference to A or to that copy.
  void factor(const RCP<CrsMatrix>& A);
  // Whether the last factor() gave a Cholesky factor.
  bool cholesky() const;
  // X = A^-1 B for the last A factored (B and X on A's row map).
  void solve(const MultiVector& B, MultiVector& X) const;

 private:
  struct LU;
  std::unique_ptr<SparseCholesky> cholesky_;
  std::unique_ptr<LU> lu_;
};

}  // namespace signorini
