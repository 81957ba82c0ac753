#pragma once
// The Delaunay triangulation of a point set (triangles in 2D, tetrahedra in 3D) by CGAL's
// Delaunay_triangulation_2 and _3 with exact predicates, less the flat slivers on the convex
// hull: the cells whose circumsphere reaches a corner of the points' bounding box enlarged by
// a fifth of its extent on every side (those a triangulation with these corners added would
// not have). Why: a sliver's long edges join points far apart, and a multigrid level of these
// cells would interpolate across them. The same points in the same order give the same cells
// in any process (CGAL's spatial sort of the input shuffles it with a fixed seed).
#include <vector>

namespace signorini {

// The cells, dim + 1 indices (from 0) into the `points` (dim coordinates per point) per
// cell, each positively oriented; cells of round-off volume (flat ones on the hull of points
// in a plane) are left out. A point given twice is a vertex once (the first). Throws
// InputError for a dimension other than 2 or 3.
std::vector<long long> delaunayCells(int dim, const std::vector<double>& points);

}  // namespace signorini
