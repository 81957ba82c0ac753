#pragma once
// The basis psi of the contact multipliers on one facet of a cell. Nodal constraints and
// weighted gaps both carry one multiplier per node of the contact boundary; for weighted
// gaps, constraint a is the integral of psi_a (g + n_o . u), and its weight, the integral
// of psi_a, must be positive. The P_k functions phi have positive facet integrals except
// the vertex functions of quadratic triangles (P2 tetrahedra), whose integrals vanish:
// there psi_v = phi_v + alpha * sum of phi_e over the facet's edges e at v and
// psi_e = (1 - 2 alpha) phi_e, alpha = 1/5 (the transformed basis of Popp, Gitterle, Gee
// and Wall for quadratic mortar elements). psi spans the same space as phi; elsewhere psi = phi.
#include <vector>

#include "fe/LagrangeBasis.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"

namespace signorini {

class ContactMultiplierBasis {
 public:
  ContactMultiplierBasis(const LagrangeBasis& basis, ContactFormulation formulation);

  // True where psi differs from phi.
  bool transformed() const { return !transform_.empty(); }
  // The coefficient of phi_b in psi_a on local facet f (a, b cell-local node indices).
  double coefficient(int facet, int a, int b) const {
    return transformed() ? transform_[facet][a * size_ + b] : (a == b ? 1.0 : 0.0);
  }
  // psi_a where the cell's P_k functions take the values phi (size() of them).
  double value(int facet, int a, const double* phi) const;

 private:
  int size_;
  std::vector<std::vector<double>> transform_;  // per local facet, size_ x size_; empty: identity
};

}  // namespace signorini
