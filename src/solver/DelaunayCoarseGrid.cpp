#include "solver/DelaunayCoarseGrid.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/SplitMixHash.hpp"
#include "solver/BoundaryFeatures.hpp"
#include "solver/DelaunayTriangulation.hpp"
#include "signorini/core/Error.hpp"
#include "solver/preconditioner/LocalBlock.hpp"

namespace signorini {

void VertexGraph::setEdgesOfCells(const std::vector<long long>& cells) {
  const std::size_t count = ids.size();
  const int corners = dim + 1;
  // The cells at each vertex (CSR), then each vertex's neighbours through them, each once.
  std::vector<long long> at, cellsAt;
  cellsAtVertices(dim, count, cells, at, cellsAt);
  std::vector<long long> seenBy(count, -1);
  start.assign(count + 1, 0);
  neighbours.clear();
  neighbours.reserve(cells.size() * 4);
  for (std::size_t v = 0; v < count; ++v) {
    seenBy[v] = static_cast<long long>(v);
    for (long long k = at[v]; k < at[v + 1]; ++k)
      for (int i = 0; i < corners; ++i) {
        const long long u = cells[corners * cellsAt[k] + i];
        if (seenBy[u] == static_cast<long long>(v)) continue;
        seenBy[u] = static_cast<long long>(v);
        neighbours.push_back(u);
      }
    start[v + 1] = static_cast<long long>(neighbours.size());
  }
}

void VertexGraph::setEdgesAndFeaturesOfCells(const Comm& comm, const std::vector<long long>& cells) {
  setEdgesOfCells(cells);
  features = boundaryFeatureDimensions(comm, dim, ids, coordinates, cells);
}

namespace {

using Import = Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node>;

// A vertex's priority in Luby's rule: the lower the dimension of the boundary feature it lies
// on, the higher (corners first), then a hash of its place; the same whatever the ids, the
// bodies' numbers and the rank count. Vertices of two bodies at one place share it, but they
// are never neighbours.
std::uint64_t priority(const VertexGraph& g, std::size_t v) {
  std::uint64_t words[3] = {0, 0, 0};
  std::memcpy(words, &g.coordinates[g.dim * v], g.dim * sizeof(double));
  const std::uint64_t feature = g.features.empty() ? g.dim : g.features[v];
  return (static_cast<std::uint64_t>(g.dim) - feature) << 62 | splitMixHash(words, words + 3) >> 2;
}

// The owned and the local (owned and ghost) vertices as maps of their ids, and the import
// between them.
struct VertexMaps {
  RCP<const Map> owned, local;
  RCP<const Import> toLocal;

  VertexMaps(const RCP<const Comm>& comm, const VertexGraph& g) {
    std::vector<GlobalOrdinal> ownedIds, localIds(g.ids.begin(), g.ids.end());
    for (std::size_t v = 0; v < g.ids.size(); ++v)
      if (g.owned[v]) ownedIds.push_back(g.ids[v]);
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    owned = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ownedIds), 0, comm));
    local = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(localIds), 0, comm));
    toLocal = rcp(new Import(owned, local));
  }
};

// Luby's maximal independent set of the graph: in each round the undecided vertices whose
// priority is above all their undecided neighbours' join the set, and their undecided
// neighbours leave it, but for the domain's corners: a corner is a feature of its own, which
// no neighbour removes, so that every level keeps every corner (two corners joined by an edge
// are both in the set). A vertex's neighbours may be spread over the ranks' cells, so each
// test is summed at its owner, who decides. Collective; per local vertex, 1 if in the set.
std::vector<char> independentSet(const RCP<const Comm>& comm, const VertexGraph& g) {
  enum : char { undecided, in, out };
  const std::size_t n = g.ids.size();
  std::vector<std::uint64_t> rank(n);
  for (std::size_t v = 0; v < n; ++v) rank[v] = priority(g, v);
  const auto above = [&](std::size_t u, std::size_t v) {  // u's priority above v's
    return rank[u] != rank[v] ? rank[u] > rank[v] : g.ids[u] > g.ids[v];
  };
  const auto corner = [&](std::size_t v) { return !g.features.empty() && g.features[v] == 0; };
  const VertexMaps maps(comm, g);
  Vector localTest(maps.local), ownedTest(maps.owned), ownedState(maps.owned), localState(maps.local);
  std::vector<char> state(n, undecided);
  // Sums test(v) over the ranks at v's owner, who sets `to` where the sum is positive (or zero
  // with `whenZero`) on an undecided vertex; then every rank learns the states.
  const auto decide = [&](auto test, char to, bool whenZero) {
    {
      auto t = localTest.getDataNonConst();
      for (std::size_t v = 0; v < n; ++v) t[v] = state[v] == undecided && test(v) ? 1.0 : 0.0;
    }
    ownedTest.putScalar(0.0);
    ownedTest.doExport(localTest, *maps.toLocal, Tpetra::ADD);
    {
      auto t = ownedTest.getData();
      auto s = ownedState.getDataNonConst();
      for (std::size_t k = 0; k < ownedState.getLocalLength(); ++k) {
        const auto v = static_cast<std::size_t>(maps.local->getLocalElement(maps.owned->getGlobalElement(k)));
        s[k] = state[v];
        if (state[v] == undecided && (t[k] > 0) != whenZero) s[k] = to;
      }
    }
    localState.doImport(ownedState, *maps.toLocal, Tpetra::INSERT);
    auto s = localState.getData();
    for (std::size_t v = 0; v < n; ++v) state[v] = static_cast<char>(s[v]);
  };
  const auto anyNeighbour = [&](std::size_t v, auto property) {
    for (long long e = g.start[v]; e < g.start[v + 1]; ++e)
      if (property(static_cast<std::size_t>(g.neighbours[e]))) return true;
    return false;
  };
  while (sumOverRanks(*comm, static_cast<long long>(std::count(state.begin(), state.end(), undecided))) > 0) {
    decide([&](std::size_t v) { return anyNeighbour(v, [&](std::size_t u) { return state[u] == undecided && above(u, v); }); },
           in, /*whenZero=*/true);
    decide([&](std::size_t v) { return !corner(v) && anyNeighbour(v, [&](std::size_t u) { return state[u] == in; }); },
           out, false);
  }
  std::vector<char> selected(n);
  for (std::size_t v = 0; v < n; ++v) selected[v] = state[v] == in;
  return selected;
}

