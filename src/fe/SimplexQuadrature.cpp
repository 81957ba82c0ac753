#include "fe/SimplexQuadrature.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Teuchos_LAPACK.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Gauss-Jacobi rule with n points on [0,1] for the weight (1-t)^alpha, by Golub-Welsch on
// the recurrence of the Jacobi polynomials P^(alpha,0) on [-1,1].
void gaussJacobi(int n, int alpha, std::vector<double>& t, std::vector<double>& w) {
  const double al = alpha;
  // The symmetric tridiagonal Jacobi matrix: diagonal d, off-diagonal e.
  std::vector<double> d(n), e(std::max(n - 1, 1)), vectors(n * n), work(std::max(2 * n - 2, 1));
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * i + al;  // 2i + alpha + beta with beta = 0
    d[i] = -al / (s + 2.0) * (i == 0 ? 1.0 : al / s);
    if (i + 1 < n) {
      const double m = i + 1.0, sm = 2.0 * m + al;
      e[i] = std::sqrt(4.0 * m * (m + al) * m * (m + al) / (sm * sm * (sm + 1.0) * (sm - 1.0)));
    }
  }
  int info = 0;
  Teuchos::LAPACK<int, double>().STEQR('I', n, d.data(), e.data(), vectors.data(), n, work.data(), &info);
  if (info != 0) throw Error("quadrature: LAPACK dsteqr failed with info = " + std::to_string(info));
  // Total weight of (1-t)^alpha on [0,1] is 1/(alpha+1); eigenvector i is column i.
  const double mass = 1.0 / (al + 1.0);
  t.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    t[i] = 0.5 * (1.0 + d[i]);
    w[i] = mass * vectors[i * n] * vectors[i * n];
  }
}

}  // namespace

QuadratureRule simplexQuadrature(int dim, int degree) {
  if (dim < 1 || dim > 3) throw InputError("simplex quadrature: dimension must be 1, 2 or 3, got " + std::to_string(dim));
  if (degree < 0) throw InputError("simplex quadrature: degree must be >= 0, got " + std::to_string(degree));
  const int n = degree / 2 + 1;
  // Direction j of the collapsed cube carries the weight (1-t)^(dim-1-j) of the collapse.
  std::vector<double> t[3], w[3];
  for (int j = 0; j < dim; ++j) gaussJacobi(n, dim - 1 - j, t[j], w[j]);

  QuadratureRule rule;
  rule.dim = dim;
  int index[3] = {0, 0, 0};
  const int total = dim == 1 ? n : dim == 2 ? n * n : n * n * n;
  for (int p = 0; p < total; ++p) {
    index[0] = p % n;
    index[1] = (p / n) % n;
    index[2] = p / (n * n);
    // x_j = t_j * prod_{l<j} (1 - t_l): the Duffy map of the cube onto the simplex.
    double scale = 1.0, weight = 1.0;
    for (int j = 0; j < dim; ++j) {
      const double tj = t[j][index[j]];
      rule.points.push_back(scale * tj);
      scale *= 1.0 - tj;
      weight *= w[j][index[j]];
    }
    rule.weights.push_back(weight);
  }
  return rule;
}

}  // namespace signorini
