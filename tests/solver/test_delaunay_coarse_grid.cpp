// Coarse grids made from a mesh's own vertices: each level's vertices are a maximal
// independent set of the finer level's vertex graph, the same set on any rank count; its
// Delaunay cells interpolate with weights that sum to one and reproduce linear functions
// inside the hull, which keeps a box's corners; points outside take the nearest cell's
// clamped weights; two bodies of one mesh get grids of their own.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "solver/DelaunayCoarseGrid.hpp"
#include "assembly/DistributedSpace.hpp"
#include "assembly/MeshVertexGrid.hpp"
#include "solver/preconditioner/LocalBlock.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// signorini::testing::distortedBoxMesh; with `twoBodies`, a copy of it beside it at x + 1.1 as a second body.
std::shared_ptr<const SimplexMesh> distortedMesh(int dim, long long n, bool twoBodies = false) {
  SimplexMesh mesh = signorini::testing::distortedBoxMesh(dim, n);
  if (twoBodies) {  // a copy of the mesh beside it, a gap of 0.1 between them
    const long long numVertices = mesh.numVertices(), numCells = mesh.numCells();
    for (long long v = 0; v < numVertices; ++v)
      for (int c = 0; c < dim; ++c) mesh.vertices.push_back(mesh.vertices[dim * v + c] + (c == 0 ? 1.1 : 0.0));
    for (long long e = 0; e < (dim + 1) * numCells; ++e) mesh.cells.push_back(mesh.cells[e] + numVertices);
    mesh.cellTags.assign(numCells, 0);
    mesh.cellTags.resize(2 * numCells, 1);
    mesh.bodyTags = {{"left", 0}, {"right", 1}};
    mesh.facets.clear();
    mesh.facetTags.clear();
  }
  return std::make_shared<const SimplexMesh>(std::move(mesh));
}

std::shared_ptr<const DistributedSpace> space(const RCP<const Comm>& comm, int dim, long long n, bool twoBodies = false) {
  auto mesh = distortedMesh(dim, n, twoBodies);
  return std::make_shared<const DistributedSpace>(comm, comm->getRank() == 0 ? mesh : nullptr, 1);
}

// The coordinates of a grid's vertices, sorted.
std::vector<std::vector<double>> places(const GeometricGrid& grid) {
  std::vector<std::vector<double>> all;
  for (long long v = 0; v < grid.numVertices(); ++v) {
    std::vector<double> x(grid.dimension());
    grid.vertexCoordinates(v, x.data());
    all.push_back(x);
  }
  std::sort(all.begin(), all.end());
  return all;
}

TEST(DelaunayCoarseGrid, FirstLevelIsAMaximalIndependentSetOfTheMeshVertices) {
  for (int dim : {2, 3}) {
    // The whole mesh on every rank's own communicator: each rank checks every vertex.
    const auto whole = space(selfComm(), dim, dim == 2 ? 24 : 8);
    const MeshVertexGrid fine(whole);
    const VertexGraph graph = fine.vertexGraph();
    const auto coarse = DelaunayCoarseGrid::hierarchyBelow(selfComm(), graph, 10);
    ASSERT_TRUE(coarse) << dim << "D";
    std::vector<char> in(graph.ids.size(), 0);
    for (std::size_t v = 0; v < graph.ids.size(); ++v) in[v] = coarse->vertexAt(&graph.coordinates[dim * v]) >= 0;
    for (std::size_t v = 0; v < graph.ids.size(); ++v) {
      bool nextToOne = false;
      for (long long e = graph.start[v]; e < graph.start[v + 1]; ++e) {
        const auto u = static_cast<std::size_t>(graph.neighbours[e]);
        EXPECT_FALSE(in[v] && in[u]) << dim << "D: vertices " << v << " and " << u << " are joined";
        nextToOne = nextToOne || in[u];
      }
      EXPECT_TRUE(in[v] || nextToOne) << dim << "D: vertex " << v << " could join the set";
    }
    // A few times fewer vertices per level, down to the fewest asked for.
    long long above = static_cast<long long>(graph.ids.size());
    for (auto grid = std::static_pointer_cast<const GeometricGrid>(coarse); grid; grid = grid->coarser()) {
      EXPECT_LT(grid->numVertices(), above / 2) << dim << "D";
      EXPECT_GT(above, 10) << dim << "D: a level below one of at most 10 vertices";
      above = grid->numVertices();
    }
  }
}

