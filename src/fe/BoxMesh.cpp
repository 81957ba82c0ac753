#include "fe/BoxMesh.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "fe/BoxGrid.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// A simplex of the box subdivision, as box corners: corner bit a (x), 2b (y), 4c (z) is the
// vertex v_abc = (i+a, j+b, k+c) of doc/benchmark-family.md.
using CornerSimplex = std::array<int, 4>;

int cornerOffset(int corner, int axis) { return (corner >> axis) & 1; }

// Swaps the last two vertices of negatively oriented simplices, so every cell has a positive
// Jacobian determinant (the vertex sets stay those of doc/benchmark-family.md).
std::vector<CornerSimplex> positivelyOriented(int dim, std::vector<CornerSimplex> simplices) {
  for (auto& s : simplices) {
    double edge[3][3] = {};
    for (int e = 0; e < dim; ++e)
      for (int axis = 0; axis < dim; ++axis)
        edge[e][axis] = cornerOffset(s[e + 1], axis) - cornerOffset(s[0], axis);
    const double det = dim == 2 ? edge[0][0] * edge[1][1] - edge[0][1] * edge[1][0]
                                : edge[0][0] * (edge[1][1] * edge[2][2] - edge[1][2] * edge[2][1]) -
                                      edge[0][1] * (edge[1][0] * edge[2][2] - edge[1][2] * edge[2][0]) +
                                      edge[0][2] * (edge[1][0] * edge[2][1] - edge[1][1] * edge[2][0]);
    if (det < 0) std::swap(s[dim - 1], s[dim]);
  }
  return simplices;
}

}  // namespace

SimplexMesh makeBoxMesh(int dim, const std::array<long long, 3>& cellsPerDirection,
                        const std::array<double, 3>& lengths) {
  BoxBlock whole;
  for (int axis = 0; axis < dim && axis < 3; ++axis) whole.end[axis] = cellsPerDirection[axis];
  return makeBoxMesh(dim, cellsPerDirection, lengths, whole);
}

SimplexMesh makeBoxMesh(int dim, const std::array<long long, 3>& cellsPerDirection,
                        const std::array<double, 3>& lengths, const BoxBlock& block) {
  if (dim != 2 && dim != 3) throw InputError("box mesh: dimension must be 2 or 3, got " + std::to_string(dim));
  for (int axis = 0; axis < dim; ++axis) {
    if (cellsPerDirection[axis] < 1)
      throw InputError("box mesh: cells per direction must be >= 1, got " + std::to_string(cellsPerDirection[axis]));
    if (!(lengths[axis] > 0)) throw InputError("box mesh: lengths must be > 0, got " + std::to_string(lengths[axis]));
  }
  std::array<long long, 3> n = {1, 1, 1}, begin = {0, 0, 0}, count = {1, 1, 1};
  for (int axis = 0; axis < dim; ++axis) {
    n[axis] = cellsPerDirection[axis];
    begin[axis] = block.begin[axis];
    count[axis] = block.end[axis] - block.begin[axis];
    if (begin[axis] < 0 || count[axis] < 1 || block.end[axis] > n[axis])
      throw InputError("box mesh: a block must be a nonempty range of the boxes");
  }
  // Strides of the block's vertex lattice, and of the whole box's for the coordinates.
  const long long stride[3] = {1, count[0] + 1, (count[0] + 1) * (count[1] + 1)};
  const long long globalStride[3] = {1, n[0] + 1, (n[0] + 1) * (n[1] + 1)};
  const long long numVertices = (count[0] + 1) * (count[1] + 1) * (dim == 3 ? count[2] + 1 : 1);

  SimplexMesh mesh;
  mesh.dim = dim;
  const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  for (int axis = 0; axis < dim; ++axis)
    for (int side = 0; side < 2; ++side) mesh.boundaryTags[names[axis][side]] = 2 * axis + side + 1;

  mesh.vertices.resize(dim * numVertices);
  const BoxGrid grid{dim, n, lengths};
  for (long long v = 0; v < numVertices; ++v) {
    long long global = 0;
    for (int axis = 0; axis < dim; ++axis)
      global += (begin[axis] + (v / stride[axis]) % (count[axis] + 1)) * globalStride[axis];
    grid.vertexCoordinates(global, mesh.vertices.data() + dim * v);
  }

  const std::vector<CornerSimplex> templates[2] = {
      positivelyOriented(dim, boxSimplexCorners(dim, 0)), positivelyOriented(dim, boxSimplexCorners(dim, 1))};
  long long cornerId[8];
  for (int corner = 0; corner < 8; ++corner)
    cornerId[corner] = cornerOffset(corner, 0) * stride[0] + cornerOffset(corner, 1) * stride[1] +
                       (dim == 3 ? cornerOffset(corner, 2) * stride[2] : 0);

  mesh.cells.resize((dim + 1) * simplicesPerBox(dim) * block.numBoxes());
  long long* cell = mesh.cells.data();
  for (long long k = begin[2]; k < begin[2] + count[2]; ++k)
    for (long long j = begin[1]; j < begin[1] + count[1]; ++j)
      for (long long i = begin[0]; i < begin[0] + count[0]; ++i) {
        const long long box[3] = {i, j, k};
        const long long base = (i - begin[0]) + stride[1] * (j - begin[1]) + stride[2] * (k - begin[2]);
        const bool onBoundary = i == 0 || j == 0 || i == n[0] - 1 || j == n[1] - 1 ||
                                (dim == 3 && (k == 0 || k == n[2] - 1));
        for (const CornerSimplex& s : templates[(i + j + k) % 2]) {
          for (int v = 0; v <= dim; ++v) cell[v] = base + cornerId[s[v]];
          // A facet (opposite local vertex f) is on a box face when all its corners share
          // that face's offset and the box touches that face.
          for (int f = 0; onBoundary && f <= dim; ++f)
            for (int axis = 0; axis < dim; ++axis)
              for (int side = 0; side < 2; ++side) {
                if (box[axis] != (side == 0 ? 0 : n[axis] - 1)) continue;
                bool onFace = true;
                for (int v = 0; v <= dim; ++v)
                  if (v != f && cornerOffset(s[v], axis) != side) onFace = false;
                if (!onFace) continue;
                for (int v = 0; v <= dim; ++v)
                  if (v != f) mesh.facets.push_back(cell[v]);
                mesh.facetTags.push_back(2 * axis + side + 1);
              }
          cell += dim + 1;
        }
      }
  return mesh;
}

