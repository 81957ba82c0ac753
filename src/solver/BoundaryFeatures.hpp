#pragma once
// Where a mesh's vertices lie on its boundary: inside, on a face, on an edge or at a corner of
// the domain, found from the mesh alone. Coarse grids made of a mesh's own vertices
// (DelaunayCoarseGrid) keep the corners first, then the edges, then the faces, so that they
// follow the domain's shape as a box's nested grids do.
//
// A boundary facet is a facet of exactly one cell over all ranks. The outward unit normals of
// the boundary facets at a vertex fall into groups of normals less than kFeatureAngle apart
// (greedily, in sorted order); a vertex with g groups lies on a feature of dimension
// dim - min(g, dim): in 3D one group is a face, two an edge, three or more a corner; in 2D
// one is an edge, two or more a corner. A curved boundary turns by less than the angle from
// one facet to the next and stays a face (3D) or an edge (2D).
#include <cstddef>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// The angle (radians) between two boundary facets' normals above which they belong to two
// sides of the domain.
constexpr double kFeatureAngle = 0.5;

// The cells at each of `count` vertices (CSR: cellsAt[at[v] .. at[v + 1]]) of `cells`, dim + 1
// vertex indices per cell.
void cellsAtVertices(int dim, std::size_t count, const std::vector<long long>& cells, std::vector<long long>& at,
                     std::vector<long long>& cellsAt);

// Collective. For each local vertex (ids: global ids, the same on every rank for the same
// vertex; coordinates: dim per vertex), the dimension of the boundary feature it lies on, dim
// for a vertex inside. `cells`: dim + 1 local vertex indices per cell, each cell on one rank
// or on several (a cell held twice is one cell). The same on any rank count.
std::vector<signed char> boundaryFeatureDimensions(const Comm& comm, int dim, const std::vector<long long>& ids,
                                                   const std::vector<double>& coordinates,
                                                   const std::vector<long long>& cells);

}  // namespace signorini
