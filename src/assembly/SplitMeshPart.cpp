#include "assembly/SplitMeshPart.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

using Key = std::array<long long, 3>;  // an entity's sorted global vertex ids (Gmsh node tags for a vertex), padded with -1

Key sortedKey(const long long* ids, int size) {
  Key key{-1, -1, -1};
  for (int i = 0; i < size; ++i) {  // insertion: at most three ids
    int j = i;
    for (; j > 0 && key[j - 1] > ids[i]; --j) key[j] = key[j - 1];
    key[j] = ids[i];
  }
  return key;
}

// The part's vertices by global id, and for each the ranks that hold it (ascending, this one
// among them).
struct VertexSharing {
  std::vector<GlobalOrdinal> ids;  // sorted
  std::vector<long long> start;
  std::vector<int> ranks;

  long long local(long long id) const { return std::lower_bound(ids.begin(), ids.end(), id) - ids.begin(); }
  bool holds(long long id) const { return std::binary_search(ids.begin(), ids.end(), id); }

  // The other ranks that hold every vertex of the entity (at least one of them for `any`).
  std::vector<int> others(const Key& key, int size, int self, bool any = false) const {
    std::vector<int> result;
    for (int i = 0; i < size; ++i) {
      const long long v = local(key[i]);
      std::vector<int> these(ranks.begin() + start[v], ranks.begin() + start[v + 1]);
      if (i == 0) {
        result = std::move(these);
      } else {
        std::vector<int> merged;
        if (any)
          std::set_union(result.begin(), result.end(), these.begin(), these.end(), std::back_inserter(merged));
        else
          std::set_intersection(result.begin(), result.end(), these.begin(), these.end(), std::back_inserter(merged));
        result = std::move(merged);
      }
    }
    result.erase(std::remove(result.begin(), result.end(), self), result.end());
    return result;
  }
};

// Each entity's owner: the lowest rank that holds it, this one or one of its candidates. Every
// rank tells each candidate which of its entities it may share with it.
std::vector<int> lowestHolders(const Comm& comm, const std::vector<Key>& keys, int size,
                               const std::vector<std::vector<int>>& candidates) {
  const int rank = comm.getRank();
  std::vector<std::vector<long long>> toRank(comm.getSize());
  for (std::size_t e = 0; e < keys.size(); ++e)
    for (int r : candidates[e]) toRank[r].insert(toRank[r].end(), keys[e].begin(), keys[e].begin() + size);
  const std::vector<std::vector<long long>> fromRank = exchangeWithRanks(comm, toRank);
  std::vector<int> owners(keys.size(), rank);
  for (int r = 0; r < rank; ++r)
    for (std::size_t i = 0; i < fromRank[r].size(); i += size) {
      const Key key = sortedKey(&fromRank[r][i], size);
      const auto it = std::lower_bound(keys.begin(), keys.end(), key);
      if (it != keys.end() && *it == key) owners[it - keys.begin()] = std::min(owners[it - keys.begin()], r);
    }
  return owners;
}

// The part's distinct entities with `size` vertices, numbered over all ranks.
struct NumberedEntities {
  std::vector<Key> keys;  // sorted
  std::vector<GlobalOrdinal> ids;
  std::vector<int> owners;
  long long count = 0;  // over all ranks

  std::size_t find(const Key& key) const { return std::lower_bound(keys.begin(), keys.end(), key) - keys.begin(); }
};

// Numbers the entities with the given keys (repeats allowed): owners as lowestHolders(), ids
// owner by owner through their `globalKey`, a number no other entity has.
NumberedEntities numberEntities(const RCP<const Comm>& comm, std::vector<Key> keys, int size,
                                const VertexSharing& sharing, const std::function<GlobalOrdinal(const Key&)>& globalKey) {
  NumberedEntities result;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::vector<int>> candidates(keys.size());
  for (std::size_t e = 0; e < keys.size(); ++e) candidates[e] = sharing.others(keys[e], size, comm->getRank());
  result.owners = lowestHolders(*comm, keys, size, candidates);
  std::vector<GlobalOrdinal> global(keys.size());
  for (std::size_t e = 0; e < keys.size(); ++e) global[e] = globalKey(keys[e]);
  result.ids = ownerOrderedIds(comm, global, result.owners, result.count);
  result.keys = std::move(keys);
  return result;
}

