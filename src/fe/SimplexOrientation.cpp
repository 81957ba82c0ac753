#include "fe/SimplexOrientation.hpp"

#include <algorithm>
#include <cmath>

namespace signorini {
namespace {

// Signed measure times dim! of the simplex.
double signedDeterminant(int dim, const double* x) {
  if (dim == 2) return (x[2] - x[0]) * (x[5] - x[1]) - (x[4] - x[0]) * (x[3] - x[1]);
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = x[3 * (r + 1) + c] - x[c];
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

double longestEdge(int dim, const double* x) {
  double longest = 0;
  for (int i = 0; i <= dim; ++i)
    for (int j = i + 1; j <= dim; ++j) {
      double squared = 0;
      for (int c = 0; c < dim; ++c) squared += (x[dim * i + c] - x[dim * j + c]) * (x[dim * i + c] - x[dim * j + c]);
      longest = std::max(longest, std::sqrt(squared));
    }
  return longest;
}

}  // namespace

int simplexOrientation(int dim, const double* x) {
  const double det = signedDeterminant(dim, x);
  if (!(std::abs(det) > 1e-12 * std::pow(longestEdge(dim, x), dim))) return 0;
  return det > 0 ? 1 : -1;
}

}  // namespace signorini
