#include "fe/GmshMesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <fstream>
#include <mutex>
#include <new>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/SplitMixHash.hpp"
#include "fe/GmshSandbox.hpp"
#include "fe/SimplexOrientation.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

using detail::answerFromChild;
using detail::readAll;
using detail::receiveArray;
using detail::sendArray;
using detail::writeAll;

using Tag = std::size_t;  // Gmsh node and element tags

constexpr int kLineType = 1;         // 2-node line
constexpr int kTriangleType = 2;     // 3-node triangle
constexpr int kTetrahedronType = 4;  // 4-node tetrahedron

int simplexType(int d) { return d == 1 ? kLineType : d == 2 ? kTriangleType : kTetrahedronType; }

std::string simplexDescription(int d) {
  return d == 1   ? "2-node lines (Gmsh type 1)"
         : d == 2 ? "3-node triangles (Gmsh type 2)"
                  : "4-node tetrahedra (Gmsh type 4)";
}

// ---------------------------------------------------------------------------------------
// What is taken from Gmsh, before any checking.

struct ElementBlock {
  int type = 0;
  std::vector<Tag> elementTags;
  std::vector<Tag> nodeTags;  // numNodes(type) per element
  int entity = -1;            // the geometric entity the elements belong to
};

struct BoundaryGroup {
  int tag = 0;
  std::string name;
  std::vector<ElementBlock> blocks;
};

std::string boundaryName(const BoundaryGroup& group) {
  return group.name.empty() ? "physical" + std::to_string(group.tag) : group.name;
}

// A physical group of the domain's dimension: a body, made of the cells of its entities.
struct BodyGroup {
  int tag = 0;
  std::string name;
  std::vector<int> entities;
};

struct RawMesh {
  int dim = 0;  // 2 or 3; 0 if the file has no element of dimension 2 or 3
  int highestDimensionFound = -1;
  std::vector<Tag> nodeTags;
  std::vector<double> nodeCoords;  // x, y, z per node
  std::vector<ElementBlock> cellBlocks;
  std::vector<BoundaryGroup> boundaryGroups;
  std::vector<BodyGroup> bodyGroups;
  // Of a meshed .geo geometry: the blocks of every entity of dimension dim - 1 and, in 3D, of
  // every curve, with the entity's tag.
  std::vector<std::pair<int, ElementBlock>> geometryFacetBlocks, geometryEdgeBlocks;
  // Of one part of a partitioned mesh: the node tags of every entity Gmsh made for the
  // partition, with the index of that entity's partitions in entityParts.
  std::vector<std::pair<Tag, int>> partitionedNodes;
  std::vector<std::vector<int>> entityParts;
};

// ---------------------------------------------------------------------------------------
// Opening a file in Gmsh.

std::mutex& gmshMutex() {
  static std::mutex mutex;
  return mutex;
}

// Opens `path` in the process that reads: a child of the caller's (GmshSandbox.hpp), which
// ends after the read, so the caller's own Gmsh model and options (copied into the child)
// may be replaced and nothing needs putting back. Gmsh is initialised first, whether or not the
// caller had (Gmsh 4.8 then only warns): no Gmsh function may run before that, as Gmsh 4.8
// leaves its settings uninitialised memory until then, and an error reported on them (such
// as "not initialised") may exit the process.
void openInThisProcess(const std::string& path) {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  // Errors only, on standard error (the sandbox shows them when Gmsh exits on one), and as
  // exceptions, whatever options the calling program had given Gmsh.
  gmsh::option::setNumber("General.Terminal", 1);
  gmsh::option::setNumber("General.Verbosity", 1);
  gmsh::option::setNumber("General.AbortOnError", 2);
  gmsh::open(path);
}

// ---------------------------------------------------------------------------------------
// Extraction through the Gmsh API (current model).

void appendElements(int dim, int entity, std::vector<ElementBlock>& blocks) {
  std::vector<int> types;
  std::vector<std::vector<Tag>> elementTags, nodeTags;
  gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, entity);
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (elementTags[i].empty()) continue;
    blocks.push_back({types[i], std::move(elementTags[i]), std::move(nodeTags[i]), entity});
  }
}

// Elements of dimension dim in the physical groups of that dimension, or all of them if
// there are no such groups.
std::vector<ElementBlock> domainElements(int dim) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  std::vector<ElementBlock> blocks;
  if (groups.empty()) {
    appendElements(dim, -1, blocks);
    return blocks;
  }
  std::set<int> entities;  // an entity may be in several groups: take it once
  for (const auto& group : groups) {
    std::vector<int> tags;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group.second, tags);
    entities.insert(tags.begin(), tags.end());
  }
  for (int entity : entities) appendElements(dim, entity, blocks);
  return blocks;
}

