// The R-tree search of facets near a segment against a pass over every facet with the slab
// test of a segment and a box: the same facets, in 2D (the third coordinate zero) and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "assembly/FacetSearch.hpp"
#include "assembly/MortarFacet.hpp"

namespace signorini {
namespace {

// Whether the segment from a to b meets the box [lo, hi] (Kay and Kajiya's slabs).
bool segmentMeetsBox(const std::array<double, 3>& a, const std::array<double, 3>& b, const double* lo,
                     const double* hi) {
  double enter = 0, leave = 1;
  for (int c = 0; c < 3; ++c) {
    const double d = b[c] - a[c];
    if (d == 0) {
      if (a[c] < lo[c] || a[c] > hi[c]) return false;
      continue;
    }
    double t0 = (lo[c] - a[c]) / d, t1 = (hi[c] - a[c]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

std::vector<MortarFacet> randomFacets(int dim, int count, std::mt19937& random) {
  std::uniform_real_distribution<double> where(0, 10), offset(-0.5, 0.5);
  std::vector<MortarFacet> facets(count);
  for (MortarFacet& f : facets) {
    f.dim = dim;
    f.count = dim;
    const double centre[3] = {where(random), where(random), dim == 3 ? where(random) : 0.0};
    for (int v = 0; v < dim; ++v)
      for (int c = 0; c < dim; ++c) f.x[v][c] = centre[c] + offset(random);
  }
  return facets;
}

void expectSameAsEveryFacet(int dim) {
  std::mt19937 random(dim);
  const std::vector<MortarFacet> facets = randomFacets(dim, 500, random);
  const double margin = 0.3;
  const FacetSearch search(facets, margin);
  std::uniform_real_distribution<double> where(-1, 11);
  int found = 0;
  for (int query = 0; query < 200; ++query) {
    std::array<double, 3> a{}, b{};
    for (int c = 0; c < dim; ++c) {
      a[c] = where(random);
      b[c] = query % 4 == 0 ? a[c] : where(random);  // some segments are points
    }
    std::vector<int> expected;
    for (std::size_t i = 0; i < facets.size(); ++i) {
      std::array<double, 6> box = facets[i].boundingBox();
      for (int c = 0; c < 3; ++c) {
        box[c] -= margin;
        box[3 + c] += margin;
      }
      if (segmentMeetsBox(a, b, &box[0], &box[3])) expected.push_back(static_cast<int>(i));
    }
    EXPECT_EQ(search.meeting(a, b), expected) << "query " << query;
    found += static_cast<int>(expected.size());
  }
  EXPECT_GT(found, 200);  // the queries do meet facets
}

TEST(FacetSearch, FindsTheFacetsEveryFacetTestFinds2D) { expectSameAsEveryFacet(2); }
TEST(FacetSearch, FindsTheFacetsEveryFacetTestFinds3D) { expectSameAsEveryFacet(3); }

TEST(FacetSearch, NoFacetsFindNothing) {
  const FacetSearch search({}, 1.0);
  EXPECT_TRUE(search.meeting({0, 0, 0}, {1, 1, 1}).empty());
}

}  // namespace
}  // namespace signorini
