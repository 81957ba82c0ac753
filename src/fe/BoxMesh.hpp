#pragma once
// Structured simplex mesh of a box, subdivided exactly as doc/benchmark-family.md defines:
// each square cut along its (i,j)-(i+1,j+1) diagonal in 2D, each cube cut into five
// tetrahedra whose pattern alternates with the parity of i+j+k in 3D.
#include <array>
#include <vector>

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

// Simplices per box: 2 triangles in 2D, 5 tetrahedra in 3D.
inline int simplicesPerBox(int dim) { return dim == 2 ? 2 : 5; }

// The boxes [begin[a], end[a]) along each axis a (entries past dim: 0 and 1).
struct BoxBlock {
  std::array<long long, 3> begin = {0, 0, 0}, end = {1, 1, 1};
  long long numBoxes() const { return (end[0] - begin[0]) * (end[1] - begin[1]) * (end[2] - begin[2]); }
};

// The part of makeBoxMesh(dim, cellsPerDirection, lengths) made of the boxes of one block:
// its cells in global order with the global cells' vertex order, its vertices in global
// order (vertex (i,j,k) of the block has id (i-b0) + (e0-b0+1)*((j-b1) + (e1-b1+1)*(k-b2))),
// and the boundary facets of its cells, tagged as in the whole mesh. The whole block gives
// makeBoxMesh's mesh. Throws InputError as makeBoxMesh does, or for a block outside the box.
SimplexMesh makeBoxMesh(int dim, const std::array<long long, 3>& cellsPerDirection,
                        const std::array<double, 3>& lengths, const BoxBlock& block);

// Global id, in makeBoxMesh's numbering, of each cell of the block's mesh.
std::vector<long long> boxBlockCells(int dim, const std::array<long long, 3>& cellsPerDirection, const BoxBlock& block);

// The boxes cut into p0 x p1 (x p2) blocks: along axis a, block b holds the boxes
// [splits[a][b], splits[a][b + 1]); block b0 + p0 (b1 + p1 b2) is block number b0, b1, b2.
struct BoxDecomposition {
  std::array<std::vector<long long>, 3> splits;  // p_a + 1 entries for each axis

  int numBlocks() const;
  BoxBlock block(int index) const;
  // The lowest-numbered block whose closed region holds the point x / degree (x in units of
  // the box size divided by degree: the lattice of the P_degree nodes).
  int lowestBlockHolding(const std::array<long long, 3>& x, int degree) const;
};

// numBlocks blocks of about equal size. Of all factorizations p0 p1 p2 = numBlocks with
// p_a <= the box count along axis a: the fewest boxes in the largest block, then the
// smallest interface area, then the most blocks along the first axes. Empty splits (no
// block) when no factorization fits.
BoxDecomposition decomposeBox(int dim, const std::array<long long, 3>& cellsPerDirection, int numBlocks);

}  // namespace signorini
