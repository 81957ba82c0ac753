#pragma once
// Uniform refinement of one simplex, in barycentric lattice coordinates: what every cell of a
// mesh refined `levels` times is made of, whatever its shape. A segment splits into 2, a
// triangle into 4 at its edge midpoints, a tetrahedron into 8 by Bey's rule (its four corner
// tetrahedra and the inner octahedron cut along the diagonal between the midpoints of edges
// 02 and 13, children's vertices in Bey's order, so that repeated refinement of a
// tetrahedron makes at most three similarity classes: the quality of the coarse mesh stays).
//
// A lattice point at level l is a = (a_0..a_d), a_i >= 0 integers summing to 2^l: the point
// sum a_i v_i / 2^l of the simplex (v_0..v_d). Every vertex of the level-l cells is such a
// point, and a point of level l + 1 either is one of level l (all a_i even) or the midpoint
// of exactly one edge of the level-l cells: refinement needs no coordinates, and neighbouring
// simplices refined alone agree on their shared facets (red refinement of a triangle is unique).
#include <array>
#include <vector>

namespace signorini {

using LatticePoint = std::array<int, 4>;                  // entries past the dimension are 0
using LatticeSimplex = std::array<LatticePoint, 4>;       // dim + 1 points; entries past dim unused

// The reference dim-simplex (dim 1..3) refined 0..levels times.
class SimplexRefinement {
 public:
  SimplexRefinement(int dim, int levels);

  int dim() const { return dim_; }
  int levels() const { return static_cast<int>(cells_.size()) - 1; }
  // The 2^(level dim) cells of level `level`, as lattice points of that level, positively
  // oriented in the reference simplex (a reflected child of Bey's has its first two vertices
  // swapped here, not in the refinement).
  const std::vector<LatticeSimplex>& cells(int level) const { return cells_[level]; }
  // The distinct vertices of those cells, ascending, and each cell's dim + 1 vertices as
  // indices into them.
  const std::vector<LatticePoint>& points(int level) const { return points_[level]; }
  const std::vector<std::array<int, 4>>& cellPoints(int level) const { return cellPoints_[level]; }
  // For a vertex of the level-`level` cells (level >= 1) that is no point of level - 1, the
  // two points of level - 1 at the ends of the edge it halves; for one that is, that point
  // twice. Throws Error for a point that is no vertex of that level.
  const std::array<LatticePoint, 2>& parents(int level, const LatticePoint& point) const;

 private:
  int dim_;
  std::vector<std::vector<LatticeSimplex>> cells_;
  std::vector<std::vector<LatticePoint>> points_;
  std::vector<std::vector<std::array<int, 4>>> cellPoints_;
  // Per level, the parents of each of points(level), in its order: found by binary search.
  std::vector<std::vector<std::array<LatticePoint, 2>>> parents_;
};

}  // namespace signorini