// The selected vertices every rank owns, numbered in the order of their ids in the finer
// grid, whichever ranks own them: a graph of them without edges (coordinates, bodies and
// features), the same on every rank, each vertex owned. Collective.
VertexGraph gatherSelected(const RCP<const Comm>& comm, const VertexGraph& g, const std::vector<char>& selected) {
  std::vector<std::size_t> mine;
  for (std::size_t v = 0; v < g.ids.size(); ++v)
    if (selected[v] && g.owned[v]) mine.push_back(v);
  const auto count = static_cast<long long>(mine.size());
  long long upTo = 0, total = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, 1, &count, &upTo);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &count, &total);
  // Coordinates, then bodies, features and ids (exact in doubles below 2^53).
  const int dim = g.dim;
  std::vector<double> local(static_cast<std::size_t>((dim + 3) * total), 0.0);
  for (long long k = 0; k < count; ++k) {
    const std::size_t at = static_cast<std::size_t>(upTo - count + k);
    std::copy_n(&g.coordinates[dim * mine[k]], dim, &local[dim * at]);
    local[dim * total + at] = g.bodies.empty() ? 0 : g.bodies[mine[k]];
    local[(dim + 1) * total + at] = g.features.empty() ? dim : g.features[mine[k]];
    local[(dim + 2) * total + at] = static_cast<double>(g.ids[mine[k]]);
  }
  std::vector<double> all(local.size());
  if (!all.empty())
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(all.size()), local.data(), all.data());
  std::vector<long long> order(total);
  std::iota(order.begin(), order.end(), 0LL);
  const double* id = &all[(dim + 2) * total];
  std::sort(order.begin(), order.end(), [&](long long p, long long q) { return id[p] < id[q]; });
  VertexGraph kept;
  kept.dim = dim;
  kept.ids.resize(total);
  std::iota(kept.ids.begin(), kept.ids.end(), 0LL);
  kept.owned.assign(total, 1);
  kept.coordinates.resize(dim * total);
  kept.bodies.resize(total);
  kept.features.resize(total);
  for (long long k = 0; k < total; ++k) {
    std::copy_n(&all[dim * order[k]], dim, &kept.coordinates[dim * k]);
    kept.bodies[k] = static_cast<int>(all[dim * total + order[k]]);
    kept.features[k] = static_cast<signed char>(all[(dim + 1) * total + order[k]]);
  }
  return kept;
}

// Each body's Delaunay cells (vertex indices into all the vertices), made on rank 0 from the
// vertices in the order of their coordinates (so that the cells do not depend on the
// numbering) and sent to every rank. Collective.
std::vector<std::vector<long long>> cellsByBody(const Comm& comm, int dim, const std::vector<double>& coordinates,
                                                const std::vector<int>& bodies) {
  const int numBodies = bodies.empty() ? 0 : *std::max_element(bodies.begin(), bodies.end()) + 1;
  std::vector<std::vector<long long>> cells(numBodies);
  for (int b = 0; b < numBodies; ++b) {
    if (comm.getRank() == 0) {
      std::vector<long long> members;
      for (std::size_t v = 0; v < bodies.size(); ++v)
        if (bodies[v] == b) members.push_back(static_cast<long long>(v));
      std::sort(members.begin(), members.end(), [&](long long p, long long q) {
        return std::lexicographical_compare(&coordinates[dim * p], &coordinates[dim * p + dim], &coordinates[dim * q],
                                            &coordinates[dim * q + dim]);
      });
      std::vector<double> points;
      for (long long v : members) points.insert(points.end(), &coordinates[dim * v], &coordinates[dim * v + dim]);
      cells[b] = delaunayCells(dim, points);
      for (long long& v : cells[b]) v = members[v];
    }
    long long size = static_cast<long long>(cells[b].size());
    Teuchos::broadcast(comm, 0, 1, &size);
    cells[b].resize(size);
    if (size > 0) Teuchos::broadcast(comm, 0, static_cast<int>(size), cells[b].data());
  }
  return cells;
}

}  // namespace

