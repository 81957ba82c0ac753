#include "fe/SimplexMesh.hpp"

#include "signorini/core/Error.hpp"

namespace signorini {

namespace {

int namedTag(const std::map<std::string, int>& tags, const std::string& name, const std::string& what,
             const std::string& plural) {
  const auto it = tags.find(name);
  if (it != tags.end()) return it->second;
  std::string known;
  for (const auto& [other, value] : tags) known += (known.empty() ? "" : ", ") + ("\"" + other + "\"");
  throw InputError("unknown " + what + " \"" + name + "\"; the mesh has: " + (known.empty() ? "no named " + plural : known));
}

}  // namespace

int SimplexMesh::tag(const std::string& boundaryName) const { return namedTag(boundaryTags, boundaryName, "boundary", "boundaries"); }

int SimplexMesh::bodyTag(const std::string& bodyName) const { return namedTag(bodyTags, bodyName, "body", "bodies"); }

void SimplexMesh::cellVertexCoordinates(long long cell, double* coords) const {
  const long long* cellVertices = cells.data() + (dim + 1) * cell;
  for (int v = 0; v <= dim; ++v)
    for (int j = 0; j < dim; ++j) coords[v * dim + j] = vertices[dim * cellVertices[v] + j];
}

std::size_t SimplexMesh::bytes() const {
  std::size_t names = 0;
  for (const auto* tags : {&boundaryTags, &bodyTags})
    for (const auto& [name, value] : *tags) names += sizeof(value) + sizeof(name) + name.capacity() + 32;  // 32: tree node
  for (const std::string& note : notes) names += sizeof(note) + note.capacity();
  return vertices.capacity() * sizeof(double) +
         (cells.capacity() + facets.capacity() + geometryFacets.capacity() + geometryEdges.capacity()) * sizeof(long long) +
         (facetTags.capacity() + cellTags.capacity() + geometryFacetEntities.capacity() + geometryEdgeEntities.capacity()) * sizeof(int) + names;
}

}  // namespace signorini
