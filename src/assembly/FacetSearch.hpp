#pragma once
// Private to the library: which of a set of facets may meet a segment, for the mortar
// integration's search of the master facets that a slave facet's normal line reaches. The
// facets' bounding boxes, grown by a margin, are held in an R-tree (Boost.Geometry), so a
// query costs O(log n + its answer) instead of a pass over every facet.
#include <array>
#include <memory>
#include <vector>

#include "assembly/MortarFacet.hpp"

namespace signorini {

class FacetSearch {
 public:
  // The bounding boxes of `facets` (copied), each grown by `margin` in every direction.
  FacetSearch(const std::vector<MortarFacet>& facets, double margin);
  ~FacetSearch();
  FacetSearch(FacetSearch&&) noexcept;
  FacetSearch& operator=(FacetSearch&&) noexcept;

  // The indices of the facets whose grown box meets the segment from `a` to `b`, ascending.
  std::vector<int> meeting(const std::array<double, 3>& a, const std::array<double, 3>& b) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace signorini