// The physical groups of dimension dim, with their entities.
std::vector<BodyGroup> bodyGroups(int dim) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  std::vector<BodyGroup> bodies;
  for (const auto& group : groups) {
    BodyGroup body;
    body.tag = group.second;
    gmsh::model::getPhysicalName(dim, group.second, body.name);
    if (body.name.empty()) body.name = "physical" + std::to_string(group.second);
    gmsh::model::getEntitiesForPhysicalGroup(dim, group.second, body.entities);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

// Whether the geometry entity is a plane or a straight line, on which the midpoints of mesh
// edges already lie.
bool isFlat(int dim, int entity) {
  std::string type;
  gmsh::model::getType(dim, entity, type);
  return type == "Plane" || type == "Line";
}

// The elements of `type` on every curved entity of dimension `dim`, each block with its entity.
std::vector<std::pair<int, ElementBlock>> curvedEntityElements(int dim, int type) {
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  std::vector<std::pair<int, ElementBlock>> result;
  for (const auto& entity : entities) {
    if (isFlat(dim, entity.second)) continue;
    std::vector<ElementBlock> blocks;
    appendElements(dim, entity.second, blocks);
    for (ElementBlock& block : blocks)
      if (block.type == type) result.emplace_back(entity.second, std::move(block));
  }
  return result;
}

// Whether the entity of dimension dim - 1 is one Gmsh made between two parts of a partitioned
// mesh (its parent is of dimension dim).
bool isPartitionInterface(int dim, int entity) {
  int parentDim = -1, parentTag = -1;
  gmsh::model::getParent(dim - 1, entity, parentDim, parentTag);
  return parentDim == dim;
}

// The nodes of every entity that belongs to partitions, with those partitions.
void addPartitionedNodes(RawMesh& raw) {
  for (int d = 0; d <= raw.dim; ++d) {
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, d);
    for (const auto& entity : entities) {
      std::vector<int> parts;
      gmsh::model::getPartitions(entity.first, entity.second, parts);
      if (parts.empty()) continue;
      std::vector<Tag> nodeTags;
      std::vector<double> coords, parametric;
      gmsh::model::mesh::getNodes(nodeTags, coords, parametric, entity.first, entity.second, false, false);
      for (Tag node : nodeTags) raw.partitionedNodes.emplace_back(node, static_cast<int>(raw.entityParts.size()));
      raw.entityParts.push_back(std::move(parts));
    }
  }
  std::sort(raw.partitionedNodes.begin(), raw.partitionedNodes.end());
}

RawMesh extractMesh(bool withGeometry) {
  RawMesh raw;
  for (int d = 3; d >= 0 && raw.highestDimensionFound < 0; --d) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, d, -1);
    if (!types.empty()) raw.highestDimensionFound = d;
  }
  if (raw.highestDimensionFound < 2) return raw;
  raw.dim = raw.highestDimensionFound;

  std::vector<double> parametricCoords;
  gmsh::model::mesh::getNodes(raw.nodeTags, raw.nodeCoords, parametricCoords, -1, -1,
                              /*includeBoundary=*/false, /*returnParametricCoord=*/false);
  raw.cellBlocks = domainElements(raw.dim);
  raw.bodyGroups = bodyGroups(raw.dim);

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, raw.dim - 1);
  for (const auto& group : groups) {
    BoundaryGroup boundary;
    boundary.tag = group.second;
    gmsh::model::getPhysicalName(raw.dim - 1, group.second, boundary.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(raw.dim - 1, group.second, entities);
    std::sort(entities.begin(), entities.end());
    entities.erase(std::unique(entities.begin(), entities.end()), entities.end());
    // Gmsh puts the interfaces between the parts of a partitioned mesh into groups of their
    // own: they are no boundary.
    const auto interfaces = std::partition(entities.begin(), entities.end(), [&raw](int entity) {
      return !isPartitionInterface(raw.dim, entity);
    });
    if (interfaces == entities.begin() && !entities.empty()) continue;
    for (auto entity = entities.begin(); entity != interfaces; ++entity)
      appendElements(raw.dim - 1, *entity, boundary.blocks);
    raw.boundaryGroups.push_back(std::move(boundary));
  }
  if (withGeometry) {
    raw.geometryFacetBlocks = curvedEntityElements(raw.dim - 1, simplexType(raw.dim - 1));
    if (raw.dim == 3) raw.geometryEdgeBlocks = curvedEntityElements(1, kLineType);
  }
  return raw;
}

std::string typeName(int type) {
  std::string name;
  int dim = 0, order = 0, numNodes = 0, numPrimaryNodes = 0;
  std::vector<double> localCoords;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, localCoords,
                                          numPrimaryNodes);
  return "\"" + name + "\" (Gmsh type " + std::to_string(type) + ")";
}

