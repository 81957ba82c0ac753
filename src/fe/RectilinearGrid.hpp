#pragma once
// A box cut into boxes by one increasing list of vertex coordinates per axis, each box
// subdivided into simplices as makeBoxMesh subdivides its boxes, seen as a P1 space. These
// are the coarse geometric multigrid levels of a box mesh: coarsening keeps every other
// vertex line of each axis and its last one, so an odd count of boxes still coarsens, into
// boxes of twice the width and one of the old width at the far end. The vertices of the
// coarser grid are vertices of this one.
#include <memory>
#include <string>
#include <vector>

#include "signorini/core/GeometricGrid.hpp"

namespace signorini {

struct BoxGrid;

class RectilinearGrid : public GeometricGrid {
 public:
  // The grid with the vertices of `grid`.
  explicit RectilinearGrid(const BoxGrid& grid);
  // One list per axis, each strictly increasing with at least two entries. Throws Error.
  explicit RectilinearGrid(std::vector<std::vector<double>> coordinates);

  int dimension() const override { return static_cast<int>(coordinates_.size()); }
  long long numVertices() const override;
  // Vertex (i,j,k) has id i + (n0+1)*(j + (n1+1)*k), makeBoxMesh's numbering.
  void vertexCoordinates(long long vertex, double* x) const override;
  // The vertex within 1e-8 of the adjacent boxes' width of x in every direction, or -1.
  long long vertexAt(const double* x) const override;
  void interpolation(const double* x, long long* vertices, double* weights) const override;
  // The coarsened grid; null when every axis has a single box.
  std::shared_ptr<const GeometricGrid> coarser() const override;
  std::string description() const override;

  // Boxes along `axis`.
  long long cells(int axis) const { return static_cast<long long>(coordinates_[axis].size()) - 1; }
  // Every other vertex line of each axis, and the last one.
  RectilinearGrid coarsened() const;

 private:
  std::vector<std::vector<double>> coordinates_;
};

}  // namespace signorini