TEST(DelaunayCoarseGrid, TheLevelsDoNotDependOnTheRankCount) {
  const auto comm = Tpetra::getDefaultComm();
  for (const auto& [dim, twoBodies] : {std::pair{2, false}, std::pair{3, false}, std::pair{2, true}}) {
    const std::string what = std::to_string(dim) + "D" + (twoBodies ? ", two bodies" : "");
    const auto distributed = space(comm, dim, dim == 2 ? 24 : 8, twoBodies);
    const auto whole = space(selfComm(), dim, dim == 2 ? 24 : 8, twoBodies);
    std::shared_ptr<const GeometricGrid> a =
        DelaunayCoarseGrid::hierarchyBelow(comm, MeshVertexGrid(distributed).vertexGraph(), 10);
    std::shared_ptr<const GeometricGrid> b =
        DelaunayCoarseGrid::hierarchyBelow(selfComm(), MeshVertexGrid(whole).vertexGraph(), 10);
    int level = 0;
    for (; a && b; a = a->coarser(), b = b->coarser(), ++level)
      EXPECT_EQ(places(*a), places(*b)) << what << " level " << level;
    EXPECT_EQ(!a, !b) << what << ": the hierarchies end at different levels";
    EXPECT_GE(level, 2) << what;
  }
}

TEST(DelaunayCoarseGrid, InterpolatesLinearFunctionsInsideItsHullAndClampsOutside) {
  const auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3}) {
    const long long n = dim == 2 ? 24 : 8;
    const auto ds = space(comm, dim, n);
    const MeshVertexGrid fine(ds);
    const auto coarse = DelaunayCoarseGrid::hierarchyBelow(comm, fine.vertexGraph(), 10);
    ASSERT_TRUE(coarse);
    const auto& xyz = ds->space().nodeCoordinates();
    for (long long v = 0; v < ds->mesh().numVertices(); ++v) {
      const double* x = &xyz[dim * v];
      long long vertices[4];
      double weights[4], sum = 0.0, back[3] = {0, 0, 0};
      coarse->interpolation(x, vertices, weights);
      for (int k = 0; k <= dim; ++k) {
        EXPECT_GE(weights[k], 0.0);
        sum += weights[k];
        double at[3];
        coarse->vertexCoordinates(vertices[k], at);
        for (int c = 0; c < dim; ++c) back[c] += weights[k] * at[c];
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      // The coarse grid keeps the box's corners (BoundaryFeatures): every vertex is inside it.
      for (int c = 0; c < dim; ++c) EXPECT_NEAR(back[c], x[c], 1e-12) << dim << "D vertex " << v;
    }
    // Far outside: the nearest cell's weights, clamped.
    const double away[3] = {3.0, 0.5, 0.5};
    long long vertices[4];
    double weights[4], sum = 0.0;
    coarse->interpolation(away, vertices, weights);
    for (int k = 0; k <= dim; ++k) {
      EXPECT_GE(weights[k], 0.0);
      sum += weights[k];
      double at[3];
      coarse->vertexCoordinates(vertices[k], at);
      if (weights[k] > 1e-12) {
        EXPECT_GT(at[0], 0.6) << dim << "D: a vertex far from the nearest side";
      }
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
}

TEST(DelaunayCoarseGrid, EachBodyHasItsOwnGrid) {
  const auto comm = Tpetra::getDefaultComm();
  const int dim = 2;
  const auto ds = space(comm, dim, 24, /*twoBodies=*/true);
  const MeshVertexGrid fine(ds);
  const VertexGraph graph = fine.vertexGraph();
  const auto coarse = DelaunayCoarseGrid::hierarchyBelow(comm, graph, 10);
  ASSERT_TRUE(coarse);
  // The bodies are numbered by their nodes' global ids: which one is on the right?
  int localRight = -1, right = -1;
  for (std::size_t v = 0; v < graph.ids.size(); ++v)
    if (graph.coordinates[dim * v] > 1.05) localRight = graph.bodies[v];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &localRight, &right);
  ASSERT_GE(right, 0);
  // A point in the gap between the bodies interpolates from the body asked for only.
  const double gap[2] = {1.05, 0.5};
  for (int body : {0, 1}) {
    long long vertices[3];
    double weights[3];
    coarse->interpolationInBody(gap, body, vertices, weights);
    for (int k = 0; k <= dim; ++k) {
      double at[2];
      coarse->vertexCoordinates(vertices[k], at);
      if (weights[k] > 1e-12) {
        EXPECT_EQ(at[0] > 1.05, body == right) << "body " << body;
      }
    }
  }
  for (std::size_t v = 0; v < graph.ids.size(); ++v) {
    const long long at = coarse->vertexOfBodyAt(&graph.coordinates[dim * v], graph.bodies[v]);
    if (at >= 0) {
      EXPECT_EQ(coarse->vertexOfBodyAt(&graph.coordinates[dim * v], 1 - graph.bodies[v]), -1)
          << "x = " << graph.coordinates[dim * v] << ", body " << graph.bodies[v];
    }
  }
}

}  // namespace
