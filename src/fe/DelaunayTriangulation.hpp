#pragma once
// The Delaunay triangulation of a point set (triangles in 2D, tetrahedra in 3D) by Gmsh's
// mesher (gmsh::model::mesh::triangulate, tetrahedralize): it covers the points' convex hull.
// Gmsh runs in a forked child, as for reading a mesh (GmshSandbox.hpp).
#include <vector>

namespace signorini {

// The cells, dim + 1 indices (from 0) into the `points` (dim coordinates per point) per
// cell, each positively oriented; cells of round-off volume (flat ones on the hull of points
// in a plane) are left out. Throws InputError for a dimension other than 2 or 3, Error if
// Gmsh fails.
std::vector<long long> delaunayCells(int dim, const std::vector<double>& points);

}  // namespace signorini
