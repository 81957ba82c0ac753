#include "fe/ElasticityElement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Distorted cells, one of them negatively oriented.
const std::vector<std::vector<double>> triangles = {{0.1, 0.2, 1.3, 0.4, 0.5, 1.1}, {0.1, 0.2, 0.5, 1.1, 1.3, 0.4}};
const std::vector<std::vector<double>> tetrahedra = {{0.1, 0.2, 0.0, 1.2, 0.1, 0.3, 0.3, 1.1, 0.2, 0.2, 0.4, 0.9},
                                                     {0.1, 0.2, 0.0, 1.2, 0.1, 0.3, 0.2, 0.4, 0.9, 0.3, 1.1, 0.2}};

const std::vector<std::vector<double>>& cellsOfDim(int dim) { return dim == 2 ? triangles : tetrahedra; }

double cellVolume(int dim, const std::vector<double>& x) {
  double e[3][3];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) e[i][j] = x[(i + 1) * dim + j] - x[j];
  if (dim == 2) return std::fabs(e[0][0] * e[1][1] - e[0][1] * e[1][0]) / 2;
  return std::fabs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                   e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
         6;
}

// Physical position of each local node: sum_i a_i x_i / k.
std::vector<double> nodePositions(const LagrangeBasis& basis, const std::vector<double>& x) {
  const int d = basis.dim();
  std::vector<double> p(basis.size() * d, 0.0);
  for (int node = 0; node < basis.size(); ++node)
    for (int i = 0; i <= d; ++i)
      for (int j = 0; j < d; ++j) p[node * d + j] += basis.latticeIndices()[node][i] * x[i * d + j] / basis.degree();
  return p;
}

// Nodal values of u(x) = B x + c.
std::vector<double> linearField(const LagrangeBasis& basis, const std::vector<double>& x, const double B[3][3],
                                const double* c) {
  const int d = basis.dim();
  const std::vector<double> p = nodePositions(basis, x);
  std::vector<double> u(basis.size() * d);
  for (int node = 0; node < basis.size(); ++node)
    for (int r = 0; r < d; ++r) {
      u[node * d + r] = c[r];
      for (int s = 0; s < d; ++s) u[node * d + r] += B[r][s] * p[node * d + s];
    }
  return u;
}

// Rigid body modes: translations and infinitesimal rotations.
std::vector<std::vector<double>> rigidModes(const LagrangeBasis& basis, const std::vector<double>& x) {
  const int d = basis.dim();
  std::vector<std::vector<double>> modes;
  const double zero[3] = {0, 0, 0};
  for (int r = 0; r < d; ++r) {
    double c[3] = {0, 0, 0};
    c[r] = 1;
    const double B[3][3] = {};
    modes.push_back(linearField(basis, x, B, c));
  }
  const int rotations = d == 2 ? 1 : 3;
  for (int axis = 0; axis < rotations; ++axis) {
    double B[3][3] = {};
    const int i = d == 2 ? 0 : (axis + 1) % 3, j = d == 2 ? 1 : (axis + 2) % 3;
    B[i][j] = -1;
    B[j][i] = 1;
    modes.push_back(linearField(basis, x, B, zero));
  }
  return modes;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

std::vector<double> multiply(const std::vector<double>& K, const std::vector<double>& u) {
  const std::size_t n = u.size();
  std::vector<double> y(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) y[i] += K[i * n + j] * u[j];
  return y;
}

// Eigenvalues of a symmetric matrix by cyclic Jacobi rotations.
std::vector<double> eigenvalues(std::vector<double> a, int n) {
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off = 0, total = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? total : off) += a[i * n + j] * a[i * n + j];
    if (off <= 1e-30 * total) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (a[p * n + q] == 0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2 * a[p * n + q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
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
      }
  }
  std::vector<double> lambda(n);
  for (int i = 0; i < n; ++i) lambda[i] = a[i * n + i];
  std::sort(lambda.begin(), lambda.end());
  return lambda;
}

TEST(IsotropicMaterial, LameParameters) {
  IsotropicMaterial m;
  m.youngsModulus = 2.0;
  m.poissonRatio = 0.25;
  EXPECT_DOUBLE_EQ(m.lame1(), 2.0 * 0.25 / (1.25 * 0.5));
  EXPECT_DOUBLE_EQ(m.lame2(), 2.0 / 2.5);
  EXPECT_DOUBLE_EQ(m.effectiveLame1(3), m.lame1());
  EXPECT_DOUBLE_EQ(m.effectiveLame1(2), m.lame1());
  m.planeStrain = false;
  EXPECT_DOUBLE_EQ(m.effectiveLame1(2), 2.0 * 0.25 / (1 - 0.25 * 0.25));
  EXPECT_DOUBLE_EQ(m.effectiveLame1(3), m.lame1());
  m.poissonRatio = 0.5;
  EXPECT_THROW(m.lame1(), InputError);
  m.poissonRatio = 0.3;
  m.youngsModulus = 0;
  EXPECT_THROW(m.lame2(), InputError);
}

