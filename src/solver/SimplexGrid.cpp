#include "signorini/solver/SimplexGrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <Tpetra_Map.hpp>
#include <boost/geometry/algorithms/comparable_distance.hpp>
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/geometry/strategies/strategies.hpp>

#include "signorini/core/Error.hpp"
#include "solver/DelaunayCoarseGrid.hpp"

namespace signorini {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
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

// The grid's vertices, edges and boundary features, each vertex owned by the rank that
// `owned` gives it. Collective.
VertexGraph vertexGraph(int dim, const std::vector<long long>& ids, const std::vector<double>& coordinates,
                        const std::vector<long long>& cells, const Map& owned) {
  VertexGraph graph;
  graph.dim = dim;
  graph.ids = ids;
  graph.owned.resize(ids.size());
  for (std::size_t v = 0; v < ids.size(); ++v) graph.owned[v] = owned.isNodeGlobalElement(ids[v]);
  graph.coordinates = coordinates;
  graph.setEdgesAndFeaturesOfCells(*owned.getComm(), cells);
  return graph;
}

}  // namespace

// Boost.Geometry R-trees of the cells' bounding boxes (widened by the tolerance) and of the
// vertices, packed at construction; points in 2D have z = 0.
struct SimplexGrid::Buckets {
  using Point = bg::model::point<double, 3, bg::cs::cartesian>;
  using Box = bg::model::box<Point>;
  double tolerance = 0.0;
  bgi::rtree<std::pair<Box, long long>, bgi::rstar<16>> cells;
  bgi::rtree<std::pair<Point, long long>, bgi::rstar<16>> vertices;

  static Point point(int dim, const double* x) { return Point(x[0], x[1], dim == 3 ? x[2] : 0.0); }
  // The trees of the cells (vertices of `cells` indices into `coordinates`, dim per vertex).
  // Throws InputError for a degenerate cell.
  static std::unique_ptr<Buckets> over(int dim, const std::vector<double>& coordinates,
                                       const std::vector<long long>& cells);
};

std::unique_ptr<SimplexGrid::Buckets> SimplexGrid::Buckets::over(int dim, const std::vector<double>& coordinates,
                                                                 const std::vector<long long>& cells) {
  auto buckets = std::make_unique<Buckets>();
  const std::size_t numVertices = coordinates.size() / dim;
  const long long numCells = static_cast<long long>(cells.size()) / (dim + 1);
  double volume = 1.0;
  for (int a = 0; a < dim; ++a) {
    double low = 0.0, high = 0.0;
    for (std::size_t v = 0; v < numVertices; ++v) {
      low = v == 0 ? coordinates[a] : std::min(low, coordinates[dim * v + a]);
      high = v == 0 ? coordinates[a] : std::max(high, coordinates[dim * v + a]);
    }
    volume *= std::max(high - low, 1e-300);
  }
  buckets->tolerance = 1e-10 * std::pow(volume / std::max<long long>(numCells, 1), 1.0 / dim);
  const double t = buckets->tolerance;
  std::vector<std::pair<Box, long long>> boxes;
  boxes.reserve(numCells);
  double x[12];
  for (long long c = 0; c < numCells; ++c) {
    for (int k = 0; k <= dim; ++k) std::copy_n(&coordinates[dim * cells[(dim + 1) * c + k]], dim, &x[dim * k]);
    if (!nondegenerate(dim, x)) throw InputError("SimplexGrid: cell " + std::to_string(c) + " is degenerate");
    double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
    for (int a = 0; a < dim; ++a) {
      low[a] = high[a] = x[a];
      for (int k = 1; k <= dim; ++k) {
        low[a] = std::min(low[a], x[dim * k + a]);
        high[a] = std::max(high[a], x[dim * k + a]);
      }
      low[a] -= t;
      high[a] += t;
    }
    boxes.emplace_back(Box(Point(low[0], low[1], low[2]), Point(high[0], high[1], high[2])), c);
  }
  buckets->cells = decltype(buckets->cells)(boxes.begin(), boxes.end());
  std::vector<std::pair<Point, long long>> points;
  points.reserve(numVertices);
  for (std::size_t v = 0; v < numVertices; ++v)
    points.emplace_back(point(dim, &coordinates[dim * v]), static_cast<long long>(v));
  buckets->vertices = decltype(buckets->vertices)(points.begin(), points.end());
  return buckets;
}

SimplexGrid::SimplexGrid(const RCP<const Comm>& comm, int dim, std::vector<long long> vertexIds,
                         std::vector<double> coordinates, std::vector<long long> cells, Outside outside,
                         CoarseGrids coarseGrids)
    : dim_(dim), outside_(outside) {
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
  const RCP<const Map> owned = Tpetra::createOneToOne(overlapping);
  numVertices_ = static_cast<long long>(owned->getGlobalNumElements());

  buckets_ = Buckets::over(dim, coordinates_, cells_);
  if (coarseGrids == CoarseGrids::delaunay)
    coarser_ = DelaunayCoarseGrid::hierarchyBelow(comm, vertexGraph(dim, vertexIds_, coordinates_, cells_, *owned));
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
  double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
  for (int a = 0; a < dim_; ++a) {
    low[a] = x[a] - b.tolerance;
    high[a] = x[a] + b.tolerance;
  }
  long long found = -1;
  const Buckets::Box near(Buckets::Point(low[0], low[1], low[2]), Buckets::Point(high[0], high[1], high[2]));
  for (auto it = b.vertices.qbegin(bgi::intersects(near)); it != b.vertices.qend(); ++it)
    if (found < 0 || it->second < found) found = it->second;
  return found < 0 ? -1 : vertexIds_[found];
}

long long SimplexGrid::bestCell(const double* x, std::size_t nearest, double* lambda) const {
  const Buckets& b = *buckets_;
  const auto p = Buckets::point(dim_, x);
  double corners[12], trial[4], best = -1e300;
  long long chosen = -1;
  const auto consider = [&](long long c) {
    for (int v = 0; v <= dim_; ++v) std::copy_n(&coordinates_[dim_ * cells_[(dim_ + 1) * c + v]], dim_, &corners[dim_ * v]);
    if (!barycentric(dim_, corners, x, trial)) return;
    const double smallest = *std::min_element(trial, trial + dim_ + 1);
    if (smallest > best) {
      best = smallest;
      chosen = c;
      std::copy_n(trial, dim_ + 1, lambda);
    }
  };
  if (nearest == 0) {
    for (auto it = b.cells.qbegin(bgi::intersects(p)); it != b.cells.qend(); ++it) consider(it->second);
  } else {
    for (auto it = b.cells.qbegin(bgi::nearest(p, static_cast<unsigned>(nearest))); it != b.cells.qend(); ++it)
      consider(it->second);
  }
  return chosen;
}

void SimplexGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  long long chosen = bestCell(x, 0, weights);
  if (chosen < 0 || *std::min_element(weights, weights + dim_ + 1) < -1e-8) {
    if (outside_ == Outside::error)
      throw Error("SimplexGrid: a point in none of this rank's cells; each rank's cells must hold the nodes it owns");
    // The cells whose boxes are nearest: the nearest cell is among them.
    chosen = bestCell(x, 16, weights);
    if (chosen < 0) throw Error("SimplexGrid: a grid without cells cannot interpolate");
  }
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
