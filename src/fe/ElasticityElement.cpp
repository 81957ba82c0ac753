#include "fe/ElasticityElement.hpp"

#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "fe/SimplexQuadrature.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// x = origin + J xi, the affine map of the reference simplex onto the cell.
struct AffineMap {
  int dim;
  double origin[3] = {0, 0, 0};
  double jacobian[3][3] = {};  // jacobian[r][s] = d x_r / d xi_s
  double inverse[3][3] = {};   // inverse[s][c] = d xi_s / d x_c
  double det = 0;

  AffineMap(int d, const double* vertexCoords) : dim(d) {
    for (int r = 0; r < d; ++r) {
      origin[r] = vertexCoords[r];
      for (int s = 0; s < d; ++s) jacobian[r][s] = vertexCoords[(s + 1) * d + r] - vertexCoords[r];
    }
    const auto& J = jacobian;
    if (d == 2) {
      det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      inverse[0][0] = J[1][1];
      inverse[0][1] = -J[0][1];
      inverse[1][0] = -J[1][0];
      inverse[1][1] = J[0][0];
    } else {
      for (int i = 0; i < 3; ++i)  // adjugate: cofactors of the transpose
        for (int j = 0; j < 3; ++j) {
          const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
          inverse[i][j] = J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1];
        }
      det = J[0][0] * inverse[0][0] + J[0][1] * inverse[1][0] + J[0][2] * inverse[2][0];
    }
    if (!(std::fabs(det) > 0)) throw Error("elasticity element: degenerate cell (zero Jacobian)");
    const double inverseDet = 1.0 / det;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) inverse[i][j] *= inverseDet;
  }

  void map(const double* xi, double* x) const {
    for (int r = 0; r < dim; ++r) {
      x[r] = origin[r];
      for (int s = 0; s < dim; ++s) x[r] += jacobian[r][s] * xi[s];
    }
  }
};

void requireElasticityDim(const LagrangeBasis& basis) {
  if (basis.dim() != 2 && basis.dim() != 3)
    throw InputError("elasticity element: dimension must be 2 or 3, got " + std::to_string(basis.dim()));
}

// R[((a n + b) dim + r) dim + s] = integral over the reference simplex of
// d phi_a / d xi_r * d phi_b / d xi_s. With an affine map, the physical stiffness follows from
// R by transforming with J^-1, so no quadrature is needed per cell.
std::vector<double> referenceGradientProducts(int dim, int degree) {
  const LagrangeBasis basis(dim, degree);
  const int n = basis.size();
  const QuadratureRule rule = simplexQuadrature(dim, 2 * (degree - 1));
  std::vector<double> R(n * n * dim * dim, 0.0), dphi(n * dim);
  for (int q = 0; q < rule.size(); ++q) {
    basis.gradients(&rule.points[q * dim], dphi.data());
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int r = 0; r < dim; ++r)
          for (int s = 0; s < dim; ++s)
            R[((a * n + b) * dim + r) * dim + s] += rule.weights[q] * dphi[a * dim + r] * dphi[b * dim + s];
  }
  return R;
}

const std::vector<double>& gradientProducts(const LagrangeBasis& basis) {
  // All six (dim, degree) tables at once, in a thread-safe static initialiser.
  static const std::array<std::vector<double>, 6> tables = [] {
    std::array<std::vector<double>, 6> t;
    for (int dim = 2; dim <= 3; ++dim)
      for (int degree = 1; degree <= LagrangeBasis::maxDegree; ++degree)
        t[(dim - 2) * 3 + degree - 1] = referenceGradientProducts(dim, degree);
    return t;
  }();
  return tables[(basis.dim() - 2) * 3 + basis.degree() - 1];
}