// Rejects element types other than the linear simplex of dimension d, which the elements
// of `where` must be as `role` ("cells" or "boundary facets"). Needs Gmsh open (type names).
void checkTypes(const std::vector<ElementBlock>& blocks, int d, const std::string& where,
                const std::string& role, const std::string& prefix) {
  for (const ElementBlock& block : blocks)
    if (block.type != simplexType(d))
      throw InputError(prefix + where + " has " + std::to_string(block.elementTags.size()) +
                       " elements of type " + typeName(block.type) + ", but its " + role +
                       " must be " + simplexDescription(d) +
                       ": Signorini reads only linear simplex meshes, " + simplexDescription(2) +
                       " in 2D or " + simplexDescription(3) + " in 3D");
}

// ---------------------------------------------------------------------------------------
// Building the SimplexMesh from the raw data (no Gmsh involved).

// The node tags of an element, sorted, padded with 0 (never a node tag).
using NodeSet = std::array<Tag, 4>;
NodeSet nodeSet(const Tag* nodes, int nodesPerElement) {
  NodeSet set{0, 0, 0, 0};
  for (int i = 0; i < nodesPerElement; ++i) {  // insertion sort of at most 4 tags
    int j = i;
    for (; j > 0 && set[j - 1] > nodes[i]; --j) set[j] = set[j - 1];
    set[j] = nodes[i];
  }
  return set;
}

// Elements of the blocks in increasing element tag, (tag, first node tag), each element and
// each set of nodes once: of elements with the same nodes, the one with the smallest tag.
// Such duplicates are how MSH 2 files store an element in several physical groups (one copy
// per group, under different tags); Gmsh reads all copies into the one entity, which is then
// in all the groups. Equal node sets are found among equal hashes of them, which sort faster
// than the sets.
std::vector<std::pair<Tag, const Tag*>> uniqueElements(const std::vector<ElementBlock>& blocks,
                                                       int nodesPerElement) {
  std::vector<std::pair<Tag, const Tag*>> all;
  for (const ElementBlock& block : blocks)
    for (std::size_t e = 0; e < block.elementTags.size(); ++e)
      all.push_back({block.elementTags[e], block.nodeTags.data() + e * nodesPerElement});
  std::vector<std::pair<std::uint64_t, std::size_t>> byHash(all.size());  // ties: by element tag
  for (std::size_t i = 0; i < all.size(); ++i) {
    const NodeSet set = nodeSet(all[i].second, nodesPerElement);
    byHash[i] = {splitMixHash(set.begin(), set.end()), i};
  }
  std::sort(byHash.begin(), byHash.end(), [&all](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : all[a.second].first < all[b.second].first;
  });
  std::vector<char> duplicate(all.size(), 0);
  for (std::size_t first = 0, end = 0; first < byHash.size(); first = end) {
    end = first + 1;
    while (end < byHash.size() && byHash[end].first == byHash[first].first) ++end;
    for (std::size_t a = first + 1; a < end; ++a)  // a run of equal hashes, by tag
      for (std::size_t b = first; b < a && !duplicate[byHash[a].second]; ++b)
        if (!duplicate[byHash[b].second] && nodeSet(all[byHash[a].second].second, nodesPerElement) ==
                                                nodeSet(all[byHash[b].second].second, nodesPerElement))
          duplicate[byHash[a].second] = 1;
  }
  std::vector<std::pair<Tag, const Tag*>> elements;
  elements.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!duplicate[i]) elements.push_back(all[i]);
  const auto byTag = [](const auto& a, const auto& b) { return a.first < b.first; };
  if (!std::is_sorted(elements.begin(), elements.end(), byTag)) std::sort(elements.begin(), elements.end(), byTag);
  return elements;
}

using Face = std::array<long long, 3>;  // sorted vertex ids, unused entries -1

Face sortedFace(const long long* ids, int n) {
  Face face{-1, -1, -1};
  for (int i = 0; i < n; ++i) face[i] = ids[i];
  // n <= 3: a sorting network (std::sort here draws a false -Warray-bounds from GCC 12)
  if (face[0] > face[1]) std::swap(face[0], face[1]);
  if (n == 3) {
    if (face[1] > face[2]) std::swap(face[1], face[2]);
    if (face[0] > face[1]) std::swap(face[0], face[1]);
  }
  return face;
}

// The mesh's vertices: the node tags its cells use, ascending, and the vertex id of a tag.
// Gmsh numbers the nodes of a mesh it writes 1, 2, .., so where the largest tag is at most
// twice the number of nodes in the file, a table by tag gives the ids; a binary search
// otherwise.
class VertexTags {
 public:
  VertexTags(const std::vector<std::pair<Tag, const Tag*>>& cells, int nodesPerCell, std::size_t nodesInFile) {
    Tag largest = 0;
    for (const auto& cell : cells) largest = std::max(largest, *std::max_element(cell.second, cell.second + nodesPerCell));
    if (largest / 2 <= nodesInFile) {
      idOfTag_.assign(largest + 1, -1);
      for (const auto& cell : cells)
        for (int i = 0; i < nodesPerCell; ++i) idOfTag_[cell.second[i]] = 0;
      for (Tag t = 0; t <= largest; ++t)
        if (idOfTag_[t] == 0) {
          idOfTag_[t] = static_cast<long long>(tags_.size());
          tags_.push_back(t);
        }
      return;
    }
    tags_.reserve(cells.size() * nodesPerCell);
    for (const auto& cell : cells) tags_.insert(tags_.end(), cell.second, cell.second + nodesPerCell);
    std::sort(tags_.begin(), tags_.end());
    tags_.erase(std::unique(tags_.begin(), tags_.end()), tags_.end());
  }

