#include "assembly/RefinedMeshGrid.hpp"

#include <algorithm>
#include <cstring>

#include "solver/DelaunayCoarseGrid.hpp"
#include "assembly/MeshPieces.hpp"
#include "assembly/RefinedMeshPart.hpp"
#include "assembly/SortByKey.hpp"
#include "core/SplitMixHash.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {

// Its place is in pointCoordinates_, its weights are index / weightDenominator_: 40 bytes, of
// which the grid below a P1 space's holds one per vertex of the space.
struct RefinedMeshGrid::Point {
  long long vertices[4] = {0, 0, 0, 0};
  unsigned char index[4] = {0, 0, 0, 0};
  int body = -1;  // of bodies meshed apart (MeshPieces), -1 for one body
};

namespace {

// A hash of a place: of its coordinates' bits, -0 taken as 0.
std::uint64_t placeHash(const double* x, int dim) {
  std::uint64_t words[3] = {0, 0, 0};
  for (int c = 0; c < dim; ++c) {
    const double value = x[c] + 0.0;
    std::memcpy(&words[c], &value, sizeof(double));
  }
  return splitMixHash(words, words + dim);
}

// This rank's vertices and edges of the coarse mesh (level 0, `coarsest`), each vertex owned
// by its lattice point's owner, of its coarse cell's body (none: one body).
VertexGraph coarseMeshGraph(const detail::CoarseMeshLattice& lattice, const detail::RefinedLevel& coarsest,
                            const std::vector<int>& coarseCellBody) {
  VertexGraph graph;
  graph.dim = lattice.dim();
  graph.ids = coarsest.vertexIds;
  graph.coordinates = coarsest.mesh.vertices;
  const int rank = lattice.comm()->getRank();
  for (std::size_t v = 0; v < graph.ids.size(); ++v) {
    const long long cell = coarsest.vertexCells[v];
    graph.owned.push_back(lattice.pointOwner(cell, coarsest.vertexPoints[v]) == rank);
    const bool known = cell < static_cast<long long>(coarseCellBody.size());
    if (!coarseCellBody.empty()) graph.bodies.push_back(known ? std::max(coarseCellBody[cell], 0) : 0);
  }
  graph.setEdgesAndFeaturesOfCells(*lattice.comm(), coarsest.mesh.cells);
  return graph;
}

}  // namespace

std::shared_ptr<const RefinedMeshGrid> RefinedMeshGrid::hierarchy(
    std::shared_ptr<const detail::CoarseMeshLattice> lattice, const SimplexRefinement& refinement,
    std::shared_ptr<const DistributedSpace> space, detail::RefinedLevel finest, bool delaunayBelow) {
  // Finest first: each level is refined once, for its own grid and the points of the next coarser.
  const int levels = refinement.levels();
  std::shared_ptr<RefinedMeshGrid> top(
      new RefinedMeshGrid(*lattice, levels, levels, std::move(finest.vertexIds), std::move(finest.mesh.vertices)));
  // Bodies meshed apart may have points at one place: each point carries its body, that of
  // its coarse cell's nodes.
  const MeshPieces& apart = meshPieces(*space);
  std::vector<int> coarseCellBody;
  if (apart.count > 1)
    detail::forEachCellNode(space->space(), refinement, [&](long long node, long long, long long coarse,
                                                            const LatticeSimplex&, const std::array<int, 4>&) {
      if (coarse >= static_cast<long long>(coarseCellBody.size())) coarseCellBody.resize(coarse + 1, -1);
      coarseCellBody[coarse] = apart.ofSpaceNode[node];
    });
  top->answerForSpaceWhenAsked(refinement, space, std::move(finest.partVertexIds),
                               apart.count > 1 ? apart.ofSpaceNode : std::vector<int>());
  RefinedMeshGrid* above = top.get();
  const detail::RefinedLevel* finer = &finest;
  detail::RefinedLevel previous;
  for (int level = levels - 1; level >= 0; --level) {
    detail::RefinedLevel own = detail::refineLocally(*lattice, refinement, level, false);
    std::shared_ptr<RefinedMeshGrid> grid(
        new RefinedMeshGrid(*lattice, level, levels, own.vertexIds, own.mesh.vertices));
    grid->answerForLevel(*lattice, refinement, *above, *finer, coarseCellBody);
    above->coarser_ = grid;
    above = grid.get();
    previous = std::move(own);
    finer = &previous;
  }
  if (delaunayBelow) {
    const VertexGraph coarseMesh = coarseMeshGraph(*lattice, previous, coarseCellBody);
    above->coarser_ = DelaunayCoarseGrid::hierarchyBelow(lattice->comm(), coarseMesh);
  }
  return top;
}

RefinedMeshGrid::RefinedMeshGrid(const detail::CoarseMeshLattice& lattice, int level, int levels,
                                 std::vector<long long> vertexIds, std::vector<double> coordinates)
    : dim_(lattice.dim()), level_(level), levels_(levels), numVertices_(lattice.numPoints(1LL << level)),
      vertexIds_(std::move(vertexIds)),
      coordinates_(std::make_shared<const std::vector<double>>(std::move(coordinates))) {}