TEST(ElasticityElement, RigidBodyModesInKernel) {
  const IsotropicMaterial material;
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      for (const auto& x : cellsOfDim(dim)) {
        std::vector<double> Ke;
        elasticityStiffness(basis, x.data(), material, Ke);
        const int n = dim * basis.size();
        ASSERT_EQ(static_cast<int>(Ke.size()), n * n);
        double norm = 0;
        for (double v : Ke) norm += v * v;
        norm = std::sqrt(norm);
        for (const auto& mode : rigidModes(basis, x)) {
          const std::vector<double> y = multiply(Ke, mode);
          EXPECT_LT(std::sqrt(dot(y, y)), 1e-12 * norm * std::sqrt(dot(mode, mode))) << "dim " << dim << " k " << k;
        }
      }
    }
}

TEST(ElasticityElement, SymmetricPositiveSemidefiniteWithRigidKernel) {
  const IsotropicMaterial material;
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      for (const auto& x : cellsOfDim(dim)) {
        std::vector<double> Ke;
        elasticityStiffness(basis, x.data(), material, Ke);
        const int n = dim * basis.size();
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) ASSERT_EQ(Ke[i * n + j], Ke[j * n + i]);
        const std::vector<double> lambda = eigenvalues(Ke, n);
        const double largest = lambda.back();
        const int kernel = dim == 2 ? 3 : 6;
        EXPECT_GT(lambda.front(), -1e-12 * largest);
        EXPECT_LT(lambda[kernel - 1], 1e-12 * largest) << "dim " << dim << " k " << k;
        EXPECT_GT(lambda[kernel], 1e-6 * largest) << "dim " << dim << " k " << k;
      }
    }
}

// Patch test: for u = B x + c the discrete strain energy is the exact one, volume * sigma:eps / 2.
TEST(ElasticityElement, PatchTestStrainEnergy) {
  const double B[3][3] = {{0.3, -0.7, 0.2}, {0.4, 0.1, -0.5}, {0.6, 0.25, -0.2}};
  const double c[3] = {0.5, -1.0, 2.0};
  for (const bool planeStrain : {true, false})
    for (int dim = 2; dim <= 3; ++dim)
      for (int k = 1; k <= 3; ++k) {
        IsotropicMaterial material;
        material.youngsModulus = 3.0;
        material.poissonRatio = 0.3;
        material.planeStrain = planeStrain;
        const LagrangeBasis basis(dim, k);
        const double lambda = material.effectiveLame1(dim), mu = material.lame2();
        double eps[3][3], trace = 0;
        for (int i = 0; i < dim; ++i) {
          for (int j = 0; j < dim; ++j) eps[i][j] = 0.5 * (B[i][j] + B[j][i]);
          trace += eps[i][i];
        }
        double energyDensity = 0;  // sigma:eps / 2
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j)
            energyDensity += 0.5 * (2 * mu * eps[i][j] + (i == j ? lambda * trace : 0)) * eps[i][j];
        for (const auto& x : cellsOfDim(dim)) {
          std::vector<double> Ke;
          elasticityStiffness(basis, x.data(), material, Ke);
          const std::vector<double> u = linearField(basis, x, B, c);
          const double expected = cellVolume(dim, x) * energyDensity;
          EXPECT_NEAR(0.5 * dot(u, multiply(Ke, u)), expected, 1e-12 * expected) << "dim " << dim << " k " << k;

          // The stress of that field, anywhere in the cell.
          const double xi[3] = {0.2, 0.3, 0.1};
          double sigma[9];
          cellStress(basis, x.data(), material, u.data(), xi, sigma);
          for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j)
              EXPECT_NEAR(sigma[i * dim + j], 2 * mu * eps[i][j] + (i == j ? lambda * trace : 0), 1e-12);
        }
      }
}

// A load given point by point (f(x, value) writes dim components) as the element routines
// take it: all points at once, component by component.
PointLoad pointwise(int dim, std::function<void(const double* x, double* value)> f) {
  return [dim, f](int count, const double* x, double* values) {
    for (int q = 0; q < count; ++q) {
      double value[3];
      f(x + dim * q, value);
      for (int c = 0; c < dim; ++c) values[c * count + q] = value[c];
    }
  };
}

