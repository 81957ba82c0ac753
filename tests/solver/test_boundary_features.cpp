// The boundary features of a mesh's vertices: corners, edges and faces of a box, found from
// its cells alone on any rank count; a curved boundary is no corner; a cell held by two
// ranks counts once. And the Delaunay coarse grids, which keep the corners of the box and
// the vertices on its edges at every level.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/MeshVertexGrid.hpp"
#include "solver/BoundaryFeatures.hpp"
#include "solver/DelaunayCoarseGrid.hpp"
#include "solver/preconditioner/LocalBlock.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// How many coordinates of x lie on the unit box's sides: the dimension of the feature is dim
// less that.
int sidesAt(int dim, const double* x) {
  int sides = 0;
  for (int c = 0; c < dim; ++c) sides += x[c] < 1e-9 || x[c] > 1 - 1e-9;
  return sides;
}

VertexGraph boxGraph(const RCP<const Comm>& comm, int dim, long long n) {
  auto mesh = std::make_shared<const SimplexMesh>(signorini::testing::distortedBoxMesh(dim, n));
  auto space = std::make_shared<const DistributedSpace>(comm, comm->getRank() == 0 ? mesh : nullptr, 1);
  return MeshVertexGrid(space).vertexGraph();
}

TEST(BoundaryFeatures, CornersEdgesAndFacesOfABox) {
  const auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3}) {
    const VertexGraph g = boxGraph(comm, dim, dim == 2 ? 12 : 6);
    ASSERT_EQ(g.features.size(), g.ids.size());
    for (std::size_t v = 0; v < g.ids.size(); ++v)
      EXPECT_EQ(g.features[v], dim - sidesAt(dim, &g.coordinates[dim * v])) << dim << "D vertex " << g.ids[v];
  }
}

TEST(BoundaryFeatures, ACellHeldTwiceIsOneCell) {
  // The same cells given twice, on one rank.
  const SimplexMesh mesh = signorini::testing::distortedBoxMesh(3, 4);
  std::vector<long long> twice = mesh.cells;
  twice.insert(twice.end(), mesh.cells.begin(), mesh.cells.end());
  std::vector<long long> ids(mesh.numVertices());
  for (std::size_t v = 0; v < ids.size(); ++v) ids[v] = static_cast<long long>(v);
  const std::vector<signed char> features = boundaryFeatureDimensions(*selfComm(), 3, ids, mesh.vertices, twice);
  for (long long v = 0; v < mesh.numVertices(); ++v)
    EXPECT_EQ(features[v], 3 - sidesAt(3, &mesh.vertices[3 * v])) << "vertex " << v;
}

TEST(BoundaryFeatures, ACurvedBoundaryHasNoCorners) {
  // A disk of 32 triangles around its centre: the boundary turns by 11.25 degrees at each
  // vertex, less than the feature angle.
  const int segments = 32;
  std::vector<long long> ids{0}, cells;
  std::vector<double> xyz{0.0, 0.0};
  for (int i = 0; i < segments; ++i) {
    ids.push_back(i + 1);
    xyz.insert(xyz.end(), {std::cos(2 * M_PI * i / segments), std::sin(2 * M_PI * i / segments)});
    cells.insert(cells.end(), {0, i + 1, (i + 1) % segments + 1});
  }
  const std::vector<signed char> features = boundaryFeatureDimensions(*selfComm(), 2, ids, xyz, cells);
  EXPECT_EQ(features[0], 2);
  for (int i = 1; i <= segments; ++i) EXPECT_EQ(features[i], 1) << "vertex " << i;
}

TEST(BoundaryFeatures, DelaunayCoarseGridsKeepTheBoxCornersAndEdges) {
  const auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3}) {
    const VertexGraph fine = boxGraph(comm, dim, dim == 2 ? 24 : 8);
    const auto coarse = DelaunayCoarseGrid::hierarchyBelow(comm, fine, 10);
    ASSERT_TRUE(coarse);
    int level = 1;
    for (auto grid = std::static_pointer_cast<const GeometricGrid>(coarse); grid; grid = grid->coarser(), ++level) {
      int corners = 0, onEdges = 0;
      for (long long v = 0; v < grid->numVertices(); ++v) {
        double x[3];
        grid->vertexCoordinates(v, x);
        corners += sidesAt(dim, x) == dim;
        onEdges += sidesAt(dim, x) == dim - 1;
      }
      // Every level covers the box, the hull of its corners.
      EXPECT_EQ(corners, 1 << dim) << dim << "D level " << level;
      // On the first, the n - 1 vertices inside each side of the square or edge of the cube
      // less the two next to its corners are a path, of which a third at least are kept.
      if (level == 1) {
        EXPECT_GE(onEdges, dim == 2 ? 4 * 7 : 12 * 2) << dim << "D";
      }
    }
  }
}

}  // namespace
