#include "solver/DelaunayTriangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Each vertex keeps the index of its point.
using Delaunay2 = CGAL::Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<long long, Kernel>>>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<
    Kernel, CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<long long, Kernel>>>;

// The corners of the points' bounding box enlarged by a fifth of its extent on every side.
template <class Point>
std::vector<Point> enclosingCorners(int dim, const std::vector<double>& points) {
  double low[3], high[3];
  for (int c = 0; c < dim; ++c) {
    low[c] = high[c] = points[c];
    for (std::size_t p = 0; p < points.size() / dim; ++p) {
      low[c] = std::min(low[c], points[dim * p + c]);
      high[c] = std::max(high[c], points[dim * p + c]);
    }
    const double margin = 0.2 * (high[c] - low[c]);
    low[c] -= margin;
    high[c] += margin;
  }
  std::vector<Point> corners;
  for (int m = 0; m < (1 << dim); ++m) {
    double x[3];
    for (int c = 0; c < dim; ++c) x[c] = (m >> c) & 1 ? high[c] : low[c];
    if constexpr (Point::Ambient_dimension::value == 2)
      corners.emplace_back(x[0], x[1]);
    else
      corners.emplace_back(x[0], x[1], x[2]);
  }
  return corners;
}

// The finite cells of the triangulation of the points, dim + 1 point indices each, but those
// whose circumsphere holds a corner of the enclosing box (exact predicates).
template <class Triangulation>
std::vector<long long> triangulationCells(int dim, const std::vector<double>& points) {
  using Point = typename Triangulation::Point;
  constexpr bool planar = Point::Ambient_dimension::value == 2;
  std::vector<std::pair<Point, long long>> indexed(points.size() / dim);
  for (std::size_t p = 0; p < indexed.size(); ++p) {
    const double* x = &points[dim * p];
    if constexpr (planar)
      indexed[p] = {Point(x[0], x[1]), static_cast<long long>(p)};
    else
      indexed[p] = {Point(x[0], x[1], x[2]), static_cast<long long>(p)};
  }
  const Triangulation triangulation(indexed.begin(), indexed.end());
  std::vector<long long> cells;
  if (triangulation.dimension() < dim) return cells;  // the points lie in a line or a plane
  const std::vector<Point> corners = enclosingCorners<Point>(dim, points);
  const auto holds = [](const auto& cell, const Point& corner) {
    const auto& v = [&cell](int k) -> const Point& { return cell->vertex(k)->point(); };
    if constexpr (planar)
      return Kernel().side_of_bounded_circle_2_object()(v(0), v(1), v(2), corner) == CGAL::ON_BOUNDED_SIDE;
    else
      return Kernel().side_of_bounded_sphere_3_object()(v(0), v(1), v(2), v(3), corner) == CGAL::ON_BOUNDED_SIDE;
  };
  const auto append = [&](const auto& cell) {
    for (const Point& corner : corners)
      if (holds(cell, corner)) return;
    for (int k = 0; k <= dim; ++k) cells.push_back(cell->vertex(k)->info());
  };
  if constexpr (planar)
    for (const auto& face : triangulation.finite_face_handles()) append(face);
  else
    for (const auto& cell : triangulation.finite_cell_handles()) append(cell);
  return cells;
}

// The signed measure (times dim!) of the cell and its longest edge.
double signedMeasure(int dim, const double* v, double& longest) {
  double e[3][3] = {};
  longest = 0.0;
  for (int i = 0; i <= dim; ++i)
    for (int j = i + 1; j <= dim; ++j) {
      double squared = 0.0;
      for (int a = 0; a < dim; ++a) squared += (v[dim * i + a] - v[dim * j + a]) * (v[dim * i + a] - v[dim * j + a]);
      longest = std::max(longest, std::sqrt(squared));
    }
  for (int k = 1; k <= dim; ++k)
    for (int a = 0; a < dim; ++a) e[k - 1][a] = v[dim * k + a] - v[a];
  return dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                  : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

}  // namespace

std::vector<long long> delaunayCells(int dim, const std::vector<double>& points) {
  if (dim != 2 && dim != 3) throw InputError("delaunayCells: the dimension must be 2 or 3, got " + std::to_string(dim));
  if (points.size() < static_cast<std::size_t>(dim * (dim + 1))) return {};
  const std::vector<long long> raw =
      dim == 2 ? triangulationCells<Delaunay2>(dim, points) : triangulationCells<Delaunay3>(dim, points);
  std::vector<long long> cells;
  cells.reserve(raw.size());
  double v[12];
  for (std::size_t c = 0; c + dim < raw.size(); c += dim + 1) {
    for (int k = 0; k <= dim; ++k) std::copy_n(&points[dim * raw[c + k]], dim, &v[dim * k]);
    double longest = 0.0;
    const double measure = signedMeasure(dim, v, longest);
    if (std::abs(measure) <= 1e-9 * std::pow(longest, dim)) continue;
    const std::size_t first = cells.size();
    cells.insert(cells.end(), raw.begin() + c, raw.begin() + c + dim + 1);
    if (measure < 0) std::swap(cells[first], cells[first + 1]);
  }
  return cells;
}

}  // namespace signorini