TEST(ElasticityElement, BodyForceLoad) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      for (const auto& x : cellsOfDim(dim)) {
        const double volume = cellVolume(dim, x);
        std::vector<double> Fe;
        // Constant f: the loads add up to f * volume.
        const double f0[3] = {1.5, -2.0, 0.5};
        bodyForceLoad(basis, x.data(), pointwise(dim, [&](const double*, double* f) { std::copy(f0, f0 + 3, f); }), k, Fe);
        ASSERT_EQ(static_cast<int>(Fe.size()), dim * basis.size());
        for (int c = 0; c < dim; ++c) {
          double sum = 0;
          for (int a = 0; a < basis.size(); ++a) sum += Fe[dim * a + c];
          EXPECT_NEAR(sum, f0[c] * volume, 1e-14);
        }
        // f = x_0 e_c: the loads add up to volume * centroid_0, and against the nodal x_1 they
        // give the integral of x_0 x_1 (x_1 lies in P_k), which the vertex formula knows.
        bodyForceLoad(basis, x.data(), pointwise(dim, [&](const double* p, double* f) { std::fill(f, f + dim, p[0]); }), k + 1,
                      Fe);
        const std::vector<double> nodes = nodePositions(basis, x);
        double centroid0 = 0, sumXX = 0, sum = 0, moment = 0;
        for (int i = 0; i <= dim; ++i) centroid0 += x[i * dim] / (dim + 1);
        for (int i = 0; i <= dim; ++i)
          for (int j = 0; j <= dim; ++j) sumXX += x[i * dim] * x[j * dim + 1] * (i == j ? 2 : 1);
        const double exactMoment = volume * sumXX / ((dim + 1) * (dim + 2));
        for (int a = 0; a < basis.size(); ++a) {
          sum += Fe[dim * a];
          moment += Fe[dim * a + 1] * nodes[a * dim + 1];
        }
        EXPECT_NEAR(sum, volume * centroid0, 1e-14);
        EXPECT_NEAR(moment, exactMoment, 1e-13);
      }
    }
}

TEST(ElasticityElement, FacetTractionLoad) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      for (const auto& x : cellsOfDim(dim))
        for (int facet = 0; facet <= dim; ++facet) {
          // The facet's measure and centroid from its vertices.
          std::vector<int> vs;
          for (int v = 0; v <= dim; ++v)
            if (v != facet) vs.push_back(v);
          double area, centroid[3] = {0, 0, 0};
          for (int v : vs)
            for (int j = 0; j < dim; ++j) centroid[j] += x[v * dim + j] / dim;
          if (dim == 2) {
            area = std::hypot(x[vs[1] * 2] - x[vs[0] * 2], x[vs[1] * 2 + 1] - x[vs[0] * 2 + 1]);
          } else {
            double e[2][3];
            for (int m = 0; m < 2; ++m)
              for (int j = 0; j < 3; ++j) e[m][j] = x[vs[m + 1] * 3 + j] - x[vs[0] * 3 + j];
            area = 0.5 * std::sqrt(std::pow(e[0][1] * e[1][2] - e[0][2] * e[1][1], 2) +
                                   std::pow(e[0][2] * e[1][0] - e[0][0] * e[1][2], 2) +
                                   std::pow(e[0][0] * e[1][1] - e[0][1] * e[1][0], 2));
          }
          std::vector<double> Fe;
          const double t0[3] = {-0.5, 2.0, 1.25};
          facetTractionLoad(basis, x.data(), facet, pointwise(dim, [&](const double*, double* t) { std::copy(t0, t0 + 3, t); }),
                            k, Fe);
          ASSERT_EQ(static_cast<int>(Fe.size()), dim * basis.size());
          for (int c = 0; c < dim; ++c) {
            double sum = 0;
            for (int a = 0; a < basis.size(); ++a) {
              sum += Fe[dim * a + c];
              if (basis.latticeIndices()[a][facet] > 0) {
                EXPECT_EQ(Fe[dim * a + c], 0.0);  // node off the facet
              }
            }
            EXPECT_NEAR(sum, t0[c] * area, 1e-14) << "dim " << dim << " k " << k << " facet " << facet;
          }
          // A linear traction sums to area * its value at the facet centroid.
          auto linear = [&](const double* p) { return 1.0 + 2.0 * p[0] - p[1] + (dim == 3 ? 0.5 * p[2] : 0.0); };
          facetTractionLoad(basis, x.data(), facet,
                            pointwise(dim, [&](const double* p, double* t) { std::fill(t, t + dim, linear(p)); }), k + 1,
                            Fe);
          double sum = 0;
          for (int a = 0; a < basis.size(); ++a) sum += Fe[dim * a + dim - 1];
          EXPECT_NEAR(sum, area * linear(centroid), 1e-13);
        }
      std::vector<double> Fe;
      EXPECT_THROW(facetTractionLoad(basis, cellsOfDim(dim)[0].data(), dim + 1,
                                     pointwise(dim, [](const double*, double* t) { t[0] = t[1] = t[2] = 0; }), 1, Fe),
                   Error);
    }
}

TEST(ElasticityElement, DegenerateCellThrows) {
  const LagrangeBasis basis(2, 1);
  const double flat[6] = {0, 0, 1, 1, 2, 2};
  std::vector<double> Ke;
  EXPECT_THROW(elasticityStiffness(basis, flat, IsotropicMaterial(), Ke), Error);
}

}  // namespace
}  // namespace signorini
