#pragma once
// The box [0,L0]x[0,L1](x[0,L2]) cut into `cells` boxes per direction, each box into
// simplices as doc/benchmark-family.md says (the subdivision of makeBoxMesh), seen as a P1
// space: which simplex holds a point, and with which weights the vertex values interpolate
// there. It is the finest geometric multigrid grid of a box mesh; the coarser ones are
// RectilinearGrids.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "signorini/core/GeometricGrid.hpp"

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
  // RectilinearGrid(*this).coarser(): half the boxes per direction (plus one for an odd count).
  std::shared_ptr<const GeometricGrid> coarser() const override;
  std::string description() const override;
};

// The simplices of box (i,j,k) as box corners: corner bit a (x), 2b (y), 4c (z) is the vertex
// (i+a, j+b, k+c). `parity` is (i+j+k) % 2; in 2D it does not matter. Entry dim+1.. unused.
const std::vector<std::array<int, 4>>& boxSimplexCorners(int dim, int parity);

// P1 interpolation at the point xi (box units, in [0,1]^dim) of box `box` of a grid with
// `cells` boxes per direction: the dim + 1 vertices (makeBoxMesh's numbering) of the simplex
// that holds xi, and their weights (>= 0, summing to 1).
void boxSimplexInterpolation(int dim, const std::array<long long, 3>& cells, const long long* box, const double* xi,
                             long long* vertices, double* weights);

}  // namespace signorini
