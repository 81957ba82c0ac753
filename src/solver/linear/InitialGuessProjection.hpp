#pragma once
// A starting vector for a Krylov solve of H x = r from the solutions of earlier, related
// systems (P. F. Fischer, "Projection techniques for iterative solution of Ax = b with
// successive right-hand sides", 1998): x0 is the H-orthogonal projection of H^-1 r on the
// span of the last few solutions, the best guess in H's energy norm from that span. H may
// change between systems, as the interior point methods' H = Q + A^T D A does with D: the
// basis is H-orthonormalised anew for every system.
//
// In the interior point methods the Newton systems' right-hand sides keep a large part
// (A^T y of the contact forces) while the solutions shrink with the step; starting CG from
// zero then costs iterations just to rebuild that part, which consecutive solutions share.
// With H = Q + A^T D A, each kept solution u carries Q u, so that H u costs A^T D A u alone
// when D has changed.
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class BarrierHessianOperator;

class InitialGuessProjection {
 public:
  // capacity: how many earlier solutions are kept (0: x0 = 0 always).
  explicit InitialGuessProjection(int capacity);

  // x = the H-orthogonal projection of H^-1 r on span{kept solutions, x if `withX`}; basis
  // vectors that are (numerically) in the span of the ones before them are skipped, the
  // most recent first. Hx, if given, receives H x, a combination of the products the
  // projection computes anyway. Returns how many basis vectors were used. Collective.
  int project(const BarrierHessianOperator& H, const Vector& r, Vector& x, bool withX, Vector* Hx = nullptr) const;

  // Keeps a copy of x and Q x (one application of Q) as the most recent solution, dropping
  // the oldest beyond the capacity.
  void remember(const BarrierHessianOperator& H, const Vector& x);

  int capacity() const { return capacity_; }

 private:
  struct Kept {
    RCP<const Vector> u, Qu;
  };
  int capacity_;
  std::vector<Kept> kept_;  // oldest first
};

}  // namespace signorini