  const std::vector<Tag>& tags() const { return tags_; }
  std::vector<Tag> release() { return std::move(tags_); }

  // The vertex id of node tag `node`, -1 if no cell uses it.
  long long id(Tag node) const {
    if (!idOfTag_.empty()) return node < idOfTag_.size() ? idOfTag_[node] : -1;
    const auto it = std::lower_bound(tags_.begin(), tags_.end(), node);
    return it != tags_.end() && *it == node ? static_cast<long long>(it - tags_.begin()) : -1;
  }

 private:
  std::vector<Tag> tags_;
  std::vector<long long> idOfTag_;  // empty: search tags_
};

// A 2D mesh must lie in the plane z = 0 (to round-off relative to its extent).
void checkPlanar(const SimplexMesh& mesh, const std::vector<Tag>& used, const std::vector<double>& z,
                 const std::string& prefix) {
  double extent = 0;
  for (int c = 0; c < 2; ++c) {
    double lo = mesh.vertices[c], hi = mesh.vertices[c];
    for (std::size_t v = 0; v < used.size(); ++v) {
      lo = std::min(lo, mesh.vertices[2 * v + c]);
      hi = std::max(hi, mesh.vertices[2 * v + c]);
    }
    extent = std::max(extent, hi - lo);
  }
  for (std::size_t v = 0; v < used.size(); ++v)
    if (std::abs(z[v]) > 1e-12 * extent)
      throw InputError(prefix + "it is a 2D mesh (triangles) but node " + std::to_string(used[v]) +
                       " has z = " + std::to_string(z[v]) + "; a 2D mesh must lie in the plane z = 0");
}

