#include "fe/RectilinearGrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "fe/BoxGrid.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

std::vector<std::vector<double>> boxGridCoordinates(const BoxGrid& grid) {
  std::vector<std::vector<double>> coordinates(grid.dim);
  for (int a = 0; a < grid.dim; ++a)
    for (long long i = 0; i <= grid.cells[a]; ++i)  // as BoxGrid::vertexCoordinates computes them
      coordinates[a].push_back(grid.lengths[a] * double(i) / double(grid.cells[a]));
  return coordinates;
}

// The box of `line` that holds x (clamped onto the line).
long long boxHolding(const std::vector<double>& line, double x) {
  const auto above = std::upper_bound(line.begin(), line.end(), x);
  const long long box = static_cast<long long>(above - line.begin()) - 1;
  return std::clamp(box, 0LL, static_cast<long long>(line.size()) - 2);
}

}  // namespace

RectilinearGrid::RectilinearGrid(const BoxGrid& grid) : RectilinearGrid(boxGridCoordinates(grid)) {}

RectilinearGrid::RectilinearGrid(std::vector<std::vector<double>> coordinates) : coordinates_(std::move(coordinates)) {
  if (coordinates_.size() != 2 && coordinates_.size() != 3)
    throw Error("RectilinearGrid: 2 or 3 axes, not " + std::to_string(coordinates_.size()));
  for (const auto& line : coordinates_) {
    if (line.size() < 2) throw Error("RectilinearGrid: an axis needs at least two vertex coordinates");
    for (std::size_t i = 1; i < line.size(); ++i)
      if (!(line[i] > line[i - 1])) throw Error("RectilinearGrid: vertex coordinates must increase");
  }
}

long long RectilinearGrid::numVertices() const {
  long long count = 1;
  for (const auto& line : coordinates_) count *= static_cast<long long>(line.size());
  return count;
}

void RectilinearGrid::vertexCoordinates(long long vertex, double* x) const {
  for (std::size_t a = 0; a < coordinates_.size(); ++a) {
    const long long size = static_cast<long long>(coordinates_[a].size());
    x[a] = coordinates_[a][vertex % size];
    vertex /= size;
  }
}

long long RectilinearGrid::vertexAt(const double* x) const {
  long long id = 0, stride = 1;
  for (std::size_t a = 0; a < coordinates_.size(); ++a) {
    const auto& line = coordinates_[a];
    const long long box = boxHolding(line, x[a]);
    const double width = line[box + 1] - line[box];
    const long long nearest = x[a] - line[box] <= line[box + 1] - x[a] ? box : box + 1;
    if (std::abs(x[a] - line[nearest]) > 1e-8 * width) return -1;
    id += stride * nearest;
    stride *= static_cast<long long>(line.size());
  }
  return id;
}

void RectilinearGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  const int dim = dimension();
  std::array<long long, 3> cellCounts = {1, 1, 1};
  long long box[3] = {0, 0, 0};
  double xi[3] = {0, 0, 0};
  for (int a = 0; a < dim; ++a) {
    const auto& line = coordinates_[a];
    cellCounts[a] = cells(a);
    box[a] = boxHolding(line, x[a]);
    xi[a] = std::clamp((x[a] - line[box[a]]) / (line[box[a] + 1] - line[box[a]]), 0.0, 1.0);
  }
  boxSimplexInterpolation(dim, cellCounts, box, xi, vertices, weights);
}

RectilinearGrid RectilinearGrid::coarsened() const {
  std::vector<std::vector<double>> coarse(coordinates_.size());
  for (std::size_t a = 0; a < coordinates_.size(); ++a) {
    const auto& line = coordinates_[a];
    for (std::size_t i = 0; i < line.size(); i += 2) coarse[a].push_back(line[i]);
    if (coarse[a].back() != line.back()) coarse[a].push_back(line.back());
  }
  return RectilinearGrid(std::move(coarse));
}

std::shared_ptr<const GeometricGrid> RectilinearGrid::coarser() const {
  for (int a = 0; a < dimension(); ++a)
    if (cells(a) > 1) return std::make_shared<RectilinearGrid>(coarsened());
  return nullptr;
}

std::string RectilinearGrid::description() const {
  std::string text;
  for (int a = 0; a < dimension(); ++a) text += (a ? " x " : "") + std::to_string(cells(a));
  return text + " rectilinear grid";
}

}  // namespace signorini
