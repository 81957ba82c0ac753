#include "fe/SimplexMesh.hpp"

#include <gtest/gtest.h>

#include <string>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

SimplexMesh twoTriangles() {
  SimplexMesh mesh;
  mesh.dim = 2;
  mesh.vertices = {0, 0, 1, 0, 0, 1, 1, 1};
  mesh.cells = {0, 1, 3, 0, 3, 2};
  mesh.facets = {0, 1, 2, 3};
  mesh.facetTags = {7, 9};
  mesh.boundaryTags = {{"bottom", 7}, {"top", 9}};
  return mesh;
}

TEST(SimplexMesh, Counts) {
  const SimplexMesh mesh = twoTriangles();
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numCells(), 2);
  EXPECT_EQ(mesh.numFacets(), 2);
  EXPECT_EQ(SimplexMesh().numCells(), 0);
}

TEST(SimplexMesh, TagOfKnownBoundary) {
  const SimplexMesh mesh = twoTriangles();
  EXPECT_EQ(mesh.tag("bottom"), 7);
  EXPECT_EQ(mesh.tag("top"), 9);
}

TEST(SimplexMesh, UnknownBoundaryListsKnownNames) {
  const SimplexMesh mesh = twoTriangles();
  try {
    mesh.tag("left");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("left"), std::string::npos) << message;
    EXPECT_NE(message.find("bottom"), std::string::npos) << message;
    EXPECT_NE(message.find("top"), std::string::npos) << message;
  }
}

TEST(SimplexMesh, CellVertexCoordinates) {
  const SimplexMesh mesh = twoTriangles();
  double x[6];
  mesh.cellVertexCoordinates(1, x);
  const double expected[6] = {0, 0, 1, 1, 0, 1};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(x[i], expected[i]) << i;
}

}  // namespace
}  // namespace signorini
