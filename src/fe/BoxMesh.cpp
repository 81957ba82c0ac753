#include "fe/BoxMesh.hpp"

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
  if (dim != 2 && dim != 3) throw InputError("box mesh: dimension must be 2 or 3, got " + std::to_string(dim));
  for (int axis = 0; axis < dim; ++axis) {
    if (cellsPerDirection[axis] < 1)
      throw InputError("box mesh: cells per direction must be >= 1, got " + std::to_string(cellsPerDirection[axis]));
    if (!(lengths[axis] > 0)) throw InputError("box mesh: lengths must be > 0, got " + std::to_string(lengths[axis]));
  }
  std::array<long long, 3> n = {1, 1, 1};
  for (int axis = 0; axis < dim; ++axis) n[axis] = cellsPerDirection[axis];
  const long long stride[3] = {1, n[0] + 1, (n[0] + 1) * (n[1] + 1)};
  const long long numVertices = (n[0] + 1) * (n[1] + 1) * (dim == 3 ? n[2] + 1 : 1);
  const long long numBoxes = n[0] * n[1] * n[2];
  const int simplicesPerBox = dim == 2 ? 2 : 5;

  SimplexMesh mesh;
  mesh.dim = dim;
  const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  for (int axis = 0; axis < dim; ++axis)
    for (int side = 0; side < 2; ++side) mesh.boundaryTags[names[axis][side]] = 2 * axis + side + 1;

  mesh.vertices.resize(dim * numVertices);
  const BoxGrid grid{dim, n, lengths};
  for (long long v = 0; v < numVertices; ++v) grid.vertexCoordinates(v, mesh.vertices.data() + dim * v);

  const std::vector<CornerSimplex> templates[2] = {
      positivelyOriented(dim, boxSimplexCorners(dim, 0)), positivelyOriented(dim, boxSimplexCorners(dim, 1))};
  long long cornerId[8];
  for (int corner = 0; corner < 8; ++corner)
    cornerId[corner] = cornerOffset(corner, 0) * stride[0] + cornerOffset(corner, 1) * stride[1] +
                       (dim == 3 ? cornerOffset(corner, 2) * stride[2] : 0);

  mesh.cells.resize((dim + 1) * simplicesPerBox * numBoxes);
  // Two facets per boundary square in 3D, one per boundary segment in 2D.
  const long long numFacets = dim == 2 ? 2 * (n[0] + n[1]) : 4 * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2]);
  mesh.facets.reserve(dim * numFacets);
  mesh.facetTags.reserve(numFacets);
  long long* cell = mesh.cells.data();
  for (long long k = 0; k < n[2]; ++k)
    for (long long j = 0; j < n[1]; ++j)
      for (long long i = 0; i < n[0]; ++i) {
        const long long box[3] = {i, j, k};
        const long long base = i + stride[1] * j + stride[2] * k;
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

}  // namespace signorini