// Whether each of `faces` (sorted vertex ids) is a face of a cell. Only the cells' faces whose
// vertices are all vertices of `faces` are looked up.
std::vector<char> facesOfCells(const SimplexMesh& mesh, const std::vector<Face>& faces) {
  const int dim = mesh.dim, nodesPerCell = dim + 1;
  std::vector<Face> sorted(faces);
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> onFace(mesh.numVertices(), 0), found(sorted.size(), 0);
  for (const Face& face : faces)
    for (int i = 0; i < dim; ++i)
      if (face[i] >= 0) onFace[face[i]] = 1;
  for (long long c = 0; c < mesh.numCells(); ++c) {
    const long long* cell = mesh.cells.data() + nodesPerCell * c;
    for (int omit = 0; omit < nodesPerCell; ++omit) {
      long long ids[3];
      for (int i = 0, k = 0; i < nodesPerCell; ++i)
        if (i != omit) ids[k++] = cell[i];
      if (!onFace[ids[0]] || !onFace[ids[1]] || (dim == 3 && !onFace[ids[2]])) continue;
      const auto it = std::lower_bound(sorted.begin(), sorted.end(), sortedFace(ids, dim));
      if (it != sorted.end() && *it == sortedFace(ids, dim)) found[it - sorted.begin()] = 1;
    }
  }
  std::vector<char> result(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    result[f] = found[std::lower_bound(sorted.begin(), sorted.end(), faces[f]) - sorted.begin()];
  return result;
}

// The boundary facets of the named groups, each checked to be a face of some cell.
void addBoundaryFacets(const RawMesh& raw, const VertexTags& vertices, const std::string& prefix,
                       SimplexMesh& mesh) {
  const int dim = mesh.dim;
  std::vector<Face> faces;
  std::vector<std::pair<Tag, std::size_t>> elementAndGroup;  // of each facet, for the message
  const auto notAFace = [&](const std::pair<Tag, std::size_t>& facet) {
    throw InputError(prefix + "boundary element " + std::to_string(facet.first) + " of the group \"" +
                     boundaryName(raw.boundaryGroups[facet.second]) + "\" is not " + (dim == 2 ? "an edge" : "a face") +
                     " of any cell of the mesh");
  };
  for (std::size_t g = 0; g < raw.boundaryGroups.size(); ++g) {
    const BoundaryGroup& group = raw.boundaryGroups[g];
    const std::string name = boundaryName(group);
    if (!mesh.boundaryTags.emplace(name, group.tag).second)
      throw InputError(prefix + "two physical groups of dimension " + std::to_string(dim - 1) +
                       " (tags " + std::to_string(mesh.boundaryTags.at(name)) + " and " +
                       std::to_string(group.tag) + ") have the same name \"" + name + "\"");
    for (const auto& element : uniqueElements(group.blocks, dim)) {
      elementAndGroup.push_back({element.first, g});
      long long ids[3];
      for (int i = 0; i < dim; ++i) ids[i] = vertices.id(element.second[i]);
      if (std::find(ids, ids + dim, -1) != ids + dim) notAFace(elementAndGroup.back());
      faces.push_back(sortedFace(ids, dim));
      mesh.facets.insert(mesh.facets.end(), ids, ids + dim);
      mesh.facetTags.push_back(group.tag);
    }
  }
  const std::vector<char> isFace = facesOfCells(mesh, faces);
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (!isFace[f]) notAFace(elementAndGroup[f]);
}

// The elements of the blocks whose nodes are all vertices of the mesh, as vertex ids, with
// their blocks' entities.
void addGeometryEntities(const std::vector<std::pair<int, ElementBlock>>& blocks, const VertexTags& vertices,
                         int nodesPerElement, std::vector<long long>& elements, std::vector<int>& entities) {
  for (const auto& [entity, block] : blocks)
    for (std::size_t e = 0; e < block.elementTags.size(); ++e) {
      long long ids[3];
      for (int i = 0; i < nodesPerElement; ++i) ids[i] = vertices.id(block.nodeTags[nodesPerElement * e + i]);
      if (std::find(ids, ids + nodesPerElement, -1) != ids + nodesPerElement) continue;
      elements.insert(elements.end(), ids, ids + nodesPerElement);
      entities.push_back(entity);
    }
}

// Each cell's body: the physical group of dimension dim its entity is in (of several, the one
// with the lowest tag); no tags when the file has no such groups.
void addCellTags(const RawMesh& raw, const std::vector<std::pair<Tag, const Tag*>>& cellElements,
                 const std::string& prefix, SimplexMesh& mesh) {
  if (raw.bodyGroups.empty()) return;
  std::map<int, int> entityBody;
  for (const BodyGroup& body : raw.bodyGroups) {
    if (!mesh.bodyTags.emplace(body.name, body.tag).second)
      throw InputError(prefix + "two physical groups of dimension " + std::to_string(mesh.dim) + " (tags " +
                       std::to_string(mesh.bodyTags.at(body.name)) + " and " + std::to_string(body.tag) +
                       ") have the same name \"" + body.name + "\"");
    for (int entity : body.entities) {
      const auto [it, fresh] = entityBody.emplace(entity, body.tag);
      if (!fresh) it->second = std::min(it->second, body.tag);
    }
  }
  std::vector<std::pair<Tag, int>> elementEntity;  // (element tag, entity), sorted
  for (const ElementBlock& block : raw.cellBlocks)
    for (Tag element : block.elementTags) elementEntity.emplace_back(element, block.entity);
  std::sort(elementEntity.begin(), elementEntity.end());
  mesh.cellTags.resize(cellElements.size());
  for (std::size_t c = 0; c < cellElements.size(); ++c) {
    const auto it = std::lower_bound(elementEntity.begin(), elementEntity.end(), std::make_pair(cellElements[c].first, INT_MIN));
    const auto body = it == elementEntity.end() ? entityBody.end() : entityBody.find(it->second);
    if (body == entityBody.end()) throw Error(prefix + "a cell outside every physical group was read");
    mesh.cellTags[c] = body->second;
  }
}

// `vertexTags`, if given, receives the Gmsh node tag of each vertex.
SimplexMesh buildMesh(const RawMesh& raw, const std::string& prefix, std::vector<Tag>* vertexTags = nullptr) {
  const int dim = raw.dim;
  const int nodesPerCell = dim + 1;
  SimplexMesh mesh;
  mesh.dim = dim;

  // Cells, each once, by element tag.
  const auto cellElements = uniqueElements(raw.cellBlocks, nodesPerCell);
  if (cellElements.empty())
    throw InputError(prefix + "its physical groups of dimension " + std::to_string(dim) +
                     " hold no elements, so the mesh has no cells");

  // Vertices: the nodes of the cells, in increasing node tag.
  VertexTags vertices(cellElements, nodesPerCell, raw.nodeTags.size());
  const std::vector<Tag>& used = vertices.tags();

  std::vector<std::size_t> byTag(raw.nodeTags.size());
  std::iota(byTag.begin(), byTag.end(), std::size_t{0});
  std::sort(byTag.begin(), byTag.end(),
            [&raw](std::size_t a, std::size_t b) { return raw.nodeTags[a] < raw.nodeTags[b]; });
  mesh.vertices.resize(dim * used.size());
  std::vector<double> z(used.size(), 0.0);
  {
    std::size_t k = 0;  // walk both sorted sequences
    for (std::size_t v = 0; v < used.size(); ++v) {
      while (k < byTag.size() && raw.nodeTags[byTag[k]] < used[v]) ++k;
      if (k == byTag.size() || raw.nodeTags[byTag[k]] != used[v])
        throw InputError(prefix + "a cell uses node " + std::to_string(used[v]) +
                         ", which the file does not define");
      const double* x = raw.nodeCoords.data() + 3 * byTag[k];
      for (int c = 0; c < dim; ++c) mesh.vertices[dim * v + c] = x[c];
      z[v] = x[2];
    }
  }
  if (dim == 2) checkPlanar(mesh, used, z, prefix);

  // Cells, positively oriented.
  mesh.cells.resize(nodesPerCell * cellElements.size());
  std::vector<double> x(dim * nodesPerCell);
  for (std::size_t c = 0; c < cellElements.size(); ++c) {
    long long* cell = mesh.cells.data() + nodesPerCell * c;
    for (int i = 0; i < nodesPerCell; ++i) cell[i] = vertices.id(cellElements[c].second[i]);
    for (int i = 0; i < nodesPerCell; ++i)
      for (int j = 0; j < dim; ++j) x[dim * i + j] = mesh.vertices[dim * cell[i] + j];
    const int orientation = simplexOrientation(dim, x.data());
    if (orientation == 0)
      throw InputError(prefix + "element " + std::to_string(cellElements[c].first) +
                       " is degenerate (zero " + (dim == 2 ? "area" : "volume") + ")");
    if (orientation < 0) std::swap(cell[1], cell[2]);
  }

  addCellTags(raw, cellElements, prefix, mesh);
  addBoundaryFacets(raw, vertices, prefix, mesh);
  addGeometryEntities(raw.geometryFacetBlocks, vertices, dim, mesh.geometryFacets, mesh.geometryFacetEntities);
  addGeometryEntities(raw.geometryEdgeBlocks, vertices, 2, mesh.geometryEdges, mesh.geometryEdgeEntities);
  if (vertexTags) *vertexTags = vertices.release();
  return mesh;
}

// The one partition (1-based, as Gmsh numbers them) that the cells of a part file belong to.
int partitionOfCells(const RawMesh& raw, const std::string& prefix) {
  std::set<int> partitions;
  for (const ElementBlock& block : raw.cellBlocks) {
    std::vector<int> parts;
    gmsh::model::getPartitions(raw.dim, block.entity, parts);
    if (parts.empty())
      throw InputError(prefix + "it is not one part of a partitioned mesh (its cells belong to no partition; "
                                "Gmsh writes one file per part with -part N -part_split)");
    partitions.insert(parts.begin(), parts.end());
  }
  if (partitions.size() != 1)
    throw InputError(prefix + "its cells belong to " + std::to_string(partitions.size()) +
                     " partitions: a part file holds one");
  return *partitions.begin();
}

// Every vertex's partitions (0-based, ascending) as CSR: those of the entity its node lies
// on, or the file's own for a node inside the part.
void addVertexSharers(const RawMesh& raw, const std::vector<Tag>& vertexTags, GmshMeshPart& part) {
  part.sharerStart.assign(1, 0);
  for (Tag node : vertexTags) {
    const auto it = std::lower_bound(raw.partitionedNodes.begin(), raw.partitionedNodes.end(), std::make_pair(node, -1));
    if (it != raw.partitionedNodes.end() && it->first == node) {
      std::vector<int> parts = raw.entityParts[it->second];
      std::sort(parts.begin(), parts.end());
      for (int p : parts) part.sharers.push_back(p - 1);
    } else {
      part.sharers.push_back(part.part);
    }
    part.sharerStart.push_back(static_cast<long long>(part.sharers.size()));
  }
  part.vertexTags.assign(vertexTags.begin(), vertexTags.end());
}

// What the user should hear of the options of the .geo file at `path`, open in Gmsh: HXT
// (Mesh.Algorithm3D = 10) meshes in parallel and, in Gmsh 4.8.4 even on one thread, makes a
// different mesh at every run.
std::vector<std::string> meshingNotes(const std::string& path) {
  double algorithm = 0;
  gmsh::option::getNumber("Mesh.Algorithm3D", algorithm);
  if (gmsh::model::getDimension() != 3 || algorithm != 10) return {};
  std::string version;
  gmsh::option::getString("General.Version", version);
  return {"Gmsh geometry '" + path + "' selects Gmsh's HXT 3D mesher (Mesh.Algorithm3D = 10), which in Gmsh " +
          version + " may make a different mesh at every run: the number of unknowns and the results then vary "
          "between runs; Gmsh's default 3D mesher (Delaunay, 1) makes the same mesh every time"};
}

// The mesh in this process; readGmshMesh runs it in a child. With `part`, the file is one
// part of a partitioned mesh, and `part` receives the mesh and what it shares.
SimplexMesh readInThisProcess(const std::string& path, double sizeFactor, GmshMeshPart* part = nullptr) {
  const std::string prefix = "Gmsh mesh file '" + path + "': ";
  const bool geometry = std::filesystem::path(path).extension() == ".geo";
  {
    std::error_code error;
    std::ifstream file(path);
    if (!std::filesystem::is_regular_file(path, error) || !file)
      throw InputError(prefix + "cannot open it (missing, not a regular file or unreadable)");
    // Gmsh would parse anything else as a .geo script, and Gmsh 4.8's parser does not
    // recover from a syntax error for the rest of the process.
    std::string first;
    if (!geometry && (file >> first) && first != "$MeshFormat")
      throw InputError(prefix + "not a Gmsh mesh file (it does not start with $MeshFormat)");
  }

  RawMesh raw;
  std::vector<std::string> notes;
  {
    std::lock_guard<std::mutex> lock(gmshMutex());
    try {
      openInThisProcess(path);
      if (geometry) {
        notes = meshingNotes(path);
        gmsh::option::setNumber("Mesh.MeshSizeFactor", sizeFactor);
        gmsh::option::setNumber("Mesh.ElementOrder", 1);
        gmsh::model::mesh::generate(gmsh::model::getDimension());
      }
      raw = extractMesh(geometry);
      if (raw.dim == 0)
        throw InputError(prefix + "it holds no " + simplexDescription(2) + " nor " +
                         simplexDescription(3) +
                         (raw.highestDimensionFound < 0
                              ? std::string(" (no elements at all: is it a mesh file?)")
                              : " (its highest-dimensional elements are of dimension " +
                                    std::to_string(raw.highestDimensionFound) + ")"));
      checkTypes(raw.cellBlocks, raw.dim, "the " + std::to_string(raw.dim) + "D domain", "cells",
                 prefix);
      for (const BoundaryGroup& group : raw.boundaryGroups)
        checkTypes(group.blocks, raw.dim - 1, "the boundary group \"" + boundaryName(group) + "\"",
                   "boundary facets", prefix);
      if (part) {
        part->part = partitionOfCells(raw, prefix) - 1;
        addPartitionedNodes(raw);
      }
    } catch (const Error&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::string& message) {  // what Gmsh 4.8 throws
      throw InputError(prefix + "Gmsh cannot read it: " + message);
    } catch (const std::exception& e) {
      throw InputError(prefix + "Gmsh cannot read it: " + e.what());
    } catch (...) {
      throw InputError(prefix + "Gmsh cannot read it");
    }
  }
  std::vector<Tag> vertexTags;
  SimplexMesh mesh = buildMesh(raw, prefix, part ? &vertexTags : nullptr);
  mesh.notes = std::move(notes);
  if (part) addVertexSharers(raw, vertexTags, *part);
  return mesh;
}

// Strings through the pipe, each ended by '\0'.
void sendStrings(int fd, const std::vector<std::string>& strings) {
  std::vector<char> chars;
  for (const std::string& string : strings) {
    chars.insert(chars.end(), string.begin(), string.end());
    chars.push_back('\0');
  }
  sendArray(fd, chars);
}

bool receiveStrings(int fd, std::vector<std::string>& strings) {
  std::vector<char> chars;
  if (!receiveArray(fd, chars)) return false;
  for (auto start = chars.begin(); start != chars.end();) {
    const auto end = std::find(start, chars.end(), '\0');
    if (end == chars.end()) return false;
    strings.emplace_back(start, end);
    start = end + 1;
  }
  return true;
}

// Names and their tags through the pipe: the names, then the tags.
void sendNames(int fd, const std::map<std::string, int>& named) {
  std::vector<std::string> names;
  std::vector<int> tags;
  for (const auto& [name, tag] : named) {
    names.push_back(name);
    tags.push_back(tag);
  }
  sendStrings(fd, names);
  sendArray(fd, tags);
}

bool receiveNames(int fd, std::map<std::string, int>& named) {
  std::vector<std::string> names;
  std::vector<int> tags;
  if (!receiveStrings(fd, names) || !receiveArray(fd, tags) || names.size() != tags.size()) return false;
  for (std::size_t i = 0; i < names.size(); ++i) named[names[i]] = tags[i];
  return true;
}

void sendMesh(int fd, const SimplexMesh& mesh) {
  writeAll(fd, &mesh.dim, sizeof mesh.dim);
  sendArray(fd, mesh.vertices);
  sendArray(fd, mesh.cells);
  sendArray(fd, mesh.facets);
  sendArray(fd, mesh.facetTags);
  sendArray(fd, mesh.geometryFacets);
  sendArray(fd, mesh.geometryFacetEntities);
  sendArray(fd, mesh.geometryEdges);
  sendArray(fd, mesh.geometryEdgeEntities);
  sendArray(fd, mesh.cellTags);
  sendNames(fd, mesh.boundaryTags);
  sendNames(fd, mesh.bodyTags);
  sendStrings(fd, mesh.notes);
}

bool receiveMesh(int fd, SimplexMesh& mesh) {
  return readAll(fd, &mesh.dim, sizeof mesh.dim) && receiveArray(fd, mesh.vertices) && receiveArray(fd, mesh.cells) &&
         receiveArray(fd, mesh.facets) && receiveArray(fd, mesh.facetTags) && receiveArray(fd, mesh.geometryFacets) &&
         receiveArray(fd, mesh.geometryFacetEntities) && receiveArray(fd, mesh.geometryEdges) &&
         receiveArray(fd, mesh.geometryEdgeEntities) && receiveArray(fd, mesh.cellTags) &&
         receiveNames(fd, mesh.boundaryTags) && receiveNames(fd, mesh.bodyTags) && receiveStrings(fd, mesh.notes);
}

double defaultTimeLimit(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".geo") return -1;
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path, error);
  return 60.0 + (error ? 0.0 : static_cast<double>(bytes) / 1e6);
}

