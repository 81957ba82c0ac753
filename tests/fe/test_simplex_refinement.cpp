// Uniform refinement of the reference simplex in lattice coordinates: the children fill it
// (volumes add up, none reflected), they form a conforming mesh (every inner facet shared by
// exactly two children, the boundary facets being the red refinement of its facets), and
// each new vertex halves exactly one edge of the level above.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <vector>

#include "fe/SimplexRefinement.hpp"
#include "signorini/core/Error.hpp"

namespace {

using namespace signorini;

// dim! times the signed volume of a lattice simplex, in lattice units.
long long scaledVolume(const LatticeSimplex& cell, int dim) {
  long long m[3][3] = {};
  for (int v = 1; v <= dim; ++v)
    for (int c = 0; c < dim; ++c) m[v - 1][c] = cell[v][c + 1] - cell[0][c + 1];
  if (dim == 1) return m[0][0];
  if (dim == 2) return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

class SimplexRefinementLevels : public ::testing::TestWithParam<int> {};

TEST_P(SimplexRefinementLevels, ChildrenFillTheSimplexConformingly) {
  const int dim = GetParam();
  const SimplexRefinement refinement(dim, 3);
  for (int level = 0; level <= 3; ++level) {
    const auto& cells = refinement.cells(level);
    const long long n = 1LL << level;
    ASSERT_EQ(static_cast<long long>(cells.size()), 1LL << (dim * level));
    long long fullVolume = 1;
    for (int i = 0; i < dim; ++i) fullVolume *= n;
    long long volume = 0;
    std::map<std::vector<LatticePoint>, int> facets;
    for (const LatticeSimplex& cell : cells) {
      const long long v = scaledVolume(cell, dim);
      EXPECT_GT(v, 0) << "level " << level;
      volume += v;
      for (int f = 0; f <= dim; ++f) {
        std::vector<LatticePoint> facet;
        for (int i = 0; i <= dim; ++i)
          if (i != f) facet.push_back(cell[i]);
        std::sort(facet.begin(), facet.end());
        ++facets[facet];
      }
      for (int i = 0; i <= dim; ++i) {
        int sum = 0;
        for (int c = 0; c <= dim; ++c) sum += cell[i][c];
        EXPECT_EQ(sum, n);
      }
    }
    EXPECT_EQ(volume, fullVolume) << "level " << level;
    // A facet on the boundary (some a_i = 0 at all its vertices) is in one child, any other in two.
    long long boundary = 0;
    for (const auto& [facet, count] : facets) {
      bool onBoundary = false;
      for (int c = 0; c <= dim; ++c)
        onBoundary = onBoundary || std::all_of(facet.begin(), facet.end(), [&](const LatticePoint& p) { return p[c] == 0; });
      EXPECT_EQ(count, onBoundary ? 1 : 2) << "level " << level;
      boundary += onBoundary;
    }
    EXPECT_EQ(boundary, (dim + 1) * (1LL << ((dim - 1) * level))) << "level " << level;
  }
}

TEST_P(SimplexRefinementLevels, NewVerticesHalveOneEdgeOfTheLevelAbove) {
  const int dim = GetParam();
  const SimplexRefinement refinement(dim, 3);
  for (int level = 1; level <= 3; ++level) {
    std::set<std::pair<LatticePoint, LatticePoint>> edgesAbove;
    for (const LatticeSimplex& cell : refinement.cells(level - 1))
      for (int i = 0; i <= dim; ++i)
        for (int j = 0; j <= dim; ++j) edgesAbove.insert({cell[i], cell[j]});
    for (const LatticeSimplex& cell : refinement.cells(level))
      for (int i = 0; i <= dim; ++i) {
        const auto& [a, b] = refinement.parents(level, cell[i]);
        EXPECT_TRUE(edgesAbove.count({a, b})) << "level " << level;  // (a, a) for an old vertex
        for (int c = 0; c < 4; ++c) EXPECT_EQ(a[c] + b[c], cell[i][c]);
      }
  }
  EXPECT_THROW(refinement.parents(1, LatticePoint{1, 0, 0, 0}), Error);  // odd sum: no point of level 1
}

INSTANTIATE_TEST_SUITE_P(Dimensions, SimplexRefinementLevels, ::testing::Values(1, 2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

}  // namespace