// Vertices: owners and global ids, then the part's vertices reordered by id (the mesh's
// cells and facets follow).
VertexSharing numberVertices(const RCP<const Comm>& comm, GmshMeshPart& read, MeshPart& part, long long& count) {
  SimplexMesh& mesh = read.mesh;
  const int d = mesh.dim;
  const long long nv = mesh.numVertices();
  VertexSharing byTag{std::vector<GlobalOrdinal>(read.vertexTags.begin(), read.vertexTags.end()), read.sharerStart,
                      read.sharers};
  std::vector<Key> keys(nv);
  std::vector<std::vector<int>> candidates(nv);
  for (long long v = 0; v < nv; ++v) {
    keys[v] = {read.vertexTags[v], -1, -1};
    candidates[v] = byTag.others(keys[v], 1, comm->getRank());
  }
  const std::vector<int> owners = lowestHolders(*comm, keys, 1, candidates);
  const std::vector<GlobalOrdinal> ids = ownerOrderedIds(comm, byTag.ids, owners, count);

  std::vector<long long> order(nv), position(nv);
  std::iota(order.begin(), order.end(), 0LL);
  std::sort(order.begin(), order.end(), [&ids](long long a, long long b) { return ids[a] < ids[b]; });
  VertexSharing sharing;
  sharing.start.push_back(0);
  std::vector<double> vertices(mesh.vertices.size());
  for (long long i = 0; i < nv; ++i) {
    const long long v = order[i];
    position[v] = i;
    sharing.ids.push_back(ids[v]);
    sharing.ranks.insert(sharing.ranks.end(), read.sharers.begin() + read.sharerStart[v],
                         read.sharers.begin() + read.sharerStart[v + 1]);
    sharing.start.push_back(static_cast<long long>(sharing.ranks.size()));
    part.nodeOwners.push_back(owners[v]);
    std::copy_n(&mesh.vertices[d * v], d, &vertices[d * i]);
  }
  mesh.vertices = std::move(vertices);
  for (long long& v : mesh.cells) v = position[v];
  for (long long& v : mesh.facets) v = position[v];
  part.nodeIds = sharing.ids;
  return sharing;
}

// The cells' edges (faces: size 3) as keys of global vertex ids, in the order of the
// lattice's cellEdges (cellFaces).
std::vector<Key> cellEntityKeys(const SimplexMesh& mesh, const VertexSharing& sharing, int size) {
  const int d = mesh.dim;
  std::vector<Key> keys;
  for (long long c = 0; c < mesh.numCells(); ++c) {
    const long long* cell = &mesh.cells[(d + 1) * c];
    long long ids[3];
    if (size == 2) {
      for (int i = 0; i <= d; ++i)
        for (int j = i + 1; j <= d; ++j) {
          ids[0] = sharing.ids[cell[i]];
          ids[1] = sharing.ids[cell[j]];
          keys.push_back(sortedKey(ids, 2));
        }
    } else {
      for (int f = 0; f <= d; ++f) {
        for (int v = 0, n = 0; v <= d; ++v)
          if (v != f) ids[n++] = sharing.ids[cell[v]];
        keys.push_back(sortedKey(ids, 3));
      }
    }
  }
  return keys;
}

void addCellEntities(const NumberedEntities& entities, const std::vector<Key>& cellKeys, std::vector<long long>& ids,
                     std::vector<int>& owners) {
  for (const Key& key : cellKeys) {
    const std::size_t e = entities.find(key);
    ids.push_back(entities.ids[e]);
    owners.push_back(entities.owners[e]);
  }
}