// The closest points of the geometry's entities (dimension, tag) to the points (3 coordinates
// each), in this process.
std::vector<double> projectInThisProcess(const std::string& path, const std::vector<int>& dims,
                                         const std::vector<int>& entities, const std::vector<double>& points) {
  std::lock_guard<std::mutex> lock(gmshMutex());
  std::vector<double> result(points.size());
  try {
    openInThisProcess(path);
    // One call per entity, with all its points.
    std::map<std::pair<int, int>, std::vector<std::size_t>> byEntity;
    for (std::size_t i = 0; i < dims.size(); ++i) byEntity[{dims[i], entities[i]}].push_back(i);
    std::vector<double> coord, closest, parametric;
    for (const auto& [entity, indices] : byEntity) {
      coord.clear();
      for (std::size_t i : indices) coord.insert(coord.end(), &points[3 * i], &points[3 * i + 3]);
      gmsh::model::getClosestPoint(entity.first, entity.second, coord, closest, parametric);
      if (closest.size() != coord.size())
        throw InputError("Gmsh geometry '" + path + "': no closest points on its entity of dimension " +
                         std::to_string(entity.first) + " and tag " + std::to_string(entity.second));
      for (std::size_t k = 0; k < indices.size(); ++k) std::copy_n(&closest[3 * k], 3, &result[3 * indices[k]]);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::string& message) {  // what Gmsh 4.8 throws
    throw InputError("Gmsh geometry '" + path + "': " + message);
  } catch (const std::exception& e) {
    throw InputError("Gmsh geometry '" + path + "': " + e.what());
  }
  return result;
}

}  // namespace

