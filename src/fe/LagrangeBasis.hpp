#pragma once
// Continuous Lagrange basis of degree k (1..3) on the reference simplex with vertices
// 0, e1, e2(, e3). Its nodes are the barycentric lattice points a = (a0..ad), sum a = k, at
// point sum a_i v_i / k (a_i weighs vertex i; vertex 0 is the origin).
#include <array>
#include <vector>

namespace signorini {

class LagrangeBasis {
 public:
  static constexpr int maxDegree = 3;
  static constexpr int maxSize = 20;  // P3 on a tetrahedron

  // Throws InputError unless dim is 2 or 3 and degree is 1..3.
  LagrangeBasis(int dim, int degree);

  int dim() const { return dim_; }
  int degree() const { return degree_; }
  int size() const { return static_cast<int>(lattice_.size()); }  // number of local nodes

  // Lattice index a of each local node (entries past dim are 0). Local order: the dim + 1
  // vertices in vertex order, then edge nodes (edge by edge, walking from the lower-numbered
  // vertex), then face nodes; within a group the support sets ascend lexicographically.
  const std::vector<std::array<int, 4>>& latticeIndices() const { return lattice_; }

  // The local nodes on the facet opposite vertex `facet` (lattice weight 0 there), ascending.
  std::vector<int> facetNodes(int facet) const;

  // The cell split at its nodes into degree^dim simplices (Freudenthal's subdivision of the
  // lattice), each as its dim + 1 local nodes (entries past dim are -1). Degree 1: the cell.
  std::vector<std::array<int, 4>> subSimplices() const;

  // Reference coordinates of a local node (entries past dim are 0).
  std::array<double, 3> referencePoint(int node) const;

  // size() values at reference point xi (dim coordinates).
  void values(const double* xi, double* phi) const;
  // size() * dim derivatives, dphi[i * dim + j] = d phi_i / d xi_j.
  void gradients(const double* xi, double* dphi) const;

 private:
  int dim_;
  int degree_;
  std::vector<std::array<int, 4>> lattice_;
};

}  // namespace signorini
