#include "signorini/solver/SimplexGrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <Tpetra_Map.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Barycentric coordinates of x in the simplex with vertex coordinates v (dim per vertex);
// false for a degenerate simplex.
bool barycentric(int dim, const double* v, const double* x, double* lambda) {
  double m[3][3] = {}, r[3] = {};
  for (int a = 0; a < dim; ++a) {
    for (int k = 0; k < dim; ++k) m[a][k] = v[dim * (k + 1) + a] - v[a];
    r[a] = x[a] - v[a];
  }
  const auto det = [&](const double (*c)[3]) {
    return dim == 2 ? c[0][0] * c[1][1] - c[0][1] * c[1][0]
                    : c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                          c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
  };
  const double whole = det(m);
  if (whole == 0.0) return false;
  lambda[0] = 1.0;
  for (int k = 0; k < dim; ++k) {  // Cramer's rule: column k replaced by r
    double c[3][3] = {};
    for (int a = 0; a < dim; ++a)
      for (int j = 0; j < dim; ++j) c[a][j] = j == k ? r[a] : m[a][j];
    lambda[k + 1] = det(c) / whole;
    lambda[0] -= lambda[k + 1];
  }
  return true;
}

// Whether the simplex's measure is more than round-off of its longest edge's.
bool nondegenerate(int dim, const double* v) {
  double m[3][3] = {}, longest = 0.0;
  for (int k = 1; k <= dim; ++k)
    for (int a = 0; a < dim; ++a) m[k - 1][a] = v[dim * k + a] - v[a];
  for (int i = 0; i <= dim; ++i)
    for (int j = i + 1; j <= dim; ++j) {
      double squared = 0.0;
      for (int a = 0; a < dim; ++a) squared += (v[dim * i + a] - v[dim * j + a]) * (v[dim * i + a] - v[dim * j + a]);
      longest = std::max(longest, std::sqrt(squared));
    }
  const double det = dim == 2 ? m[0][0] * m[1][1] - m[0][1] * m[1][0]
                              : m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                                    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                                    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return std::abs(det) > 1e-12 * std::pow(longest, dim);
}

}  // namespace

// A uniform grid of boxes over this rank's cells: each box lists the cells whose bounding
// box (widened by the tolerance) meets it and the vertices in it.
struct SimplexGrid::Buckets {
  int dim = 0;
  std::array<double, 3> lower{}, width{};
  std::array<long long, 3> count{1, 1, 1};
  double tolerance = 0.0;
  std::vector<long long> cellStart, cellItems, vertexStart, vertexItems;  // CSR per box

  long long index(int axis, double x) const {
    const auto i = static_cast<long long>(std::floor((x - lower[axis]) / width[axis]));
    return std::clamp<long long>(i, 0, count[axis] - 1);
  }
  long long box(const std::array<long long, 3>& i) const { return i[0] + count[0] * (i[1] + count[1] * i[2]); }
  // Calls visit(box) for every box that meets [low, high].
  template <class Visit>
  void forBoxes(const double* low, const double* high, Visit&& visit) const {
    std::array<long long, 3> from{0, 0, 0}, to{0, 0, 0}, i{0, 0, 0};
    for (int a = 0; a < dim; ++a) {
      from[a] = index(a, low[a]);
      to[a] = index(a, high[a]);
    }
    for (i[2] = from[2]; i[2] <= to[2]; ++i[2])
      for (i[1] = from[1]; i[1] <= to[1]; ++i[1])
        for (i[0] = from[0]; i[0] <= to[0]; ++i[0]) visit(box(i));
  }
  // The buckets of the cells (vertices of `cells` indices into `coordinates`, dim per vertex).
  // Throws InputError for a degenerate cell.
  static std::unique_ptr<Buckets> over(int dim, const std::vector<double>& coordinates,
                                       const std::vector<long long>& cells);
};

