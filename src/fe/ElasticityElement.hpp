#pragma once
// Element matrices and vectors of isotropic linear elasticity for vector valued P_k on one
// simplex with straight sides. Local dof ordering: dim * localNode + component. The cell is
// given by vertexCoords, its (dim + 1) vertices with dim coordinates each, in cell order.
#include <functional>
#include <vector>

#include "fe/LagrangeBasis.hpp"
#include "signorini/fe/IsotropicMaterial.hpp"

namespace signorini {

// Stiffness matrix, (dim * n)^2 row-major with n = basis.size(): exactly integrated, exactly
// symmetric. Reference gradient products are tabulated once per (dim, degree), so a call
// costs O(n^2 dim^3) and allocates nothing once Ke has its size.
void elasticityStiffness(const LagrangeBasis& basis, const double* vertexCoords, const IsotropicMaterial& material,
                         std::vector<double>& Ke);

// The inverse of the Jacobian J = d x / d xi of the cell's affine map, row-major
// (inverse[s * dim + c] = d xi_s / d x_c), and |det J|. Throws Error for a degenerate cell.
double inverseJacobian(int dim, const double* vertexCoords, double* inverse);

// A load density at the points of a quadrature rule: load(count, x, f) gets count points of
// dim coordinates each, one after the other, and writes component c at point q into
// f[c * count + q] (component by component, so that each can be evaluated in bulk).
using PointLoad = std::function<void(int count, const double* x, double* f)>;

// Fe_(dim a + c) = integral over the cell of f_c phi_a, with a rule exact for total degree
// quadratureDegree.
void bodyForceLoad(const LagrangeBasis& basis, const double* vertexCoords, const PointLoad& force, int quadratureDegree,
                   std::vector<double>& Fe);

// Fe_(dim a + c) = integral over local facet localFacet (opposite local vertex localFacet)
// of t_c phi_a, with the facet's true surface measure. Fe has the size of the whole cell's
// vector; nodes off the facet get 0.
void facetTractionLoad(const LagrangeBasis& basis, const double* vertexCoords, int localFacet,
                       const PointLoad& traction, int quadratureDegree, std::vector<double>& Fe);

// Cauchy stress sigma = lambda tr(eps) I + 2 mu eps at reference point xi, from the cell's local
// displacement dofs: the full symmetric dim x dim tensor, row-major (in-plane part in 2D).
// Lumped mass of local facet f (opposite local vertex f) by diagonal scaling (Hinton, Rock
// and Zienkiewicz): w_a = |facet| M_aa / trace(M), M the facet's consistent mass matrix.
// Positive on the facet's nodes for every degree (the row sums are not: P2 vertices of a
// triangle get 0), zero elsewhere; the weights sum to the facet's measure.
void facetLumpedMass(const LagrangeBasis& basis, const double* vertexCoords, int localFacet, std::vector<double>& w);

void cellStress(const LagrangeBasis& basis, const double* vertexCoords, const IsotropicMaterial& material,
                const double* localDisplacement, const double* xi, double* sigma);

// A quadrature rule on local facet f of one cell, exact for polynomials of total degree
// `degree` on the facet: physical points (dim coordinates each), weights carrying the
// facet's true measure, and the values of all basis.size() functions at each point (zero
// for nodes off the facet).
struct FacetQuadrature {
  std::vector<double> points, weights, phi;
  int size() const { return static_cast<int>(weights.size()); }
};
void facetQuadrature(const LagrangeBasis& basis, const double* vertexCoords, int localFacet, int degree,
                     FacetQuadrature& rule);

}  // namespace signorini