void RefinedMeshGrid::answerForLevel(const detail::CoarseMeshLattice& lattice, const SimplexRefinement& refinement,
                                     const RefinedMeshGrid& finerGrid, const detail::RefinedLevel& finer,
                                     const std::vector<int>& coarseCellBody) {
  const long long n = 1LL << level_;
  pointCoordinates_ = finerGrid.coordinates_;  // the finer grid's vertices, in the order of `finer`'s
  weightDenominator_ = 2;
  points_.resize(finer.vertexCells.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    Point& point = points_[i];
    const long long cell = finer.vertexCells[i];
    if (cell < static_cast<long long>(coarseCellBody.size())) point.body = coarseCellBody[cell];
    const auto& [a, b] = refinement.parents(level_ + 1, finer.vertexPoints[i]);
    point.vertices[0] = lattice.pointId(cell, a, n);
    if (a == b) {
      point.index[0] = 2;
    } else {
      point.vertices[1] = lattice.pointId(cell, b, n);
      point.vertices[2] = point.vertices[3] = point.vertices[1];
      point.index[0] = point.index[1] = 1;
    }
  }
  indexPoints();
}

void RefinedMeshGrid::answerForSpaceWhenAsked(const SimplexRefinement& refinement,
                                              std::shared_ptr<const DistributedSpace> space,
                                              std::vector<long long> vertexIds, std::vector<int> nodeBody) {
  spaceToAnswerFor_.reset(
      new SpaceToAnswerFor{refinement, std::move(space), std::move(vertexIds), std::move(nodeBody)});
}

void RefinedMeshGrid::answerForSpace() const {
  const std::unique_ptr<SpaceToAnswerFor> pending = std::move(spaceToAnswerFor_);
  const DistributedSpace& space = *pending->space;
  const LagrangeSpace& pk = space.space();
  // The space's node coordinates, kept with the space they belong to.
  pointCoordinates_ = std::shared_ptr<const std::vector<double>>(pending->space, &pk.nodeCoordinates());
  weightDenominator_ = pk.degree();
  points_.resize(pk.numNodes());
  std::vector<char> seen(pk.numNodes(), 0);
  detail::forEachCellNode(pk, pending->refinement, [&](long long node, long long cell, long long,
                                                       const LatticeSimplex&, const std::array<int, 4>& index) {
    if (seen[node]) return;
    seen[node] = 1;
    Point& point = points_[node];
    if (!pending->nodeBody.empty()) point.body = pending->nodeBody[node];
    for (int v = 0; v <= dim_; ++v) {
      point.vertices[v] = pending->vertexIds[space.mesh().cells[(dim_ + 1) * cell + v]];
      point.index[v] = static_cast<unsigned char>(index[v]);
    }
  });
  indexPoints();
}

void RefinedMeshGrid::indexPoints() const {
  byPlace_.resize(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) byPlace_[i] = {placeHash(placeOf(i), dim_), i};
  detail::sortByKey(byPlace_, [](const PlaceEntry& entry) { return entry.first; });
}

const RefinedMeshGrid::Point* RefinedMeshGrid::findPoint(const double* x, int body) const {
  if (spaceToAnswerFor_) answerForSpace();
  const std::uint64_t hash = placeHash(x, dim_);
  auto it = std::lower_bound(byPlace_.begin(), byPlace_.end(), hash,
                             [](const PlaceEntry& entry, std::uint64_t h) { return entry.first < h; });
  for (; it != byPlace_.end() && it->first == hash; ++it) {
    const Point& point = points_[it->second];
    if (std::equal(x, x + dim_, placeOf(it->second)) && (body < 0 || point.body == body)) return &point;
  }
  return nullptr;
}

long long RefinedMeshGrid::vertexOf(const Point& point) const {
  for (int v = 0; v <= dim_; ++v)
    if (point.index[v] == weightDenominator_) return point.vertices[v];
  return -1;
}

void RefinedMeshGrid::vertexCoordinates(long long vertex, double* x) const {
  const auto it = std::lower_bound(vertexIds_.begin(), vertexIds_.end(), vertex);
  if (it == vertexIds_.end() || *it != vertex)
    throw Error("refined mesh grid: vertex " + std::to_string(vertex) + " is not in this rank's part");
  std::copy_n(&(*coordinates_)[dim_ * (it - vertexIds_.begin())], dim_, x);
}

long long RefinedMeshGrid::vertexAt(const double* x) const { return vertexOfBodyAt(x, -1); }

long long RefinedMeshGrid::vertexOfBodyAt(const double* x, int body) const {
  const Point* point = findPoint(x, body);
  return point ? vertexOf(*point) : -1;
}

void RefinedMeshGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  interpolationInBody(x, -1, vertices, weights);
}

void RefinedMeshGrid::interpolationInBody(const double* x, int body, long long* vertices, double* weights) const {
  const Point* point = findPoint(x, body);
  if (!point) throw Error("refined mesh grid: a point that is no node of this rank's part of the finer level");
  std::copy_n(point->vertices, dim_ + 1, vertices);
  for (int v = 0; v <= dim_; ++v) weights[v] = static_cast<double>(point->index[v]) / weightDenominator_;
}

std::string RefinedMeshGrid::description() const {
  return "level " + std::to_string(level_) + " of " + std::to_string(levels_) + " uniform refinements (" +
         std::to_string(numVertices_) + " vertices)";
}

}  // namespace signorini