// Ke from the reference gradient products R of n basis functions, with lambda and mu already
// scaled by the cell volume. Templated on the dimension, and the D-trip loops unrolled by
// pragma: -O2 does not unroll them itself, and these short loops are most of the element's work.
template <int D>
void stiffnessFromGradientProducts(int n, const double* R, const double (&Jinv)[3][3], double lambda, double mu,
                                   double* Ke) {
  const int size = D * n;
  for (int a = 0; a < n; ++a)
    for (int b = a; b < n; ++b) {
      // M[c][e] = integral of d phi_a/d x_c d phi_b/d x_e = (J^-T R_ab J^-1)[c][e].
      const double* Rab = R + (a * n + b) * D * D;
      double RJ[D][D], M[D][D];
#pragma GCC unroll 3
      for (int r = 0; r < D; ++r)
#pragma GCC unroll 3
        for (int e = 0; e < D; ++e) {
          RJ[r][e] = 0;
#pragma GCC unroll 3
          for (int s = 0; s < D; ++s) RJ[r][e] += Rab[r * D + s] * Jinv[s][e];
        }
      double trace = 0;
#pragma GCC unroll 3
      for (int c = 0; c < D; ++c) {
#pragma GCC unroll 3
        for (int e = 0; e < D; ++e) {
          M[c][e] = 0;
#pragma GCC unroll 3
          for (int r = 0; r < D; ++r) M[c][e] += Jinv[r][c] * RJ[r][e];
        }
        trace += M[c][c];
      }
      // a(phi_b e_e, phi_a e_c) = lambda M[c][e] + mu M[e][c] + mu delta_ce tr M; set both
      // triangles from one value so Ke is symmetric to the last bit.
#pragma GCC unroll 3
      for (int c = 0; c < D; ++c)
#pragma GCC unroll 3
        for (int e = (a == b ? c : 0); e < D; ++e) {
          const double value = lambda * M[c][e] + mu * M[e][c] + (c == e ? mu * trace : 0.0);
          const int row = D * a + c, col = D * b + e;
          Ke[row * size + col] = value;
          Ke[col * size + row] = value;
        }
    }
}

// Quadrature points (reference cell coordinates), weights and basis values, on the
// reference cell (facet -1) or on one of its facets (weights of the reference facet).
struct LoadTabulation {
  std::vector<double> points;
  std::vector<double> weights;
  std::vector<double> phi;  // size() * basis.size()
  int size() const { return static_cast<int>(weights.size()); }
};

LoadTabulation tabulateLoad(const LagrangeBasis& basis, int quadratureDegree, int facet) {
  const int d = basis.dim();
  LoadTabulation tab;
  if (facet < 0) {
    QuadratureRule rule = simplexQuadrature(d, quadratureDegree);
    tab.points = std::move(rule.points);
    tab.weights = std::move(rule.weights);
  } else {
    // The facet's vertices w_0..w_{d-1} (all but `facet`); xi = w_0 + sum_j eta_j (w_{j+1} - w_0).
    double w[3][3] = {};
    for (int v = 0, m = 0; v <= d; ++v)
      if (v != facet) {
        if (v > 0) w[m][v - 1] = 1.0;  // reference vertex v is e_v, vertex 0 the origin
        ++m;
      }
    const QuadratureRule rule = simplexQuadrature(d - 1, quadratureDegree);
    tab.weights = rule.weights;
    for (int q = 0; q < rule.size(); ++q)
      for (int s = 0; s < d; ++s) {
        double xi = w[0][s];
        for (int j = 0; j + 1 < d; ++j) xi += rule.points[q * (d - 1) + j] * (w[j + 1][s] - w[0][s]);
        tab.points.push_back(xi);
      }
  }
  const int n = basis.size();
  tab.phi.resize(tab.size() * n);
  for (int q = 0; q < tab.size(); ++q) {
    basis.values(&tab.points[q * d], &tab.phi[q * n]);
    // Functions of nodes off the facet vanish on it: make that exact, not 1e-17.
    for (int a = 0; facet >= 0 && a < n; ++a)
      if (basis.latticeIndices()[a][facet] > 0) tab.phi[q * n + a] = 0.0;
  }
  return tab;
}

// Tabulations are cached, as loads are assembled cell by cell with the same few rules.
const LoadTabulation& loadTabulation(const LagrangeBasis& basis, int quadratureDegree, int facet) {
  static std::mutex mutex;
  static std::map<std::array<int, 4>, LoadTabulation> cache;  // node-based: references stay valid
  const std::array<int, 4> key = {basis.dim(), basis.degree(), quadratureDegree, facet};
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, tabulateLoad(basis, quadratureDegree, facet)).first;
  return it->second;
}

