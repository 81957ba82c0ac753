#include "fe/LagrangeBasis.hpp"

#include <algorithm>
#include <string>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Local nodes sort by support size (vertices, edges, faces), then support set, then by
// descending lattice index, so edge nodes run from the edge's first vertex to its second.
bool localOrderLess(const std::array<int, 4>& a, const std::array<int, 4>& b) {
  std::array<int, 4> supportA, supportB;  // support indices, padded with 4
  int sizeA = 0, sizeB = 0;
  supportA.fill(4);
  supportB.fill(4);
  for (int i = 0; i < 4; ++i) {
    if (a[i] > 0) supportA[sizeA++] = i;
    if (b[i] > 0) supportB[sizeB++] = i;
  }
  if (sizeA != sizeB) return sizeA < sizeB;
  if (supportA != supportB) return supportA < supportB;
  return a > b;
}

// Factors of the product formula for each barycentric coordinate lambda_i at a point:
// p[i][m] = prod_{j<m} (k*lambda_i - j)/(j+1) and dp[i][m] = d p[i][m] / d lambda_i, m = 0..k.
struct ProductFactors {
  double p[4][LagrangeBasis::maxDegree + 1];
  double dp[4][LagrangeBasis::maxDegree + 1];

  ProductFactors(int dim, int k, const double* xi) {
    double lambda[4] = {1.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < dim; ++j) {
      lambda[j + 1] = xi[j];
      lambda[0] -= xi[j];
    }
    for (int i = 0; i <= dim; ++i) {
      p[i][0] = 1.0;
      dp[i][0] = 0.0;
      for (int m = 1; m <= k; ++m) {
        const double factor = (k * lambda[i] - (m - 1)) / m;
        p[i][m] = p[i][m - 1] * factor;
        dp[i][m] = dp[i][m - 1] * factor + p[i][m - 1] * k / m;
      }
    }
  }
};

}  // namespace

LagrangeBasis::LagrangeBasis(int dim, int degree) : dim_(dim), degree_(degree) {
  if (dim != 2 && dim != 3) throw InputError("Lagrange basis: dimension must be 2 or 3, got " + std::to_string(dim));
  if (degree < 1 || degree > maxDegree)
    throw InputError("Lagrange basis: degree must be 1, 2 or 3, got " + std::to_string(degree));
  // All a with a_1..a_dim >= 0 and a_1 + .. + a_dim <= k; a_0 takes the rest.
  for (int a1 = 0; a1 <= degree; ++a1)
    for (int a2 = 0; a1 + a2 <= degree; ++a2)
      for (int a3 = 0; a1 + a2 + a3 <= degree && (dim == 3 || a3 == 0); ++a3)
        lattice_.push_back({degree - a1 - a2 - a3, a1, a2, a3});
  std::sort(lattice_.begin(), lattice_.end(), localOrderLess);
}

std::array<double, 3> LagrangeBasis::referencePoint(int node) const {
  std::array<double, 3> xi = {0.0, 0.0, 0.0};
  for (int j = 0; j < dim_; ++j) xi[j] = double(lattice_[node][j + 1]) / degree_;
  return xi;
}

void LagrangeBasis::values(const double* xi, double* phi) const {
  const ProductFactors f(dim_, degree_, xi);
  for (int node = 0; node < size(); ++node) {
    const auto& a = lattice_[node];
    double value = 1.0;
    for (int i = 0; i <= dim_; ++i) value *= f.p[i][a[i]];
    phi[node] = value;
  }
}

void LagrangeBasis::gradients(const double* xi, double* dphi) const {
  const ProductFactors f(dim_, degree_, xi);
  for (int node = 0; node < size(); ++node) {
    const auto& a = lattice_[node];
    // Product rule in barycentric coordinates, then lambda_0 = 1 - sum xi, lambda_{j+1} = xi_j.
    double dLambda[4];
    for (int i = 0; i <= dim_; ++i) {
      double d = f.dp[i][a[i]];
      for (int l = 0; l <= dim_; ++l)
        if (l != i) d *= f.p[l][a[l]];
      dLambda[i] = d;
    }
    for (int j = 0; j < dim_; ++j) dphi[node * dim_ + j] = dLambda[j + 1] - dLambda[0];
  }
}

std::vector<int> LagrangeBasis::facetNodes(int facet) const {
  std::vector<int> nodes;
  for (int a = 0; a < size(); ++a)
    if (lattice_[a][facet] == 0) nodes.push_back(a);
  return nodes;
}

// In the coordinates y_i = a_i + .. + a_dim the lattice fills k >= y_1 >= .. >= y_dim >= 0,
// a scaled Kuhn simplex: the Kuhn simplices of the unit cubes inside it (corner p, then
// one step along each axis in the order of a permutation) split it into k^dim congruent
// pieces, with vertices on the lattice.
std::vector<std::array<int, 4>> LagrangeBasis::subSimplices() const {
  const int k = degree_;
  const auto nodeAt = [&](const std::array<int, 3>& y) {
    std::array<int, 4> a = {k - y[0], 0, 0, 0};
    for (int i = 0; i < dim_; ++i) a[i + 1] = y[i] - (i + 1 < dim_ ? y[i + 1] : 0);
    return static_cast<int>(std::find(lattice_.begin(), lattice_.end(), a) - lattice_.begin());
  };
  const auto inside = [&](const std::array<int, 3>& y) {
    for (int i = 0; i < dim_; ++i)
      if (y[i] < (i + 1 < dim_ ? y[i + 1] : 0) || y[i] > (i > 0 ? y[i - 1] : k)) return false;
    return true;
  };
  std::vector<std::array<int, 4>> simplices;
  std::array<int, 3> corner = {0, 0, 0};
  for (corner[0] = 0; corner[0] < k; ++corner[0])
    for (corner[1] = 0; corner[1] < k; ++corner[1])
      for (corner[2] = 0; corner[2] < (dim_ == 3 ? k : 1); ++corner[2]) {
        std::array<int, 3> axes = {0, 1, 2};
        do {
          std::array<int, 4> simplex = {-1, -1, -1, -1};
          std::array<int, 3> y = corner;
          bool keep = inside(y);
          simplex[0] = nodeAt(y);
          for (int s = 0; s < dim_ && keep; ++s) {
            ++y[axes[s]];
            keep = inside(y);
            simplex[s + 1] = nodeAt(y);
          }
          if (keep) simplices.push_back(simplex);
        } while (std::next_permutation(axes.begin(), axes.begin() + dim_));
      }
  return simplices;
}

}  // namespace signorini
