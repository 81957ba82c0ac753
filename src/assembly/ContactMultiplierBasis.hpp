#pragma once
// The basis psi of the contact multipliers on one facet of a cell. Nodal constraints and
// weighted gaps both carry one multiplier per node of the contact boundary; for weighted
// gaps, constraint a is the integral of psi_a (g + n_o . u), and its weight, the integral
// of psi_a, must be positive.
//  weighted gap: psi = phi, the P_k functions, whose facet integrals are positive but for
//    the vertex functions of quadratic triangles (P2 tetrahedra), whose integrals vanish:
//    there psi = phi~, psi_v = phi_v + alpha * sum of phi_e over the facet's edges e at v and
//    psi_e = (1 - 2 alpha) phi_e, alpha = 1/5 (the transformed basis of Popp, Gitterle, Gee
//    and Wall for quadratic mortar elements), which spans the same space.
//  dual mortar: the dual (biorthogonal) basis of phi~ on each facet F (Wohlmuth; Popp et al.
//    for the quadratic case), integral over F of psi_a phi~_b = delta_ab times the integral
//    of phi~_a: psi_a = sum_b (D M^-1)_ab phi~_b with M the facet mass matrix of phi~ and D
//    its row sums. A constraint then holds the displacement of its own node alone (P1, P2
//    segments, P3) or its node's transformed displacement (an edge node of a P2 triangle and
//    the facet's two vertices), and the multiplier is the local mean of the pressure
//    int p phi~_a / int phi~_a, a nodal value that cannot be negative.
// Facets are affine, so the coefficients are those of the reference cell's facets.
#include <vector>

#include "fe/LagrangeBasis.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"

namespace signorini {

class ContactMultiplierBasis {
 public:
  ContactMultiplierBasis(const LagrangeBasis& basis, ContactFormulation formulation);

  // True where psi differs from phi.
  bool transformed() const { return !transform_.empty(); }
  // True for the dual basis: the multipliers are the pressure's nodal values.
  bool biorthogonal() const { return biorthogonal_; }
  // The coefficient of phi_b in psi_a on local facet f (a, b cell-local node indices).
  double coefficient(int facet, int a, int b) const {
    return transformed() ? transform_[facet][a * size_ + b] : (a == b ? 1.0 : 0.0);
  }
  // psi_a where the cell's P_k functions take the values phi (size() of them).
  double value(int facet, int a, const double* phi) const;
  // Whether the integral of psi_a phi_b over facet f can be nonzero (a, b facet nodes): the
  // pattern of constraint a's row. Every pair but for the dual basis.
  bool couples(int facet, int a, int b) const {
    return couplings_.empty() || couplings_[facet][a * size_ + b];
  }

 private:
  int size_;
  bool biorthogonal_ = false;
  std::vector<std::vector<double>> transform_;  // per local facet, size_ x size_; empty: identity
  std::vector<std::vector<char>> couplings_;    // per local facet, size_ x size_; empty: all pairs
};

}  // namespace signorini