// Boxes about as many as the cells, each about a cell wide, over the vertices' bounding box.
std::unique_ptr<SimplexGrid::Buckets> SimplexGrid::Buckets::over(int dim, const std::vector<double>& coordinates,
                                                                 const std::vector<long long>& cells) {
  auto buckets = std::make_unique<Buckets>();
  Buckets& b = *buckets;
  b.dim = dim;
  const std::size_t numVertices = coordinates.size() / dim;
  const long long numCells = static_cast<long long>(cells.size()) / (dim + 1);
  std::array<double, 3> upper{};
  for (int a = 0; a < dim; ++a) {
    b.lower[a] = upper[a] = numVertices > 0 ? coordinates[a] : 0.0;
    for (std::size_t v = 0; v < numVertices; ++v) {
      b.lower[a] = std::min(b.lower[a], coordinates[dim * v + a]);
      upper[a] = std::max(upper[a], coordinates[dim * v + a]);
    }
  }
  double volume = 1.0;
  for (int a = 0; a < dim; ++a) volume *= std::max(upper[a] - b.lower[a], 1e-300);
  const double cellSize = std::pow(volume / std::max<long long>(numCells, 1), 1.0 / dim);
  b.tolerance = 1e-10 * cellSize;
  for (int a = 0; a < dim; ++a) {
    b.count[a] = std::clamp<long long>(static_cast<long long>((upper[a] - b.lower[a]) / cellSize), 1, 1 << 20);
    b.width[a] = std::max(upper[a] - b.lower[a], 1e-300) / static_cast<double>(b.count[a]);
  }
  const long long boxes = b.count[0] * b.count[1] * b.count[2];
  std::vector<std::vector<long long>> cellLists(boxes), vertexLists(boxes);
  double x[12], low[3], high[3];
  for (long long c = 0; c < numCells; ++c) {
    for (int k = 0; k <= dim; ++k) std::copy_n(&coordinates[dim * cells[(dim + 1) * c + k]], dim, &x[dim * k]);
    if (!nondegenerate(dim, x)) throw InputError("SimplexGrid: cell " + std::to_string(c) + " is degenerate");
    for (int a = 0; a < dim; ++a) {
      low[a] = high[a] = x[a];
      for (int k = 1; k <= dim; ++k) {
        low[a] = std::min(low[a], x[dim * k + a]);
        high[a] = std::max(high[a], x[dim * k + a]);
      }
      low[a] -= b.tolerance;
      high[a] += b.tolerance;
    }
    b.forBoxes(low, high, [&](long long box) { cellLists[box].push_back(c); });
  }
  for (std::size_t v = 0; v < numVertices; ++v)
    b.forBoxes(&coordinates[dim * v], &coordinates[dim * v], [&](long long box) {
      vertexLists[box].push_back(static_cast<long long>(v));
    });
  const auto flatten = [](std::vector<std::vector<long long>>& lists, std::vector<long long>& start,
                          std::vector<long long>& items) {
    start.assign(1, 0);
    for (auto& list : lists) {
      items.insert(items.end(), list.begin(), list.end());
      start.push_back(static_cast<long long>(items.size()));
      std::vector<long long>().swap(list);
    }
  };
  flatten(cellLists, b.cellStart, b.cellItems);
  flatten(vertexLists, b.vertexStart, b.vertexItems);
  return buckets;
}