// Fe_(dim a + c) = scale * sum_q w_q f_c(x_q) phi_a(xi_q), with f evaluated at all points of
// the rule in one call.
void integrateLoad(const LagrangeBasis& basis, const AffineMap& map, const LoadTabulation& tab, double scale,
                   const PointLoad& f, std::vector<double>& Fe) {
  const int d = basis.dim(), n = basis.size(), count = tab.size();
  thread_local std::vector<double> x, value;  // no allocation per cell
  x.resize(static_cast<std::size_t>(count) * d);
  value.assign(static_cast<std::size_t>(count) * d, 0.0);
  for (int q = 0; q < count; ++q) map.map(&tab.points[q * d], &x[q * d]);
  f(count, x.data(), value.data());
  Fe.assign(d * n, 0.0);
  for (int q = 0; q < count; ++q) {
    const double weight = scale * tab.weights[q];
    for (int a = 0; a < n; ++a) {
      const double wphi = weight * tab.phi[q * n + a];
      for (int c = 0; c < d; ++c) Fe[d * a + c] += wphi * value[c * count + q];
    }
  }
}

// Surface measure factor of local facet f: the (d-1)-volume spanned by the facet's edge
// vectors from its first vertex (length in 2D, twice the area in 3D, matching the reference
// facet's weights).
double facetMeasure(int d, const double* vertexCoords, int localFacet) {
  double edge[2][3] = {};
  const double* first = nullptr;
  for (int v = 0, m = 0; v <= d; ++v) {
    if (v == localFacet) continue;
    const double* x = vertexCoords + v * d;
    if (!first) {
      first = x;
      continue;
    }
    for (int j = 0; j < d; ++j) edge[m][j] = x[j] - first[j];
    ++m;
  }
  if (d == 2) return std::hypot(edge[0][0], edge[0][1]);
  const double cx = edge[0][1] * edge[1][2] - edge[0][2] * edge[1][1];
  const double cy = edge[0][2] * edge[1][0] - edge[0][0] * edge[1][2];
  const double cz = edge[0][0] * edge[1][1] - edge[0][1] * edge[1][0];
  return std::sqrt(cx * cx + cy * cy + cz * cz);
}

}  // namespace

double IsotropicMaterial::lame1() const {
  lame2();  // validates E and nu
  return youngsModulus * poissonRatio / ((1.0 + poissonRatio) * (1.0 - 2.0 * poissonRatio));
}

double IsotropicMaterial::lame2() const {
  if (!(youngsModulus > 0))
    throw InputError("material: Young's modulus must be > 0, got " + std::to_string(youngsModulus));
  if (!(poissonRatio > -1.0 && poissonRatio < 0.5))
    throw InputError("material: Poisson ratio must lie in (-1, 0.5), got " + std::to_string(poissonRatio));
  return youngsModulus / (2.0 * (1.0 + poissonRatio));
}

double IsotropicMaterial::effectiveLame1(int dim) const {
  const double lambda = lame1(), mu = lame2();
  return dim == 2 && !planeStrain ? 2.0 * lambda * mu / (lambda + 2.0 * mu) : lambda;
}

double inverseJacobian(int dim, const double* vertexCoords, double* inverse) {
  if (dim != 2 && dim != 3) throw InputError("elasticity element: dimension must be 2 or 3, got " + std::to_string(dim));
  const AffineMap map(dim, vertexCoords);
  for (int s = 0; s < dim; ++s)
    for (int c = 0; c < dim; ++c) inverse[s * dim + c] = map.inverse[s][c];
  return std::fabs(map.det);
}

void elasticityStiffness(const LagrangeBasis& basis, const double* vertexCoords, const IsotropicMaterial& material,
                         std::vector<double>& Ke) {
  requireElasticityDim(basis);
  const int d = basis.dim(), size = d * basis.size();
  const AffineMap map(d, vertexCoords);
  const double volume = std::fabs(map.det);
  const double lambda = volume * material.effectiveLame1(d), mu = volume * material.lame2();
  Ke.resize(size * size);
  if (d == 2)
    stiffnessFromGradientProducts<2>(basis.size(), gradientProducts(basis).data(), map.inverse, lambda, mu, Ke.data());
  else
    stiffnessFromGradientProducts<3>(basis.size(), gradientProducts(basis).data(), map.inverse, lambda, mu, Ke.data());
}

