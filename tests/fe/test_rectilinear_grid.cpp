// RectilinearGrid: the same P1 space as the BoxGrid it is made from; coarsening keeps every
// other vertex line and the last, so every coarse vertex is a fine one; P1 interpolation
// reproduces linear functions on grids with boxes of unequal widths.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fe/BoxGrid.hpp"
#include "fe/RectilinearGrid.hpp"
#include "signorini/core/Error.hpp"
#include "support/InterpolationCheck.hpp"

namespace {

using namespace signorini;
using signorini::testing::expectInterpolationReproduces;

BoxGrid boxGrid(int dim, long long n0, long long n1, long long n2) {
  return BoxGrid(dim, {n0, n1, n2}, {2.0, 1.0, 0.5});
}

// Random points of the grid's box, the first ones on vertices, edges and faces of boxes.
template <class Check>
void forPoints(const GeometricGrid& g, const double* lengths, Check check) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    double x[3] = {0, 0, 0};
    for (int a = 0; a < g.dimension(); ++a) x[a] = lengths[a] * (trial < 20 ? std::round(8 * unit(random)) / 8 : unit(random));
    check(x);
  }
}

TEST(RectilinearGrid, IsTheSpaceOfItsBoxGrid) {
  for (int dim : {2, 3}) {
    const BoxGrid box = boxGrid(dim, 4, 3, 2);
    const RectilinearGrid g(box);
    ASSERT_EQ(g.numVertices(), box.numVertices());
    for (long long v = 0; v < g.numVertices(); ++v) {
      double x[3], y[3];
      g.vertexCoordinates(v, x);
      box.vertexCoordinates(v, y);
      for (int a = 0; a < dim; ++a) EXPECT_EQ(x[a], y[a]);
      EXPECT_EQ(g.vertexAt(x), v);
    }
    // The same interpolant of a vertex function (on a box face the two may pick different,
    // equivalent simplices).
    std::vector<double> f(g.numVertices());
    std::mt19937 random(3);
    for (double& value : f) value = std::uniform_real_distribution<double>(-1.0, 1.0)(random);
    forPoints(g, box.lengths.data(), [&](const double* x) {
      long long v[4], w[4];
      double gw[4], bw[4], gf = 0.0, bf = 0.0;
      g.interpolation(x, v, gw);
      box.interpolation(x, w, bw);
      for (int k = 0; k <= dim; ++k) {
        gf += gw[k] * f[v[k]];
        bf += bw[k] * f[w[k]];
      }
      EXPECT_NEAR(gf, bf, 1e-14);
    });
  }
}

TEST(RectilinearGrid, CoarseningKeepsEveryOtherLineAndTheLast) {
  const RectilinearGrid fine(boxGrid(3, 4, 3, 1));
  const RectilinearGrid coarse = fine.coarsened();
  EXPECT_EQ(coarse.cells(0), 2);
  EXPECT_EQ(coarse.cells(1), 2);  // lines 0, 2 and 3: boxes of widths 2/3 and 1/3
  EXPECT_EQ(coarse.cells(2), 1);
  double x[3];
  coarse.vertexCoordinates(2 * 3, x);  // vertex (0, 2, 0)
  EXPECT_EQ(x[1], 1.0);
  coarse.vertexCoordinates(1 * 3, x);  // vertex (0, 1, 0)
  EXPECT_NEAR(x[1], 2.0 / 3.0, 1e-15);
  for (long long v = 0; v < coarse.numVertices(); ++v) {
    coarse.vertexCoordinates(v, x);
    EXPECT_GE(fine.vertexAt(x), 0) << "coarse vertex " << v;
  }
  // 5 boxes: 3, 2, 1, then no coarser grid.
  std::vector<long long> counts;
  for (auto g = BoxGrid(2, {5, 5, 1}, {1, 1, 1}).coarser(); g; g = g->coarser())
    counts.push_back(dynamic_cast<const RectilinearGrid&>(*g).cells(0));
  EXPECT_EQ(counts, (std::vector<long long>{3, 2, 1}));
}

TEST(RectilinearGrid, InterpolationReproducesLinearFunctionsOnUnequalBoxes) {
  for (int dim : {2, 3}) {
    std::vector<std::vector<double>> lines = {{0.0, 0.3, 1.0, 1.1, 2.0}, {0.0, 0.5, 0.6, 1.0}, {0.0, 0.1, 0.5}};
    lines.resize(dim);
    const RectilinearGrid g(lines);
    const double lengths[3] = {2.0, 1.0, 0.5};
    forPoints(g, lengths, [&](const double* x) { expectInterpolationReproduces(g, x); });
    const double between[3] = {0.2, 0.5, 0.1};  // off a vertex in x only
    EXPECT_EQ(g.vertexAt(between), -1);
  }
}

TEST(RectilinearGrid, RejectsCoordinatesThatDoNotIncrease) {
  EXPECT_THROW(RectilinearGrid({{0.0, 1.0}, {0.0, 0.0, 1.0}}), Error);
  EXPECT_THROW(RectilinearGrid({{0.0, 1.0}, {0.0}}), Error);
  EXPECT_THROW(RectilinearGrid({{0.0, 1.0}}), Error);
}

}  // namespace
