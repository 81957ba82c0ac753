#include "fe/SimplexRefinement.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

LatticePoint sum(const LatticePoint& a, const LatticePoint& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]};
}

// The children of one simplex, as points of the next level: corners x_i = 2 v_i, edge
// midpoints x_ij = v_i + v_j.
std::vector<LatticeSimplex> children(int dim, const LatticeSimplex& parent) {
  LatticePoint x[4][4];
  for (int i = 0; i <= dim; ++i)
    for (int j = 0; j <= dim; ++j) x[i][j] = sum(parent[i], parent[j]);
  switch (dim) {
    case 1:
      return {{x[0][0], x[0][1]}, {x[0][1], x[1][1]}};
    case 2:
      return {{x[0][0], x[0][1], x[0][2]},
              {x[0][1], x[1][1], x[1][2]},
              {x[0][2], x[1][2], x[2][2]},
              {x[0][1], x[1][2], x[0][2]}};
    default:  // Bey's order
      return {{x[0][0], x[0][1], x[0][2], x[0][3]}, {x[0][1], x[1][1], x[1][2], x[1][3]},
              {x[0][2], x[1][2], x[2][2], x[2][3]}, {x[0][3], x[1][3], x[2][3], x[3][3]},
              {x[0][1], x[0][2], x[0][3], x[1][3]}, {x[0][1], x[0][2], x[1][2], x[1][3]},
              {x[0][2], x[0][3], x[1][3], x[2][3]}, {x[0][2], x[1][2], x[1][3], x[2][3]}};
  }
}

// The simplex with vertices 0 and 1 swapped if it is reflected: barycentric points are
// Cartesian ones (a_1..a_d) of the reference simplex, which is positively oriented.
LatticeSimplex oriented(int dim, LatticeSimplex cell) {
  double m[3][3] = {};
  for (int v = 1; v <= dim; ++v)
    for (int c = 0; c < dim; ++c) m[v - 1][c] = cell[v][c + 1] - cell[0][c + 1];
  const double det = dim == 1   ? m[0][0]
                     : dim == 2 ? m[0][0] * m[1][1] - m[0][1] * m[1][0]
                                : m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (det < 0) std::swap(cell[0], cell[1]);
  return cell;
}

}  // namespace

SimplexRefinement::SimplexRefinement(int dim, int levels) : dim_(dim) {
  if (dim < 1 || dim > 3) throw InputError("simplex refinement: dimension must be 1, 2 or 3, got " + std::to_string(dim));
  if (levels < 0) throw InputError("simplex refinement: levels must be >= 0, got " + std::to_string(levels));
  LatticeSimplex reference{};
  for (int i = 0; i <= dim; ++i) reference[i][i] = 1;
  std::vector<LatticeSimplex> bey{reference};  // the cells of a level in Bey's order, to refine
  cells_.push_back(bey);
  std::vector<std::map<LatticePoint, std::array<LatticePoint, 2>>> parents(1);
  for (int level = 1; level <= levels; ++level) {
    std::vector<LatticeSimplex> next;
    auto& ofPoint = parents.emplace_back();
    for (const LatticeSimplex& cell : bey) {
      for (const LatticeSimplex& child : children(dim, cell)) next.push_back(child);
      for (int i = 0; i <= dim; ++i)
        for (int j = i; j <= dim; ++j) ofPoint[sum(cell[i], cell[j])] = {cell[i], cell[j]};
    }
    bey = std::move(next);
    cells_.emplace_back();
    for (const LatticeSimplex& cell : bey) cells_.back().push_back(oriented(dim, cell));
  }
  for (const std::vector<LatticeSimplex>& cells : cells_) {
    std::vector<LatticePoint> points;
    for (const LatticeSimplex& cell : cells) points.insert(points.end(), cell.begin(), cell.begin() + dim + 1);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    std::vector<std::array<int, 4>> cellPoints;
    for (const LatticeSimplex& cell : cells) {
      std::array<int, 4> indices{-1, -1, -1, -1};
      for (int v = 0; v <= dim; ++v)
        indices[v] = static_cast<int>(std::lower_bound(points.begin(), points.end(), cell[v]) - points.begin());
      cellPoints.push_back(indices);
    }
    points_.push_back(std::move(points));
    cellPoints_.push_back(std::move(cellPoints));
  }
  for (const auto& ofPoint : parents) {  // the keys are points(level), in its order
    parents_.emplace_back();
    for (const auto& [point, ends] : ofPoint) parents_.back().push_back(ends);
  }
  for (int level = 1; level <= levels; ++level)
    if (parents_[level].size() != points_[level].size()) throw Error("simplex refinement: parents do not match points");
}

const std::array<LatticePoint, 2>& SimplexRefinement::parents(int level, const LatticePoint& point) const {
  if (level < 1 || level > levels()) throw Error("simplex refinement: no parents at level " + std::to_string(level));
  const std::vector<LatticePoint>& points = points_[level];
  const auto it = std::lower_bound(points.begin(), points.end(), point);
  if (it == points.end() || *it != point)
    throw Error("simplex refinement: not a vertex of level " + std::to_string(level));
  return parents_[level][it - points.begin()];
}

}  // namespace signorini