SimplexMesh readGmshMesh(const std::string& path, double sizeFactor, double timeLimitSeconds) {
  SimplexMesh mesh;
  answerFromChild(
      "Gmsh mesh file '" + path + "'", "reading it", timeLimitSeconds < 0 ? defaultTimeLimit(path) : timeLimitSeconds,
      [&](int fd) {
        const SimplexMesh read = readInThisProcess(path, sizeFactor);
        writeAll(fd, "A", 1);
        sendMesh(fd, read);
      },
      [&](int fd) { return receiveMesh(fd, mesh); });
  return mesh;
}

GmshMeshPart readGmshMeshPart(const std::string& path, double timeLimitSeconds) {
  GmshMeshPart part;
  answerFromChild(
      "Gmsh mesh file '" + path + "'", "reading it", timeLimitSeconds < 0 ? defaultTimeLimit(path) : timeLimitSeconds,
      [&](int fd) {
        GmshMeshPart read;
        read.mesh = readInThisProcess(path, 1.0, &read);
        writeAll(fd, "A", 1);
        sendMesh(fd, read.mesh);
        writeAll(fd, &read.part, sizeof read.part);
        sendArray(fd, read.vertexTags);
        sendArray(fd, read.sharerStart);
        sendArray(fd, read.sharers);
      },
      [&](int fd) {
        return receiveMesh(fd, part.mesh) && readAll(fd, &part.part, sizeof part.part) &&
               receiveArray(fd, part.vertexTags) && receiveArray(fd, part.sharerStart) &&
               receiveArray(fd, part.sharers);
      });
  return part;
}

std::vector<double> closestPointsOnGeometry(const std::string& path, const std::vector<int>& dims,
                                            const std::vector<int>& entities, const std::vector<double>& points) {
  if (dims.size() != entities.size() || points.size() != 3 * dims.size())
    throw Error("closestPointsOnGeometry: " + std::to_string(dims.size()) + " dimensions, " +
                std::to_string(entities.size()) + " entities, " + std::to_string(points.size()) + " coordinates");
  if (dims.empty()) return {};
  std::vector<double> result;
  answerFromChild(
      "Gmsh geometry '" + path + "'", "placing points on it", -1,
      [&](int fd) {
        const std::vector<double> closest = projectInThisProcess(path, dims, entities, points);
        writeAll(fd, "A", 1);
        sendArray(fd, closest);
      },
      [&](int fd) { return receiveArray(fd, result) && result.size() == points.size(); });
  return result;
}

}  // namespace signorini
