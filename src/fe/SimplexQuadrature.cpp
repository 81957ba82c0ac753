#include "signorini/SimplexQuadrature.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "signorini/Error.hpp"

namespace signorini {
namespace {

// Eigenvalues and eigenvectors of a small symmetric matrix (row-major, n x n) by cyclic
// Jacobi rotations: slow for big matrices, but accurate to rounding, which is what the
// Golub-Welsch weights need, and n here is at most a dozen or so. On return a's diagonal
// holds the eigenvalues, v's columns the eigenvectors.
void symmetricEigen(int n, std::vector<double>& a, std::vector<double>& v) {
  v.assign(n * n, 0.0);
  for (int i = 0; i < n; ++i) v[i * n + i] = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) off += std::fabs(a[i * n + j]);
    if (off == 0.0) return;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0.0) continue;
        // An entry below rounding of both diagonal entries is zero: this ends the sweeps.
        const double g = 100.0 * std::fabs(apq);
        if (std::fabs(a[p * n + p]) + g == std::fabs(a[p * n + p]) &&
            std::fabs(a[q * n + q]) + g == std::fabs(a[q * n + q])) {
          a[p * n + q] = a[q * n + p] = 0.0;
          continue;
        }
        const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        // A <- J^T A J with J the rotation in the (p, q) plane that zeroes a_pq.
        for (int k = 0; k < n; ++k) {
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq;
          a[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk;
          a[q * n + k] = s * apk + c * aqk;
        }
        a[p * n + q] = a[q * n + p] = 0.0;  // zero in exact arithmetic
        for (int k = 0; k < n; ++k) {
          const double vkp = v[k * n + p], vkq = v[k * n + q];
          v[k * n + p] = c * vkp - s * vkq;
          v[k * n + q] = s * vkp + c * vkq;
        }
      }
  }
  throw Error("quadrature: Jacobi eigenvalue iteration did not converge");
}

// Gauss-Jacobi rule with n points on [0,1] for the weight (1-t)^alpha, by Golub-Welsch on
// the recurrence of the Jacobi polynomials P^(alpha,0) on [-1,1].
void gaussJacobi(int n, int alpha, std::vector<double>& t, std::vector<double>& w) {
  const double al = alpha;
  std::vector<double> jacobi(n * n, 0.0), vectors;
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * i + al;  // 2i + alpha + beta with beta = 0
    jacobi[i * n + i] = -al / (s + 2.0) * (i == 0 ? 1.0 : al / s);
    if (i + 1 < n) {
      const double m = i + 1.0, sm = 2.0 * m + al;
      const double b = std::sqrt(4.0 * m * (m + al) * m * (m + al) / (sm * sm * (sm + 1.0) * (sm - 1.0)));
      jacobi[i * n + i + 1] = jacobi[(i + 1) * n + i] = b;
    }
  }
  symmetricEigen(n, jacobi, vectors);
  // Total weight of (1-t)^alpha on [0,1] is 1/(alpha+1).
  const double mass = 1.0 / (al + 1.0);
  t.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    t[i] = 0.5 * (1.0 + jacobi[i * n + i]);
    w[i] = mass * vectors[i] * vectors[i];
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
