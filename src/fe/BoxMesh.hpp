#pragma once
// Structured simplex mesh of a box, subdivided exactly as doc/benchmark-family.md defines:
// each square cut along its (i,j)-(i+1,j+1) diagonal in 2D, each cube cut into five
// tetrahedra whose pattern alternates with the parity of i+j+k in 3D.
#include <array>

#include "fe/SimplexMesh.hpp"

namespace signorini {

// Mesh of [0,L0]x[0,L1](x[0,L2]) with cellsPerDirection[i] boxes along axis i (entries past
// dim are ignored). Vertex (i,j,k) has id i + (n0+1)*(j + (n1+1)*k). Cells are listed box by
// box (x fastest), each box's simplices in doc/benchmark-family.md's order, with its vertex order
// except that the last two vertices are swapped where that listing is negatively oriented,
// so every cell has a positive Jacobian. Boundary names and tags: "xmin" 1, "xmax" 2,
// "ymin" 3, "ymax" 4 (+ "zmin" 5, "zmax" 6 in 3D); each boundary facet has the tag of the
// box face it lies on. Throws InputError for dim not 2 or 3, counts < 1 or lengths <= 0.
SimplexMesh makeBoxMesh(int dim, const std::array<long long, 3>& cellsPerDirection,
                        const std::array<double, 3>& lengths);

}  // namespace signorini
