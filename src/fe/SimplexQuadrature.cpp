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

// Adds the points of one symmetry orbit: every distinct permutation of the barycentric
// coordinates `lambda` (dim + 1 of them), each with weight w. Points are the barycentric
// coordinates 1..dim.
void addOrbit(QuadratureRule& rule, std::vector<double> lambda, double w) {
  std::sort(lambda.begin(), lambda.end());
  do {
    rule.points.insert(rule.points.end(), lambda.begin() + 1, lambda.end());
    rule.weights.push_back(w);
  } while (std::next_permutation(lambda.begin(), lambda.end()));
}

// Fully symmetric degree-2 rules (Stroud): 3 points on the triangle and 4 on the
// tetrahedron, where the collapsed rule needs 4 and 8; they integrate P2 gradient products.
QuadratureRule symmetricDegree2Rule(int dim) {
  QuadratureRule rule;
  rule.dim = dim;
  if (dim == 2) {
    addOrbit(rule, {2.0 / 3, 1.0 / 6, 1.0 / 6}, 1.0 / 6);
  } else {
    const double a = (5.0 - std::sqrt(5.0)) / 20.0;
    addOrbit(rule, {a, a, a, 1 - 3 * a}, 1.0 / 24);
  }
  return rule;
}

// Fully symmetric degree-5 rules with positive weights and interior points: Radon's 7-point
// rule on the triangle, and the 14-point rule on the tetrahedron (Walkington, "Quadrature on
// simplices of arbitrary dimension", 2000; also Keast 1986). The collapsed rule of the same
// degree needs 9 and 27 points; loads are integrated with degree 5 on P1 cells.
QuadratureRule symmetricDegree5Rule(int dim) {
  QuadratureRule rule;
  rule.dim = dim;
  if (dim == 2) {
    const double r = std::sqrt(15.0);
    const double a1 = (6.0 - r) / 21.0, a2 = (6.0 + r) / 21.0;
    addOrbit(rule, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 9.0 / 80);
    addOrbit(rule, {a1, a1, 1 - 2 * a1}, (155.0 - r) / 2400);
    addOrbit(rule, {a2, a2, 1 - 2 * a2}, (155.0 + r) / 2400);
  } else {
    const double a1 = 0.092735250310891226402, a2 = 0.31088591926330060980, b = 0.045503704125649649492;
    addOrbit(rule, {a1, a1, a1, 1 - 3 * a1}, 0.012248840519393658257);
    addOrbit(rule, {a2, a2, a2, 1 - 3 * a2}, 0.018781320953002641800);
    addOrbit(rule, {b, b, 0.5 - b, 0.5 - b}, 0.0070910034628469110730);
  }
  return rule;
}

}  // namespace

QuadratureRule simplexQuadrature(int dim, int degree) {
  if (dim < 1 || dim > 3) throw InputError("simplex quadrature: dimension must be 1, 2 or 3, got " + std::to_string(dim));
  if (degree < 0) throw InputError("simplex quadrature: degree must be >= 0, got " + std::to_string(degree));
  if (dim >= 2 && degree == 2) return symmetricDegree2Rule(dim);
  if (dim >= 2 && (degree == 4 || degree == 5)) return symmetricDegree5Rule(dim);
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
