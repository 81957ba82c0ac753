#pragma once
// Contact multipliers that balance the load along the rigid body motions only the contact
// holds. For such a motion f, Q f = 0, so f^T r_d = f^T (A^T y - b) whatever v: the part of
// the load along f that the multipliers do not balance can only be taken by moving the body
// along f against the barrier terms. Started out of balance, the primal-dual method takes
// Newton steps along f far longer than the slacks allow, and the fraction-to-boundary rule cuts
// them to nothing, or collapses the contact onto the constraint that closes first. Started in
// balance, the linear residual f^T r_d only shrinks (by 1 - alpha a step, up to the Krylov
// residual), and the body moves by what the contact's stiffness and gaps say.
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

// Rescales y > 0 (on A's range map) to y_i exp((G' z)_i), G'_i = a_i F / |a_i| the motion of
// constraint i under the free motions F (orthonormal columns on A's domain map), with the z
// that makes (A F)^T y = F^T b, the load's resultant along F. z minimises the convex
// sum_i |a_i| y_i exp((G' z)_i) - z^T F^T b, by Newton's method: the smallest change of the
// forces |a_i| y_i in the relative-entropy sense that balances the load, whatever the rows'
// scaling (a weighted gap's is its facets' measure). Returns
// false, leaving y as it was, where no positive y balances the load (it pulls the body off a
// motion no constraint resists, or has no component along F and needs y = 0 there).
// Collective; costs one application of A to F.
bool balanceLoadAlongFreeMotions(const CrsMatrix& A, const Vector& b, const MultiVector& F, Vector& y);

}  // namespace signorini::detail
