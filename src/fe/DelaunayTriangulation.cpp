#include "fe/DelaunayTriangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>

#include <gmsh.h>

#include "fe/GmshSandbox.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Gmsh's triangulation of the points, its node tags (from 1) as indices from 0.
std::vector<long long> gmshCells(int dim, const std::vector<double>& points) {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 1);
  gmsh::option::setNumber("General.Verbosity", 1);
  // The same cells for the same points in any process: one thread, and the random numbers
  // of Gmsh's point perturbation (rand()) started alike.
  gmsh::option::setNumber("General.NumThreads", 1);
  std::srand(1);
  std::vector<std::size_t> tags;
  if (dim == 2)
    gmsh::model::mesh::triangulate(points, tags);
  else
    gmsh::model::mesh::tetrahedralize(points, tags);
  std::vector<long long> cells(tags.size());
  for (std::size_t k = 0; k < tags.size(); ++k) cells[k] = static_cast<long long>(tags[k]) - 1;
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
  std::vector<long long> raw;
  detail::answerFromChild(
      "Gmsh's Delaunay mesher", "triangulating " + std::to_string(points.size() / dim) + " points", -1,
      [&](int fd) {
        const std::vector<long long> cells = gmshCells(dim, points);
        detail::writeAll(fd, "A", 1);
        detail::sendArray(fd, cells);
      },
      [&](int fd) { return detail::receiveArray(fd, raw); });
  const auto numPoints = static_cast<long long>(points.size() / dim);
  std::vector<long long> cells;
  cells.reserve(raw.size());
  double v[12];
  for (std::size_t c = 0; c + dim < raw.size(); c += dim + 1) {
    for (int k = 0; k <= dim; ++k) {
      if (raw[c + k] < 0 || raw[c + k] >= numPoints) throw Error("delaunayCells: Gmsh named a point it was not given");
      std::copy_n(&points[dim * raw[c + k]], dim, &v[dim * k]);
    }
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
