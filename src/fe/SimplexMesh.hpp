#pragma once
// A conforming simplex mesh (triangles in 2D, tetrahedra in 3D) with linear geometry and
// named boundary parts. Plain arrays, so it can be built, read or partitioned anywhere.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace signorini {

struct SimplexMesh {
  int dim = 0;                              // 2 or 3
  std::vector<double> vertices;             // dim * numVertices(), interleaved x, y(, z)
  std::vector<long long> cells;             // (dim + 1) * numCells(), vertex ids
  std::vector<long long> facets;            // dim * numFacets(): boundary facets (edges in 2D, triangles in 3D)
  std::vector<int> facetTags;               // one tag per boundary facet
  std::map<std::string, int> boundaryTags;  // boundary name -> tag
  // The body each cell belongs to: one tag per cell, or empty when the mesh names no bodies
  // (every cell then has tag 0). A Gmsh mesh's bodies are its physical groups of dimension dim.
  std::vector<int> cellTags;
  std::map<std::string, int> bodyTags;  // body name -> tag
  // Of a mesh Gmsh made from a .geo geometry (else empty): the curved geometry entity each
  // facet on the geometry's boundary lies on (a surface in 3D, a curve in 2D; dim vertex ids
  // per facet) and, in 3D, each edge on a curved geometry curve (2 vertex ids per edge), so
  // that a refinement can place new vertices on the geometry. Planes and straight lines are
  // left out: the new vertices already lie on them.
  std::vector<long long> geometryFacets, geometryEdges;
  std::vector<int> geometryFacetEntities, geometryEdgeEntities;
  // What its reader found that the user should hear of, one line each: of a .geo, meshing
  // options that make the mesh change from run to run.
  std::vector<std::string> notes;

  long long numVertices() const { return dim > 0 ? static_cast<long long>(vertices.size()) / dim : 0; }
  long long numCells() const { return dim > 0 ? static_cast<long long>(cells.size()) / (dim + 1) : 0; }
  long long numFacets() const { return dim > 0 ? static_cast<long long>(facets.size()) / dim : 0; }

  // Tag of a named boundary; throws InputError listing the known names if it is absent.
  int tag(const std::string& boundaryName) const;
  // Tag of a named body; throws InputError listing the known names if it is absent.
  int bodyTag(const std::string& bodyName) const;
  int cellTag(long long cell) const { return cellTags.empty() ? 0 : cellTags[cell]; }

  // The cell's (dim + 1) vertices, dim coordinates each, in cell order: the input the
  // element routines expect.
  void cellVertexCoordinates(long long cell, double* coords) const;

  // Heap bytes held by the arrays (their capacities), the boundary names and the notes.
  std::size_t bytes() const;
};

}  // namespace signorini
