#pragma once
// The orientation of a simplex from its vertices' coordinates, the test every mesh reader
// applies to its cells: positive, negative (two vertices to swap) or degenerate.
namespace signorini {

// +1 or -1, the sign of the determinant of the edge vectors from vertex 0 of the simplex
// whose dim + 1 vertices are at x (dim coordinates each); 0 if the simplex is degenerate: its
// determinant at most 1e-12 times its longest edge to the power dim.
int simplexOrientation(int dim, const double* x);

}  // namespace signorini
