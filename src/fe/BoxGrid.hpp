#pragma once
// The box [0,L0]x[0,L1](x[0,L2]) cut into `cells` boxes per direction, each box into
// simplices as doc/benchmark-family.md says (the subdivision of makeBoxMesh), seen as a P1
// space: which simplex holds a point, and with which weights the vertex values interpolate
// there. The geometric multigrid levels of a box mesh are such grids, each with half the
// cells of the one above.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "signorini/solver/GeometricGrid.hpp"

namespace signorini {

struct BoxGrid : GeometricGrid {
  int dim = 2;
  std::array<long long, 3> cells = {1, 1, 1};    // entries past dim are ignored
  std::array<double, 3> lengths = {1.0, 1.0, 1.0};

  BoxGrid() = default;
  BoxGrid(int dim, const std::array<long long, 3>& cells, const std::array<double, 3>& lengths)
      : dim(dim), cells(cells), lengths(lengths) {}

  int dimension() const override { return dim; }
  long long numVertices() const override;
  // Vertex (i,j,k) has id i + (n0+1)*(j + (n1+1)*k), makeBoxMesh's numbering.
  void vertexCoordinates(long long vertex, double* x) const override;
  // The vertex within 1e-8 cell widths of x in every direction, or -1.
  long long vertexAt(const double* x) const override;
  void interpolation(const double* x, long long* vertices, double* weights) const override;
  // The halved grid, when every count is even.
  std::shared_ptr<const GeometricGrid> coarser() const override;
  std::string description() const override;

  bool halvable() const;
  BoxGrid halved() const;
};

// The simplices of box (i,j,k) as box corners: corner bit a (x), 2b (y), 4c (z) is the vertex
// (i+a, j+b, k+c). `parity` is (i+j+k) % 2; in 2D it does not matter. Entry dim+1.. unused.
const std::vector<std::array<int, 4>>& boxSimplexCorners(int dim, int parity);

}  // namespace signorini