void bodyForceLoad(const LagrangeBasis& basis, const double* vertexCoords, const PointLoad& force, int quadratureDegree,
                   std::vector<double>& Fe) {
  requireElasticityDim(basis);
  const AffineMap map(basis.dim(), vertexCoords);
  integrateLoad(basis, map, loadTabulation(basis, quadratureDegree, -1), std::fabs(map.det), force, Fe);
}

void facetTractionLoad(const LagrangeBasis& basis, const double* vertexCoords, int localFacet,
                       const PointLoad& traction, int quadratureDegree,
                       std::vector<double>& Fe) {
  requireElasticityDim(basis);
  const int d = basis.dim();
  if (localFacet < 0 || localFacet > d)
    throw Error("facet traction: local facet must be 0.." + std::to_string(d) + ", got " + std::to_string(localFacet));
  const AffineMap map(d, vertexCoords);
  const double measure = facetMeasure(d, vertexCoords, localFacet);
  integrateLoad(basis, map, loadTabulation(basis, quadratureDegree, localFacet), measure, traction, Fe);
}

void cellStress(const LagrangeBasis& basis, const double* vertexCoords, const IsotropicMaterial& material,
                const double* localDisplacement, const double* xi, double* sigma) {
  requireElasticityDim(basis);
  const int d = basis.dim(), n = basis.size();
  const AffineMap map(d, vertexCoords);
  double dphi[LagrangeBasis::maxSize * 3];
  basis.gradients(xi, dphi);
  // grad u[c][e] = sum_a u_(d a + c) d phi_a / d x_e, with d/dx_e = sum_s (J^-1)[s][e] d/dxi_s.
  double gradU[3][3] = {};
  for (int a = 0; a < n; ++a)
    for (int e = 0; e < d; ++e) {
      double dphidx = 0;
      for (int s = 0; s < d; ++s) dphidx += dphi[a * d + s] * map.inverse[s][e];
      for (int c = 0; c < d; ++c) gradU[c][e] += localDisplacement[d * a + c] * dphidx;
    }
  const double lambda = material.effectiveLame1(d), mu = material.lame2();
  double trace = 0;
  for (int c = 0; c < d; ++c) trace += gradU[c][c];
  for (int c = 0; c < d; ++c)
    for (int e = 0; e < d; ++e)
      sigma[c * d + e] = mu * (gradU[c][e] + gradU[e][c]) + (c == e ? lambda * trace : 0.0);
}

void facetLumpedMass(const LagrangeBasis& basis, const double* vertexCoords, int localFacet, std::vector<double>& w) {
  const int d = basis.dim(), n = basis.size();
  if (localFacet < 0 || localFacet > d)
    throw Error("facet mass: local facet must be 0.." + std::to_string(d) + ", got " + std::to_string(localFacet));
  const LoadTabulation& tab = loadTabulation(basis, 2 * basis.degree(), localFacet);
  const double measure = facetMeasure(d, vertexCoords, localFacet);
  std::vector<double> diagonal(n, 0.0);
  double area = 0, trace = 0;
  for (int q = 0; q < tab.size(); ++q) {
    area += measure * tab.weights[q];
    for (int a = 0; a < n; ++a) diagonal[a] += measure * tab.weights[q] * tab.phi[q * n + a] * tab.phi[q * n + a];
  }
  for (double m : diagonal) trace += m;
  w.assign(n, 0.0);
  for (int a = 0; a < n; ++a) w[a] = area * diagonal[a] / trace;
}

void facetQuadrature(const LagrangeBasis& basis, const double* vertexCoords, int localFacet, int degree,
                     FacetQuadrature& rule) {
  requireElasticityDim(basis);
  const int d = basis.dim();
  if (localFacet < 0 || localFacet > d)
    throw Error("facet quadrature: local facet must be 0.." + std::to_string(d) + ", got " + std::to_string(localFacet));
  const LoadTabulation& tab = loadTabulation(basis, degree, localFacet);
  const AffineMap map(d, vertexCoords);
  const double measure = facetMeasure(d, vertexCoords, localFacet);
  rule.points.resize(d * tab.size());
  rule.weights.resize(tab.size());
  for (int q = 0; q < tab.size(); ++q) {
    map.map(&tab.points[q * d], &rule.points[q * d]);
    rule.weights[q] = measure * tab.weights[q];
  }
  rule.phi = tab.phi;
}

}  // namespace signorini
