#include "fe/LagrangeBasis.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Points inside, on the boundary of and outside the reference simplex.
const std::vector<std::array<double, 3>> samplePoints = {
    {0.2, 0.3, 0.1}, {0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}, {0.1, 0.05, 0.7}, {1.3, -0.4, 0.2}, {0.33, 0.21, 0.17}};

TEST(LagrangeBasis, RejectsBadInput) {
  EXPECT_THROW(LagrangeBasis(2, 4), InputError);
  EXPECT_THROW(LagrangeBasis(3, 0), InputError);
  EXPECT_THROW(LagrangeBasis(1, 1), InputError);
}

TEST(LagrangeBasis, SizesAndLocalOrder) {
  const int expectedSize[2][3] = {{3, 6, 10}, {4, 10, 20}};
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      EXPECT_EQ(basis.dim(), dim);
      EXPECT_EQ(basis.degree(), k);
      ASSERT_EQ(basis.size(), expectedSize[dim - 2][k - 1]);
      const auto& lattice = basis.latticeIndices();
      for (int node = 0; node < basis.size(); ++node) {
        int sum = 0;
        for (int i = 0; i <= dim; ++i) sum += lattice[node][i];
        EXPECT_EQ(sum, k);
        if (dim == 2) {
          EXPECT_EQ(lattice[node][3], 0);
        }
      }
      for (int v = 0; v <= dim; ++v) {  // vertices first, in vertex order
        std::array<int, 4> a = {0, 0, 0, 0};
        a[v] = k;
        EXPECT_EQ(lattice[v], a);
      }
    }
  // P3 edge nodes follow the vertices, edge by edge, from the edge's first vertex.
  const LagrangeBasis cubic(3, 3);
  const auto& p3 = cubic.latticeIndices();
  EXPECT_EQ(p3[4], (std::array<int, 4>{2, 1, 0, 0}));
  EXPECT_EQ(p3[5], (std::array<int, 4>{1, 2, 0, 0}));
  EXPECT_EQ(p3[6], (std::array<int, 4>{2, 0, 1, 0}));
  EXPECT_EQ(p3[15], (std::array<int, 4>{0, 0, 1, 2}));
  EXPECT_EQ(p3[16], (std::array<int, 4>{1, 1, 1, 0}));
  EXPECT_EQ(p3[19], (std::array<int, 4>{0, 1, 1, 1}));
}

// The split at the nodes tiles the cell: degree^dim simplices of equal volume on the nodes,
// together using every node.
TEST(LagrangeBasis, SubSimplicesTileTheCell) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      const auto simplices = basis.subSimplices();
      int count = 1;
      for (int i = 0; i < dim; ++i) count *= k;
      ASSERT_EQ(static_cast<int>(simplices.size()), count) << dim << "D P" << k;
      const double cellVolume = dim == 2 ? 0.5 : 1.0 / 6.0;
      std::vector<int> uses(basis.size(), 0);
      for (const auto& s : simplices) {
        std::array<std::array<double, 3>, 4> x;
        for (int v = 0; v <= dim; ++v) {
          ASSERT_GE(s[v], 0);
          ASSERT_LT(s[v], basis.size());
          x[v] = basis.referencePoint(s[v]);
          ++uses[s[v]];
        }
        if (dim == 2) {
          EXPECT_EQ(s[3], -1);
        }
        double e[3][3];
        for (int v = 0; v < dim; ++v)
          for (int c = 0; c < 3; ++c) e[v][c] = x[v + 1][c] - x[0][c];
        const double det = dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                                    : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                          e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        EXPECT_NEAR(std::fabs(det) / (dim == 2 ? 2.0 : 6.0), cellVolume / count, 1e-14) << dim << "D P" << k;
      }
      for (int node = 0; node < basis.size(); ++node) EXPECT_GT(uses[node], 0) << dim << "D P" << k << " node " << node;
    }
}

TEST(LagrangeBasis, KroneckerAtNodes) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      std::vector<double> phi(basis.size());
      for (int node = 0; node < basis.size(); ++node) {
        const std::array<double, 3> xi = basis.referencePoint(node);
        for (int j = 0; j < dim; ++j) EXPECT_DOUBLE_EQ(xi[j], double(basis.latticeIndices()[node][j + 1]) / k);
        basis.values(xi.data(), phi.data());
        for (int i = 0; i < basis.size(); ++i)
          EXPECT_NEAR(phi[i], i == node ? 1.0 : 0.0, 1e-14) << "dim " << dim << " k " << k << " phi_" << i;
      }
    }
}

TEST(LagrangeBasis, PartitionOfUnityAndZeroGradientSum) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      std::vector<double> phi(basis.size()), dphi(basis.size() * dim);
      for (const auto& xi : samplePoints) {
        basis.values(xi.data(), phi.data());
        basis.gradients(xi.data(), dphi.data());
        double sum = 0, gradSum[3] = {0, 0, 0};
        for (int i = 0; i < basis.size(); ++i) {
          sum += phi[i];
          for (int j = 0; j < dim; ++j) gradSum[j] += dphi[i * dim + j];
        }
        EXPECT_NEAR(sum, 1.0, 1e-13);
        for (int j = 0; j < dim; ++j) EXPECT_NEAR(gradSum[j], 0.0, 1e-12);
      }
    }
}

// The basis reproduces every polynomial of degree <= k from its nodal values: a k-th power
// of a linear function here.
TEST(LagrangeBasis, ReproducesDegreeKPolynomial) {
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      std::vector<double> phi(basis.size());
      auto p = [&](const double* x) {
        double value = 1.0;
        for (int i = 0; i < k; ++i) value *= x[0] + 2 * x[1] - x[dim - 1] + 0.5;
        return value;
      };
      for (const auto& xi : samplePoints) {
        basis.values(xi.data(), phi.data());
        double interpolant = 0;
        for (int i = 0; i < basis.size(); ++i) interpolant += phi[i] * p(basis.referencePoint(i).data());
        EXPECT_NEAR(interpolant, p(xi.data()), 1e-12);
      }
    }
}

TEST(LagrangeBasis, GradientsMatchFiniteDifferences) {
  const double h = 1e-6;
  for (int dim = 2; dim <= 3; ++dim)
    for (int k = 1; k <= 3; ++k) {
      const LagrangeBasis basis(dim, k);
      const int n = basis.size();
      std::vector<double> dphi(n * dim), plus(n), minus(n);
      for (const auto& xi : samplePoints) {
        basis.gradients(xi.data(), dphi.data());
        for (int j = 0; j < dim; ++j) {
          std::array<double, 3> xp = xi, xm = xi;
          xp[j] += h;
          xm[j] -= h;
          basis.values(xp.data(), plus.data());
          basis.values(xm.data(), minus.data());
          for (int i = 0; i < n; ++i)
            EXPECT_NEAR(dphi[i * dim + j], (plus[i] - minus[i]) / (2 * h), 1e-7)
                << "dim " << dim << " k " << k << " node " << i << " direction " << j;
        }
      }
    }
}

}  // namespace
}  // namespace signorini
