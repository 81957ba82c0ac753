#include "assembly/ContactMultiplierBasis.hpp"

namespace signorini {

ContactMultiplierBasis::ContactMultiplierBasis(const LagrangeBasis& basis, ContactFormulation formulation)
    : size_(basis.size()) {
  if (formulation != ContactFormulation::weightedGap || basis.dim() != 3 || basis.degree() != 2) return;
  constexpr double alpha = 0.2;
  const auto& lattice = basis.latticeIndices();
  for (int facet = 0; facet <= basis.dim(); ++facet) {
    std::vector<double> T(size_ * size_, 0.0);
    const std::vector<int> nodes = basis.facetNodes(facet);
    for (int a : nodes) T[a * size_ + a] = 1.0;
    for (int e : nodes) {
      int support = 0;
      for (int i = 0; i < 4; ++i) support += lattice[e][i] > 0;
      if (support != 2) continue;  // a vertex
      T[e * size_ + e] = 1.0 - 2.0 * alpha;
      for (int v : nodes)
        if (v <= basis.dim() && lattice[e][v] > 0) T[v * size_ + e] = alpha;  // vertex v of edge e
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