SimplexGrid::SimplexGrid(const RCP<const Comm>& comm, int dim, std::vector<long long> vertexIds,
                         std::vector<double> coordinates, std::vector<long long> cells)
    : dim_(dim) {
  if (dim != 2 && dim != 3) throw InputError("SimplexGrid: the dimension must be 2 or 3, got " + std::to_string(dim));
  const std::size_t numVertices = vertexIds.size();
  if (coordinates.size() != dim * numVertices || cells.size() % (dim + 1) != 0)
    throw InputError("SimplexGrid: " + std::to_string(numVertices) + " vertices with " +
                     std::to_string(coordinates.size()) + " coordinates and " + std::to_string(cells.size()) +
                     " cell entries; give " + std::to_string(dim) + " coordinates per vertex and " +
                     std::to_string(dim + 1) + " vertices per cell");
  // Vertices sorted by id, with their coordinates.
  std::vector<std::size_t> order(numVertices);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return vertexIds[a] < vertexIds[b]; });
  vertexIds_.resize(numVertices);
  coordinates_.resize(coordinates.size());
  for (std::size_t i = 0; i < numVertices; ++i) {
    vertexIds_[i] = vertexIds[order[i]];
    std::copy_n(&coordinates[dim * order[i]], dim, &coordinates_[dim * i]);
    if (i > 0 && vertexIds_[i] == vertexIds_[i - 1])
      throw InputError("SimplexGrid: vertex " + std::to_string(vertexIds_[i]) + " is given twice");
  }
  cells_.resize(cells.size());
  for (std::size_t e = 0; e < cells.size(); ++e) {
    const auto it = std::lower_bound(vertexIds_.begin(), vertexIds_.end(), cells[e]);
    if (it == vertexIds_.end() || *it != cells[e])
      throw InputError("SimplexGrid: cell " + std::to_string(e / (dim + 1)) + " names vertex " +
                       std::to_string(cells[e]) + ", which is not among the vertices given");
    cells_[e] = it - vertexIds_.begin();
  }

  // The distinct vertices over all ranks.
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::vector<GlobalOrdinal> ids(vertexIds_.begin(), vertexIds_.end());
  const RCP<const Map> overlapping = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, comm));
  numVertices_ = static_cast<long long>(Tpetra::createOneToOne(overlapping)->getGlobalNumElements());

  buckets_ = Buckets::over(dim, coordinates_, cells_);
}

SimplexGrid::~SimplexGrid() = default;

void SimplexGrid::vertexCoordinates(long long vertex, double* x) const {
  const auto it = std::lower_bound(vertexIds_.begin(), vertexIds_.end(), vertex);
  if (it == vertexIds_.end() || *it != vertex)
    throw Error("SimplexGrid: vertex " + std::to_string(vertex) + " is not a vertex of this rank's cells");
  std::copy_n(&coordinates_[dim_ * (it - vertexIds_.begin())], dim_, x);
}

long long SimplexGrid::vertexAt(const double* x) const {
  const Buckets& b = *buckets_;
  double low[3], high[3];
  for (int a = 0; a < dim_; ++a) {
    low[a] = x[a] - b.tolerance;
    high[a] = x[a] + b.tolerance;
  }
  long long found = -1;
  b.forBoxes(low, high, [&](long long box) {
    for (long long i = b.vertexStart[box]; i < b.vertexStart[box + 1] && found < 0; ++i) {
      const long long v = b.vertexItems[i];
      bool near = true;
      for (int a = 0; a < dim_; ++a) near = near && std::abs(coordinates_[dim_ * v + a] - x[a]) <= b.tolerance;
      if (near) found = vertexIds_[v];
    }
  });
  return found;
}

void SimplexGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  const Buckets& b = *buckets_;
  double corners[12], lambda[4], best = -1e300;
  long long chosen = -1;
  std::array<long long, 3> at{0, 0, 0};
  for (int a = 0; a < dim_; ++a) at[a] = b.index(a, x[a]);
  const long long box = b.box(at);
  for (long long i = b.cellStart[box]; i < b.cellStart[box + 1]; ++i) {
    const long long c = b.cellItems[i];
    for (int k = 0; k <= dim_; ++k) std::copy_n(&coordinates_[dim_ * cells_[(dim_ + 1) * c + k]], dim_, &corners[dim_ * k]);
    if (!barycentric(dim_, corners, x, lambda)) continue;
    const double smallest = *std::min_element(lambda, lambda + dim_ + 1);
    if (smallest > best) {
      best = smallest;
      chosen = c;
      std::copy_n(lambda, dim_ + 1, weights);
    }
  }
  if (chosen < 0 || best < -1e-8)
    throw Error("SimplexGrid: a point in none of this rank's cells; each rank's cells must hold the nodes it owns");
  double sum = 0.0;
  for (int k = 0; k <= dim_; ++k) sum += weights[k] = std::max(weights[k], 0.0);
  for (int k = 0; k <= dim_; ++k) {
    weights[k] /= sum;
    vertices[k] = vertexIds_[cells_[(dim_ + 1) * chosen + k]];
  }
}

std::string SimplexGrid::description() const {
  return "simplex grid of " + std::to_string(numVertices_) + " vertices";
}

}  // namespace signorini
