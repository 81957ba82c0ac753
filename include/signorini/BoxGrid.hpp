#pragma once
// The box [0,L0]x[0,L1](x[0,L2]) cut into `cells` boxes per direction, each box into
// simplices as doc/benchmark-family.md says (the subdivision of makeBoxMesh), seen as a P1
// space: which simplex holds a point, and with which weights the vertex values interpolate
// there. The geometric multigrid levels of a box mesh are such grids.
#include <array>
#include <vector>

namespace signorini {

struct BoxGrid {
  int dim = 2;
  std::array<long long, 3> cells = {1, 1, 1};    // entries past dim are ignored
  std::array<double, 3> lengths = {1.0, 1.0, 1.0};

  long long numVertices() const;
  // Vertex (i,j,k) has id i + (n0+1)*(j + (n1+1)*k), makeBoxMesh's numbering.
  void vertexCoordinates(long long vertex, double* x) const;
  // The vertex within 1e-8 cell widths of x in every direction, or -1.
  long long vertexAt(const double* x) const;
  // The dim + 1 vertices of a simplex that holds x (a point outside the box is first moved
  // onto it) and their P1 basis functions at x: weights >= 0 that sum to 1.
  void interpolation(const double* x, long long* vertices, double* weights) const;
  // The grid with half the cells per direction, whose vertices are vertices of this one;
  // it exists when every count is even.
  bool halvable() const;
  BoxGrid halved() const;
};

// The simplices of box (i,j,k) as box corners: corner bit a (x), 2b (y), 4c (z) is the vertex
// (i+a, j+b, k+c). `parity` is (i+j+k) % 2; in 2D it does not matter. Entry dim+1.. unused.
const std::vector<std::array<int, 4>>& boxSimplexCorners(int dim, int parity);

}  // namespace signorini
