#pragma once
// The largest eigenvalue of D^-1 A (D = diag A, A symmetric positive definite) by Lanczos in
// the D inner product, where D^-1 A is self-adjoint, for a Chebyshev smoother: after k steps
// the largest Ritz value is far closer to it than the power method's Rayleigh quotient (which
// needed 30 steps in 3D), at the same one product with A a step.
//
// It is kept with a level of a multigrid hierarchy whose matrix changes values but not its
// graph from one build to the next: the diagonal's positions in the graph, the diagonal, a
// work vector and the last Ritz vector stay, so a rebuild costs the few steps that update
// the estimate and a handful of passes over the vectors. The Lanczos basis is allocated
// for each estimate and freed after it. The Ritz vector is kept scaled by D^1/2 (an
// eigenvector of D^-1/2 A D^-1/2): so scaled, it still starts the next estimate well after D
// changed by orders of magnitude on some rows, where unscaled it would be those rows alone.
#include <Kokkos_View.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class JacobiEigenvalueEstimate {
 public:
  // Reads A's diagonal (positive on every row); the matrix of every later call has A's row map.
  void setMatrix(const CrsMatrix& A);
  // The same for an operator known by its diagonal (positive on every row).
  void setDiagonal(const Vector& diagonal);

  // The largest Ritz value after `steps` Lanczos steps, for the matrix or operator whose
  // diagonal was last set, from the start chosen below (by default a fresh one). Collective.
  double estimate(const Operator& A, int steps);

  // The next start is a vector that depends on the global row ids alone, so that the
  // estimate is the same on any number of ranks.
  void startFresh() { ritz_ = Teuchos::null; }
  // After A changed in `change`'s rows, the next start is the last Ritz vector plus as much
  // again on those rows, where a new largest eigenvalue would have its eigenvector. Whether
  // there is a last Ritz vector to start from (else the start is a fresh one):
  bool hasRitzVector() const { return !ritz_.is_null(); }
  void startFromLast(const CrsMatrix& change);

  // D^-1 of the matrix last set, on its row map (what Ifpack2's Chebyshev takes as
  // "chebyshev: operator inv diagonal"); the next setMatrix() overwrites it in place.
  RCP<const Vector> inverseDiagonal() const { return inverseDiagonal_; }

 private:
  void allocate(const RCP<const Map>& map);  // the vectors, for rows on `map`
  using Offsets = Kokkos::View<std::size_t*, CrsMatrix::device_type>;
  RCP<const CrsMatrix::crs_graph_type> graph_;  // the graph offsets_ index
  Offsets offsets_;                             // of the diagonal entries in graph_'s rows
  RCP<Vector> diagonal_, inverseDiagonal_, ritz_, product_;
};

// A bound on the eigenvalues of diag(C)^-1 C for a symmetric positive semidefinite C, its
// rows of zeros left out: the smaller of Gershgorin's bounds for that matrix and for the
// similar diag(C)^-1/2 C diag(C)^-1/2. The second is exact for the block a a^T of a
// constraint on one node (the count of a's nonzero components). Collective.
double jacobiGershgorinBound(const CrsMatrix& C);

}  // namespace signorini
