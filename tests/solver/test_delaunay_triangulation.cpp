// delaunayCells: positively oriented cells with empty circumspheres (the Delaunay property,
// checked against every point), covering the points' convex hull but for the flat slivers on
// it, and so none of large circumsphere; the same cells for the same points; degenerate input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "solver/DelaunayTriangulation.hpp"
#include "signorini/core/Error.hpp"

namespace {

using signorini::delaunayCells;

std::vector<double> randomPoints(int dim, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> points(dim * count);
  for (double& x : points) x = unit(random);
  return points;
}

// The circumcenter of cell c (solving 2 (v_i - v_0) . x = |v_i|^2 - |v_0|^2) and the squared radius.
double circumsphere(int dim, const std::vector<double>& points, const long long* cell, double* center) {
  double a[3][4] = {};
  for (int i = 0; i < dim; ++i) {
    for (int k = 0; k < dim; ++k) {
      const double p = points[dim * cell[i + 1] + k], q = points[dim * cell[0] + k];
      a[i][k] = 2.0 * (p - q);
      a[i][3] += p * p - q * q;
    }
  }
  for (int i = 0; i < dim; ++i) {  // Gauss-Jordan with partial pivoting
    for (int r = i + 1; r < dim; ++r)
      if (std::abs(a[r][i]) > std::abs(a[i][i])) std::swap(a[r], a[i]);
    for (int r = 0; r < dim; ++r)
      if (r != i) {
        const double f = a[r][i] / a[i][i];
        for (int k = 0; k < 4; ++k) a[r][k] -= f * a[i][k];
      }
  }
  double radius = 0.0;
  for (int k = 0; k < dim; ++k) {
    center[k] = a[k][3] / a[k][k];
    radius += std::pow(center[k] - points[dim * cell[0] + k], 2);
  }
  return radius;
}

double signedMeasure(int dim, const std::vector<double>& points, const long long* cell) {
  double e[3][3] = {};
  for (int i = 0; i < dim; ++i)
    for (int k = 0; k < dim; ++k) e[i][k] = points[dim * cell[i + 1] + k] - points[dim * cell[0] + k];
  if (dim == 2) return (e[0][0] * e[1][1] - e[0][1] * e[1][0]) / 2.0;
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6.0;
}

class DelaunayCells : public ::testing::TestWithParam<int> {};

// Random points in the unit square / cube and a lattice of 5 per edge on its boundary: the
// vertices a coarse grid of a box-shaped body has, whose hull is the box.
std::vector<double> boxPoints(int dim, int count) {
  std::vector<double> points = randomPoints(dim, count, 5);
  for (int k = 0; k < (dim == 3 ? 5 : 1); ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const double x[3] = {i / 4.0, j / 4.0, k / 4.0};
        bool boundary = false;
        for (int c = 0; c < dim; ++c) boundary = boundary || x[c] == 0.0 || x[c] == 1.0;
        if (boundary) points.insert(points.end(), x, x + dim);
      }
  return points;
}

TEST_P(DelaunayCells, AreOrientedWithEmptyCircumspheresAndFillTheHull) {
  const int dim = GetParam();
  const std::vector<double> points = boxPoints(dim, dim == 2 ? 400 : 300);
  const std::vector<long long> cells = delaunayCells(dim, points);
  ASSERT_FALSE(cells.empty());
  ASSERT_EQ(cells.size() % (dim + 1), 0u);
  double measure = 0.0;
  for (std::size_t c = 0; c < cells.size(); c += dim + 1) {
    const double m = signedMeasure(dim, points, &cells[c]);
    EXPECT_GT(m, 0.0) << "cell " << c / (dim + 1) << " is not positively oriented";
    measure += m;
    double center[3];
    const double radius = circumsphere(dim, points, &cells[c], center);
    for (std::size_t p = 0; p < points.size() / dim; ++p) {
      double distance = 0.0;
      for (int k = 0; k < dim; ++k) distance += std::pow(points[dim * p + k] - center[k], 2);
      EXPECT_GE(distance, radius * (1.0 - 1e-9)) << "point " << p << " inside the circumsphere of cell " << c / (dim + 1);
    }
  }
  // The hull, the unit square / cube, less the slivers on its sides.
  EXPECT_GT(measure, 0.98);
  EXPECT_LE(measure, 1.0 + 1e-12);
}

// Without points on its sides, a box's random points have a convex hull of few, far apart
// vertices, and the Delaunay triangulation of that hull has flat slivers along it: cells of
// points near one side whose circumspheres reach far outside the box. A sphere through points
// of the bounding box [l, h] with radius R > diag^2 / (0.4 min extent) (diag: that of the box
// enlarged by a fifth of its extent on every side) holds a corner of the enlarged box, so
// none of the cells kept can have one.
TEST_P(DelaunayCells, OfRandomPointsHaveNoSliversOnTheHull) {
  const int dim = GetParam();
  for (unsigned seed : {3u, 4u, 7u}) {
    const std::vector<double> points = randomPoints(dim, dim == 2 ? 400 : 300, seed);
    double low[3] = {1, 1, 1}, high[3] = {0, 0, 0}, squaredDiagonal = 0.0, smallestExtent = 1.0;
    for (std::size_t p = 0; p < points.size(); ++p) {
      low[p % dim] = std::min(low[p % dim], points[p]);
      high[p % dim] = std::max(high[p % dim], points[p]);
    }
    for (int c = 0; c < dim; ++c) {
      squaredDiagonal += std::pow(1.4 * (high[c] - low[c]), 2);
      smallestExtent = std::min(smallestExtent, high[c] - low[c]);
    }
    const double largestRadius = squaredDiagonal / (0.4 * smallestExtent);
    const std::vector<long long> cells = delaunayCells(dim, points);
    ASSERT_FALSE(cells.empty());
    for (std::size_t c = 0; c < cells.size(); c += dim + 1) {
      double center[3];
      EXPECT_LE(std::sqrt(circumsphere(dim, points, &cells[c], center)), largestRadius)
          << "seed " << seed << ": cell " << c / (dim + 1) << " is a sliver on the hull";
    }
  }
}

TEST_P(DelaunayCells, AreTheSameForTheSamePoints) {
  const int dim = GetParam();
  const std::vector<double> points = randomPoints(dim, 2000, 9);
  EXPECT_EQ(delaunayCells(dim, points), delaunayCells(dim, points));
}

TEST_P(DelaunayCells, OfALatticeCoverItsBox) {
  // Cospherical points everywhere: the cells are still a triangulation of the box.
  const int dim = GetParam();
  const int n = 6;
  std::vector<double> points;
  for (int k = 0; k < (dim == 3 ? n : 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        points.insert(points.end(), {i / (n - 1.0), j / (n - 1.0)});
        if (dim == 3) points.push_back(k / (n - 1.0));
      }
  const std::vector<long long> cells = delaunayCells(dim, points);
  double measure = 0.0;
  for (std::size_t c = 0; c < cells.size(); c += dim + 1) measure += signedMeasure(dim, points, &cells[c]);
  EXPECT_NEAR(measure, 1.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, DelaunayCells, ::testing::Values(2, 3));

TEST(DelaunayCellsInput, PointsInAPlaneOfSpaceHaveNoCells) {
  std::vector<double> points;
  for (int i = 0; i < 20; ++i) points.insert(points.end(), {std::cos(i * 0.3), std::sin(i * 0.7), 0.5});
  EXPECT_TRUE(delaunayCells(3, points).empty());
  EXPECT_TRUE(delaunayCells(2, {0.0, 0.0, 1.0, 0.0}).empty());  // fewer points than a cell has
}

TEST(DelaunayCellsInput, ADimensionOtherThanTwoOrThreeIsAnInputError) {
  EXPECT_THROW(delaunayCells(4, randomPoints(4, 10, 1)), signorini::InputError);
}

}  // namespace
