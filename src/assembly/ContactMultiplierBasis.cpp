#include "assembly/ContactMultiplierBasis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Teuchos_LAPACK.hpp>

#include "fe/ElasticityElement.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {

namespace {

// phi~ on local facet f as rows of a size x size matrix over phi: the identity on the facet's
// nodes, or Popp et al.'s transformed basis for quadratic triangles.
std::vector<double> facetBasis(const LagrangeBasis& basis, int facet, bool transform) {
  constexpr double alpha = 0.2;
  const int size = basis.size();
  const auto& lattice = basis.latticeIndices();
  std::vector<double> T(size * size, 0.0);
  const std::vector<int> nodes = basis.facetNodes(facet);
  for (int a : nodes) T[a * size + a] = 1.0;
  if (!transform) return T;
  for (int e : nodes) {
    int support = 0;
    for (int i = 0; i < 4; ++i) support += lattice[e][i] > 0;
    if (support != 2) continue;  // a vertex
    T[e * size + e] = 1.0 - 2.0 * alpha;
    for (int v : nodes)
      if (v <= basis.dim() && lattice[e][v] > 0) T[v * size + e] = alpha;  // vertex v of edge e
  }
  return T;
}

// The reference cell's facet quadrature, exact for products of two P_k functions.
FacetQuadrature referenceFacetRule(const LagrangeBasis& basis, int facet) {
  const int d = basis.dim();
  std::vector<double> vertices((d + 1) * d, 0.0);
  for (int i = 0; i < d; ++i) vertices[(i + 1) * d + i] = 1.0;
  FacetQuadrature rule;
  facetQuadrature(basis, vertices.data(), facet, 2 * basis.degree(), rule);
  return rule;
}

// psi_a = sum_b (D M^-1)_ab phi~_b over phi, for phi~ = T phi on facet f.
std::vector<double> dualBasis(const LagrangeBasis& basis, int facet, const std::vector<double>& T) {
  const int size = basis.size();
  const std::vector<int> nodes = basis.facetNodes(facet);
  const int k = static_cast<int>(nodes.size());
  const FacetQuadrature rule = referenceFacetRule(basis, facet);
  std::vector<double> M(k * k, 0.0), X(k * size, 0.0), D(k, 0.0), tilde(k);
  for (int q = 0; q < rule.size(); ++q) {
    const double* phi = &rule.phi[q * size];
    for (int i = 0; i < k; ++i) {
      tilde[i] = 0;
      for (int c = 0; c < size; ++c) tilde[i] += T[nodes[i] * size + c] * phi[c];
    }
    for (int i = 0; i < k; ++i) {
      D[i] += rule.weights[q] * tilde[i];
      for (int j = 0; j < k; ++j) M[i + j * k] += rule.weights[q] * tilde[i] * tilde[j];
    }
  }
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < size; ++c) X[i + c * k] = T[nodes[i] * size + c];
  int info = 0;
  Teuchos::LAPACK<int, double>().POSV('L', k, size, M.data(), k, X.data(), k, &info);
  if (info != 0)
    throw Error("dual mortar basis: the facet mass matrix is singular (LAPACK info " + std::to_string(info) + ")");
  std::vector<double> psi(size * size, 0.0);
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < size; ++c) psi[nodes[i] * size + c] = D[i] * X[i + c * k];
  return psi;
}

// Which integrals of psi_a phi_b over facet f are nonzero, on the reference facet.
std::vector<char> couplingPattern(const LagrangeBasis& basis, int facet, const std::vector<double>& psi) {
  const int size = basis.size();
  const std::vector<int> nodes = basis.facetNodes(facet);
  const FacetQuadrature rule = referenceFacetRule(basis, facet);
  std::vector<double> W(size * size, 0.0);
  for (int q = 0; q < rule.size(); ++q) {
    const double* phi = &rule.phi[q * size];
    for (int a : nodes) {
      double psiA = 0;
      for (int c = 0; c < size; ++c) psiA += psi[a * size + c] * phi[c];
      for (int b : nodes) W[a * size + b] += rule.weights[q] * psiA * phi[b];
    }
  }
  std::vector<char> couples(size * size, 0);
  for (int a : nodes) {
    double scale = 0;
    for (int b : nodes) scale = std::max(scale, std::abs(W[a * size + b]));
    for (int b : nodes) couples[a * size + b] = std::abs(W[a * size + b]) > 1e-10 * scale;
  }
  return couples;
}

}  // namespace

ContactMultiplierBasis::ContactMultiplierBasis(const LagrangeBasis& basis, ContactFormulation formulation)
    : size_(basis.size()), biorthogonal_(formulation == ContactFormulation::dualMortar) {
  const bool transform = basis.dim() == 3 && basis.degree() == 2;
  if (formulation == ContactFormulation::nodal || (!transform && !biorthogonal_)) return;
  for (int facet = 0; facet <= basis.dim(); ++facet) {
    std::vector<double> T = facetBasis(basis, facet, transform);
    if (biorthogonal_) {
      T = dualBasis(basis, facet, T);
      couplings_.push_back(couplingPattern(basis, facet, T));
    }
    transform_.push_back(std::move(T));
  }
}

double ContactMultiplierBasis::value(int facet, int a, const double* phi) const {
  if (!transformed()) return phi[a];
  double psi = 0;
  for (int b = 0; b < size_; ++b) psi += transform_[facet][a * size_ + b] * phi[b];
  return psi;
}

}  // namespace signorini