std::vector<long long> boxBlockCells(int dim, const std::array<long long, 3>& cellsPerDirection,
                                     const BoxBlock& block) {
  const int perBox = simplicesPerBox(dim);
  const long long n0 = cellsPerDirection[0], n1 = cellsPerDirection[1];
  std::vector<long long> cells;
  cells.reserve(perBox * block.numBoxes());
  for (long long k = block.begin[2]; k < block.end[2]; ++k)
    for (long long j = block.begin[1]; j < block.end[1]; ++j)
      for (long long i = block.begin[0]; i < block.end[0]; ++i)
        for (int s = 0; s < perBox; ++s) cells.push_back((i + n0 * (j + n1 * k)) * perBox + s);
  return cells;
}

int BoxDecomposition::numBlocks() const {
  int count = 1;
  for (const auto& axis : splits) count *= axis.empty() ? 0 : static_cast<int>(axis.size()) - 1;
  return count;
}

BoxBlock BoxDecomposition::block(int index) const {
  BoxBlock result;
  for (int axis = 0; axis < 3; ++axis) {
    const int p = static_cast<int>(splits[axis].size()) - 1;
    result.begin[axis] = splits[axis][index % p];
    result.end[axis] = splits[axis][index % p + 1];
    index /= p;
  }
  return result;
}

int BoxDecomposition::lowestBlockHolding(const std::array<long long, 3>& x, int degree) const {
  int index = 0, stride = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& s = splits[axis];
    // The first block whose upper end reaches x: it holds x, on its boundary or inside.
    const auto end = std::lower_bound(s.begin() + 1, s.end(), x[axis],
                                      [degree](long long split, long long point) { return split * degree < point; });
    index += stride * static_cast<int>(end - (s.begin() + 1));
    stride *= static_cast<int>(s.size()) - 1;
  }
  return index;
}

BoxDecomposition decomposeBox(int dim, const std::array<long long, 3>& cellsPerDirection, int numBlocks) {
  std::array<long long, 3> n = {1, 1, 1};
  for (int axis = 0; axis < dim; ++axis) n[axis] = cellsPerDirection[axis];
  std::array<long long, 2> best = {-1, -1};  // (largest block's boxes, interface area)
  std::array<long long, 3> blocks = {0, 0, 0};
  for (long long p0 = numBlocks; p0 >= 1; --p0)
    for (long long p1 = numBlocks / p0; p1 >= 1; --p1) {
      if (numBlocks % p0 != 0 || (numBlocks / p0) % p1 != 0) continue;
      const std::array<long long, 3> p = {p0, p1, numBlocks / p0 / p1};
      if (p[0] > n[0] || p[1] > n[1] || p[2] > n[2]) continue;
      long long largest = 1, area = 0;
      for (int axis = 0; axis < 3; ++axis) {
        largest *= (n[axis] + p[axis] - 1) / p[axis];
        area += (p[axis] - 1) * (n[0] * n[1] * n[2] / n[axis]);
      }
      const std::array<long long, 2> score = {largest, area};
      if (best[0] < 0 || score < best) {
        best = score;
        blocks = p;
      }
    }
  BoxDecomposition result;
  if (best[0] < 0) return result;
  for (int axis = 0; axis < 3; ++axis)
    for (long long b = 0; b <= blocks[axis]; ++b) result.splits[axis].push_back(n[axis] * b / blocks[axis]);
  return result;
}

}  // namespace signorini
