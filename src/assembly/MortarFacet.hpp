#pragma once
// Private to the library: a facet of a body's boundary as the mortar integration sees it (a
// segment in 2D, a triangle in 3D, P1 to P3 on affine facets): its nodes' global ids and
// coordinates, the vertices first, each node's lattice index on the facet, and the outward
// normal of its body. Plain data, so that ranks can send each other the facets they need.
//
// Points on a facet are given by their barycentric coordinates over its vertices; a point
// off its plane (line) by those of its orthogonal projection, the projection along the
// facet's normal.
#include <array>
#include <vector>

#include "assembly/DistributedSpace.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

struct MortarFacet {
  static constexpr int kMaxNodes = 10;  // a P3 triangle

  int dim = 0;  // of the space: 2 (a segment) or 3 (a triangle)
  int degree = 1;
  int count = 0;
  GlobalOrdinal nodes[kMaxNodes] = {};
  double x[kMaxNodes][3] = {};
  int lattice[kMaxNodes][3] = {};  // degree times the node's barycentric coordinates
  double normal[3] = {};

  // The facet's length (2D) or area (3D).
  double measure() const;
  // The barycentric coordinates of p's projection onto the facet's line or plane.
  void barycentric(const double* p, double* lambda) const;
  // The point at barycentric coordinates lambda.
  void point(const double* lambda, double* p) const;
  // The values of the Lagrange functions of the facet's nodes at barycentric coordinates lambda.
  void shapeValues(const double* lambda, double* values) const;
  // Lower corner then upper corner (the third coordinate 0 in 2D).
  std::array<double, 6> boundingBox() const;
};

// The boundary facets of this rank's part with the given tag, each with its cell and local facet.
struct LocalFacets {
  std::vector<MortarFacet> facets;
  std::vector<std::pair<long long, int>> cellFacets;
};
LocalFacets boundaryFacets(const DistributedSpace& space, int tag);

// The mean outward normal of the boundary with the given tag over every rank: its facets'
// unit normals weighted by their measures, over their total measure (length 1 for a flat
// boundary, near 0 for one that faces every way). Collective.
std::array<double, 3> meanOutwardNormal(const DistributedSpace& space, int tag);

// The pieces of `slave` that `master` covers when projected onto it along the slave's normal:
// simplices of the slave facet (segments in 2D, the triangles of the clipped polygon in 3D),
// each given by the barycentric coordinates over the slave's vertices of its dim vertices.
// Empty where the projections do not overlap.
std::vector<std::array<std::array<double, 3>, 3>> projectedOverlap(const MortarFacet& slave, const MortarFacet& master);

// Facets as doubles, to send between ranks, and back.
void pack(const MortarFacet& facet, std::vector<double>& out);
std::vector<MortarFacet> unpackFacets(const std::vector<double>& in);

}  // namespace signorini
