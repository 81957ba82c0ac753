#pragma once
// Quadrature on the reference simplex (the segment [0,1], the triangle 0,e1,e2 or the
// tetrahedron 0,e1,e2,e3), exact for polynomials up to a given total degree.
#include <vector>

namespace signorini {

struct QuadratureRule {
  int dim = 0;
  std::vector<double> points;   // dim * size(), interleaved
  std::vector<double> weights;  // sum to the reference volume 1/dim!
  int size() const { return static_cast<int>(weights.size()); }
};

// A rule exact for total degree <= degree; any degree >= 0 works. On the triangle and the
// tetrahedron, degree 2 uses fully symmetric rules of 3 and 4 points, degrees 4 and 5 fully
// symmetric degree-5 rules of 7 and 14 points; all others the collapsed Gauss-Jacobi (Stroud conical product) rule with ceil((degree+1)/2)
// points per direction. Weights are positive and points lie strictly inside the simplex.
// Throws InputError for dim outside 1..3 or a negative degree.
QuadratureRule simplexQuadrature(int dim, int degree);

}  // namespace signorini