// The boundary facets near the part: its own and those of other ranks that share a vertex with
// it; those with two vertices in the part become nearFacets, and every vertex of the part on
// a facet goes into the boundary nodes of its tag. The tags are those with a facet on any rank.
void addBoundary(const Comm& comm, const VertexSharing& sharing, MeshPart& part) {
  const SimplexMesh& mesh = part.mesh;
  const int d = mesh.dim;
  std::vector<std::vector<long long>> toRank(comm.getSize());
  std::vector<long long> near;  // d global ids and the tag per facet
  for (long long f = 0; f < mesh.numFacets(); ++f) {
    long long ids[3];
    for (int v = 0; v < d; ++v) ids[v] = sharing.ids[mesh.facets[d * f + v]];
    near.insert(near.end(), ids, ids + d);
    near.push_back(mesh.facetTags[f]);
    for (int r : sharing.others(sortedKey(ids, d), d, comm.getRank(), true)) {
      toRank[r].insert(toRank[r].end(), ids, ids + d);
      toRank[r].push_back(mesh.facetTags[f]);
    }
  }
  for (const std::vector<long long>& received : exchangeWithRanks(comm, toRank))
    near.insert(near.end(), received.begin(), received.end());

  std::vector<int> tags;
  for (const auto& named : mesh.boundaryTags) tags.push_back(named.second);
  std::sort(tags.begin(), tags.end());
  std::vector<long long> local(tags.size(), 0), global(tags.size(), 0);
  for (int tag : mesh.facetTags) ++local[std::lower_bound(tags.begin(), tags.end(), tag) - tags.begin()];
  if (!tags.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(tags.size()), local.data(), global.data());
  std::vector<std::vector<long long>> nodesOfTag(tags.size());
  for (std::size_t at = 0; at < near.size(); at += d + 1) {
    const int tag = static_cast<int>(near[at + d]);
    const std::size_t t = std::lower_bound(tags.begin(), tags.end(), tag) - tags.begin();
    int inPart = 0;
    for (int v = 0; v < d; ++v)
      if (sharing.holds(near[at + v])) {
        ++inPart;
        nodesOfTag[t].push_back(sharing.local(near[at + v]));
      }
    if (inPart < 2) continue;
    part.nearFacets.insert(part.nearFacets.end(), &near[at], &near[at + d]);
    part.nearFacetTags.push_back(tag);
  }
  part.boundaryStart.push_back(0);
  for (std::size_t t = 0; t < tags.size(); ++t) {
    if (global[t] == 0) continue;
    std::vector<long long>& nodes = nodesOfTag[t];
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    part.boundaryTags.push_back(tags[t]);
    part.boundaryNodes.insert(part.boundaryNodes.end(), nodes.begin(), nodes.end());
    part.boundaryStart.push_back(static_cast<long long>(part.boundaryNodes.size()));
  }
}

}  // namespace

MeshPart latticePartOfSplitMesh(const RCP<const Comm>& comm, GmshMeshPart&& read) {
  const int d = read.mesh.dim;
  const long long numCells = read.mesh.numCells();
  if (numCells == 0) throw Error("split mesh: rank " + std::to_string(comm->getRank()) + " holds no cells");
  MeshPart part;
  long long numVertices = 0;
  const VertexSharing sharing = numberVertices(comm, read, part, numVertices);
  part.mesh = std::move(read.mesh);
  read = GmshMeshPart();
  // Edges and faces are numbered through keys of two and three vertex ids; they must fit.
  if (numVertices > 3000000000LL) throw Error("split mesh: too many vertices for 64-bit entity keys");

  long long firstCell = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, 1, &numCells, &firstCell);
  firstCell -= numCells;
  part.globalCells.resize(numCells);
  std::iota(part.globalCells.begin(), part.globalCells.end(), firstCell);

  const std::vector<Key> edgeKeys = cellEntityKeys(part.mesh, sharing, 2);
  const NumberedEntities edges = numberEntities(comm, edgeKeys, 2, sharing,
                                                [&](const Key& k) { return k[0] * numVertices + k[1]; });
  addCellEntities(edges, edgeKeys, part.cellEdges, part.edgeOwners);
  NumberedEntities faces;
  if (d == 3) {
    if (edges.count > std::numeric_limits<long long>::max() / numVertices)
      throw Error("split mesh: too many edges for 64-bit face keys");
    const std::vector<Key> faceKeys = cellEntityKeys(part.mesh, sharing, 3);
    faces = numberEntities(comm, faceKeys, 3, sharing, [&](const Key& k) {
      return edges.ids[edges.find({k[0], k[1], -1})] * numVertices + k[2];
    });
    addCellEntities(faces, faceKeys, part.cellFaces, part.faceOwners);
  }
  addBoundary(*comm, sharing, part);
  part.entityCounts = {numVertices, edges.count, faces.count, sumOverRanks(*comm, numCells)};
  return part;
}

}  // namespace signorini::detail
