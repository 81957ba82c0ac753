#include "fe/SimplexMesh.hpp"

#include "signorini/core/Error.hpp"

namespace signorini {

int SimplexMesh::tag(const std::string& boundaryName) const {
  const auto it = boundaryTags.find(boundaryName);
  if (it != boundaryTags.end()) return it->second;
  std::string known;
  for (const auto& [name, value] : boundaryTags) known += (known.empty() ? "" : ", ") + ("\"" + name + "\"");
  throw InputError("unknown boundary \"" + boundaryName + "\"; the mesh has: " +
                   (known.empty() ? std::string("no named boundaries") : known));
}

void SimplexMesh::cellVertexCoordinates(long long cell, double* coords) const {
  const long long* cellVertices = cells.data() + (dim + 1) * cell;
  for (int v = 0; v <= dim; ++v)
    for (int j = 0; j < dim; ++j) coords[v * dim + j] = vertices[dim * cellVertices[v] + j];
}

std::size_t SimplexMesh::bytes() const {
  std::size_t names = 0;
  for (const auto& [name, value] : boundaryTags) names += sizeof(value) + sizeof(name) + name.capacity() + 32;  // 32: tree node
  return vertices.capacity() * sizeof(double) +
         (cells.capacity() + facets.capacity() + geometryFacets.capacity() + geometryEdges.capacity()) * sizeof(long long) +
         (facetTags.capacity() + geometryFacetEntities.capacity() + geometryEdgeEntities.capacity()) * sizeof(int) + names;
}

}  // namespace signorini
