// BoxGrid: vertex numbering and coordinates as makeBoxMesh's, and P1 interpolation that
// reproduces linear functions at any point of the box.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fe/BoxGrid.hpp"
#include "fe/BoxMesh.hpp"
#include "support/InterpolationCheck.hpp"

namespace {

using namespace signorini;
using signorini::testing::expectInterpolationReproduces;

BoxGrid grid(int dim, long long n0, long long n1, long long n2) {
  BoxGrid g;
  g.dim = dim;
  g.cells = {n0, n1, n2};
  g.lengths = {2.0, 1.0, 0.5};
  return g;
}

TEST(BoxGrid, VerticesAreThoseOfTheBoxMesh) {
  for (int dim : {2, 3}) {
    const BoxGrid g = grid(dim, 4, 3, 2);
    const SimplexMesh mesh = makeBoxMesh(dim, g.cells, g.lengths);
    ASSERT_EQ(g.numVertices(), mesh.numVertices());
    for (long long v = 0; v < g.numVertices(); ++v) {
      double x[3];
      g.vertexCoordinates(v, x);
      for (int a = 0; a < dim; ++a) EXPECT_EQ(x[a], mesh.vertices[dim * v + a]);
      EXPECT_EQ(g.vertexAt(x), v);
    }
    const double between[3] = {0.25, 0.5, 0.125};  // a quarter cell off in x
    EXPECT_EQ(g.vertexAt(between), -1);
  }
}

TEST(BoxGrid, InterpolationReproducesLinearFunctions) {
  std::mt19937 random(7);
  for (int dim : {2, 3}) {
    const BoxGrid g = grid(dim, 4, 3, 2);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
      double x[3];
      for (int a = 0; a < dim; ++a) x[a] = g.lengths[a] * unit(random);
      if (trial < 20)  // points on the vertices, edges and faces of the subdivision
        for (int a = 0; a < dim; ++a) x[a] = g.lengths[a] * std::round(x[a] / g.lengths[a] * 2 * g.cells[a]) / (2.0 * g.cells[a]);
      expectInterpolationReproduces(g, x);
    }
  }
}

TEST(BoxGrid, InterpolationUsesTheSimplexOfTheMesh) {
  // At the centre of a square, the 2D subdivision's diagonal runs from (i,j) to (i+1,j+1):
  // the interpolation uses those two vertices with weight 1/2 each.
  const BoxGrid g = grid(2, 2, 2, 1);
  const double centre[2] = {0.5, 0.25};  // centre of box (0,0): lengths 2 x 1, 2 cells
  long long vertices[3];
  double weights[3];
  g.interpolation(centre, vertices, weights);
  double onDiagonal = 0.0;
  for (int k = 0; k < 3; ++k)
    if (vertices[k] == 0 || vertices[k] == 4) onDiagonal += weights[k];
  EXPECT_NEAR(onDiagonal, 1.0, 1e-14);
}

}  // namespace
