#include "assembly/FacetSearch.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

// Boost 1.74's geometry strategies include a header of its own that it marks deprecated.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/geometries/segment.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/geometry/strategies/strategies.hpp>

namespace signorini {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using Point = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Segment = bg::model::segment<Point>;
using Entry = std::pair<Box, int>;

struct FacetSearch::Tree {
  bgi::rtree<Entry, bgi::rstar<16>> rtree;
};

FacetSearch::FacetSearch(const std::vector<MortarFacet>& facets, double margin) : tree_(new Tree) {
  std::vector<Entry> entries;
  entries.reserve(facets.size());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    const std::array<double, 6> b = facets[i].boundingBox();
    entries.emplace_back(Box(Point(b[0] - margin, b[1] - margin, b[2] - margin),
                             Point(b[3] + margin, b[4] + margin, b[5] + margin)),
                         static_cast<int>(i));
  }
  tree_->rtree = bgi::rtree<Entry, bgi::rstar<16>>(entries.begin(), entries.end());  // packed
}

FacetSearch::~FacetSearch() = default;
FacetSearch::FacetSearch(FacetSearch&&) noexcept = default;
FacetSearch& FacetSearch::operator=(FacetSearch&&) noexcept = default;

std::vector<int> FacetSearch::meeting(const std::array<double, 3>& a, const std::array<double, 3>& b) const {
  std::vector<Entry> found;
  tree_->rtree.query(bgi::intersects(Segment(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]))),
                     std::back_inserter(found));
  std::vector<int> indices;
  indices.reserve(found.size());
  for (const Entry& e : found) indices.push_back(e.second);
  std::sort(indices.begin(), indices.end());
  return indices;
}

}  // namespace signorini