DelaunayCoarseGrid::DelaunayCoarseGrid(int dim, std::vector<double> coordinates, std::vector<int> bodies,
                                       const std::vector<std::vector<long long>>& cellsOfBodies)
    : dim_(dim), coordinates_(std::move(coordinates)), bodies_(std::move(bodies)) {
  const RCP<const Comm> self = selfComm();
  for (std::size_t b = 0; b < cellsOfBodies.size(); ++b) {
    std::vector<long long> ids;
    std::vector<double> xyz;
    for (std::size_t v = 0; v < bodies_.size(); ++v)
      if (bodies_[v] == static_cast<int>(b)) {
        ids.push_back(static_cast<long long>(v));
        xyz.insert(xyz.end(), &coordinates_[dim * v], &coordinates_[dim * v + dim]);
      }
    byBody_.push_back(std::make_unique<SimplexGrid>(self, dim, std::move(ids), std::move(xyz), cellsOfBodies[b],
                                                    SimplexGrid::Outside::nearestCell, SimplexGrid::CoarseGrids::none));
  }
}

std::shared_ptr<const DelaunayCoarseGrid> DelaunayCoarseGrid::hierarchyBelow(const RCP<const Comm>& comm,
                                                                            const VertexGraph& graph,
                                                                            long long fewestVertices,
                                                                            double keptAtMost) {
  return coarsen(comm, comm, graph, fewestVertices, keptAtMost);
}

std::shared_ptr<const DelaunayCoarseGrid> DelaunayCoarseGrid::coarsen(const RCP<const Comm>& comm,
                                                                     const RCP<const Comm>& graphComm,
                                                                     const VertexGraph& graph, long long fewestVertices,
                                                                     double keptAtMost) {
  const long long finer =
      sumOverRanks(*graphComm, static_cast<long long>(std::count(graph.owned.begin(), graph.owned.end(), 1)));
  if (finer <= fewestVertices) return nullptr;
  VertexGraph kept = gatherSelected(graphComm, graph, independentSet(graphComm, graph));
  if (static_cast<long long>(kept.ids.size()) > keptAtMost * finer) return nullptr;
  const auto cells = cellsByBody(*comm, graph.dim, kept.coordinates, kept.bodies);
  std::vector<long long> allCells;
  for (const auto& bodyCells : cells) {
    if (bodyCells.empty()) return nullptr;  // a body of too few vertices to triangulate
    allCells.insert(allCells.end(), bodyCells.begin(), bodyCells.end());
  }
  kept.setEdgesOfCells(allCells);
  std::shared_ptr<DelaunayCoarseGrid> grid(new DelaunayCoarseGrid(graph.dim, kept.coordinates, kept.bodies, cells));
  // Every rank holds this grid: each finds the same coarser set on its own, its vertices
  // keeping the features they lie on in the mesh.
  grid->coarser_ = coarsen(comm, selfComm(), kept, fewestVertices, keptAtMost);
  return grid;
}

void DelaunayCoarseGrid::vertexCoordinates(long long vertex, double* x) const {
  if (vertex < 0 || vertex >= numVertices())
    throw Error("DelaunayCoarseGrid: no vertex " + std::to_string(vertex));
  std::copy_n(&coordinates_[dim_ * vertex], dim_, x);
}

long long DelaunayCoarseGrid::vertexOfBodyAt(const double* x, int body) const {
  if (body >= 0) return body < static_cast<int>(byBody_.size()) ? byBody_[body]->vertexAt(x) : -1;
  for (const auto& grid : byBody_)
    if (const long long v = grid->vertexAt(x); v >= 0) return v;
  return -1;
}

void DelaunayCoarseGrid::interpolationInBody(const double* x, int body, long long* vertices, double* weights) const {
  if (body >= static_cast<int>(byBody_.size()))
    throw Error("DelaunayCoarseGrid: no body " + std::to_string(body));
  byBody_[std::max(body, 0)]->interpolation(x, vertices, weights);
}

std::string DelaunayCoarseGrid::description() const {
  return "Delaunay coarse grid of " + std::to_string(numVertices()) + " vertices";
}

}  // namespace signorini
