#include "assembly/SplitMeshPart.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/SortedVertexKey.hpp"
#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

using Key = SortedVertexKey;  // of global vertex ids (Gmsh node tags for a vertex)

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
    std::vector<int> result, merged;
    for (int i = 0; i < size; ++i) {
      const long long v = local(key[i]);
      const int* first = ranks.data() + start[v];
      const int* last = ranks.data() + start[v + 1];
      if (!any && last - first == 1) return {};  // a vertex inside the part
      if (i == 0) {
        result.assign(first, last);
        continue;
      }
      merged.clear();
      if (any)
        std::set_union(result.begin(), result.end(), first, last, std::back_inserter(merged));
      else
        std::set_intersection(result.begin(), result.end(), first, last, std::back_inserter(merged));
      result.swap(merged);
    }
    result.erase(std::remove(result.begin(), result.end(), self), result.end());
    return result;
  }
};

// The part's distinct entities with `size` vertices, numbered over all ranks.
struct NumberedEntities {
  std::vector<Key> keys;  // sorted
  std::vector<GlobalOrdinal> ids;
  std::vector<int> owners;
  long long count = 0;  // over all ranks

  std::size_t find(const Key& key) const { return std::lower_bound(keys.begin(), keys.end(), key) - keys.begin(); }
};

// Numbers the entities with the given keys (repeats allowed), each owned by the lowest rank
// that holds it: every rank tells each other rank that holds all the entity's vertices which
// entities it may share with it, the owners number theirs (rank by rank, in key order) and
// send the ids to the ranks that share them. `candidates(key)`: those other ranks.
NumberedEntities numberEntities(const Comm& comm, std::vector<Key> keys, int size,
                                const std::function<std::vector<int>(const Key&)>& candidates) {
  const int rank = comm.getRank(), ranks = comm.getSize();
  NumberedEntities result;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  result.keys = std::move(keys);
  const std::vector<Key>& all = result.keys;
  std::vector<std::vector<long long>> toRank(ranks);
  for (const Key& key : all)
    for (int r : candidates(key)) toRank[r].insert(toRank[r].end(), key.begin(), key.begin() + size);
  const std::vector<std::vector<long long>> fromRank = exchangeWithRanks(comm, toRank);

  // heldBy[r]: this rank's entities that rank r holds too.
  std::vector<std::vector<std::size_t>> heldBy(ranks);
  result.owners.assign(all.size(), rank);
  for (int r = 0; r < ranks; ++r)
    for (std::size_t i = 0; i < fromRank[r].size(); i += size) {
      const Key key = sortedVertexKey(&fromRank[r][i], size);
      const std::size_t e = result.find(key);
      if (e == all.size() || all[e] != key) continue;
      heldBy[r].push_back(e);
      result.owners[e] = std::min(result.owners[e], r);
    }
  const long long owned = std::count(result.owners.begin(), result.owners.end(), rank);
  long long next = 0;
  Teuchos::scan(comm, Teuchos::REDUCE_SUM, 1, &owned, &next);
  result.count = sumOverRanks(comm, owned);
  next -= owned;
  result.ids.assign(all.size(), -1);
  for (std::size_t e = 0; e < all.size(); ++e)
    if (result.owners[e] == rank) result.ids[e] = next++;

  for (int r = 0; r < ranks; ++r) {
    toRank[r].clear();
    for (std::size_t e : heldBy[r])
      if (result.owners[e] == rank) {
        toRank[r].insert(toRank[r].end(), all[e].begin(), all[e].begin() + size);
        toRank[r].push_back(result.ids[e]);
      }
  }
  for (const std::vector<long long>& received : exchangeWithRanks(comm, toRank))
    for (std::size_t i = 0; i < received.size(); i += size + 1)
      result.ids[result.find(sortedVertexKey(&received[i], size))] = received[i + size];
  if (std::find(result.ids.begin(), result.ids.end(), -1) != result.ids.end())
    throw Error("split mesh: an entity shared with another rank got no number from its owner");
  return result;
}

// Vertices: owners and global ids, then the part's vertices reordered by id (the mesh's
// cells and facets follow).
VertexSharing numberVertices(const Comm& comm, GmshMeshPart& read, MeshPart& part, long long& count) {
  SimplexMesh& mesh = read.mesh;
  const int d = mesh.dim;
  const long long nv = mesh.numVertices();
  const VertexSharing byTag{std::vector<GlobalOrdinal>(read.vertexTags.begin(), read.vertexTags.end()),
                            read.sharerStart, read.sharers};
  std::vector<Key> keys(nv);
  for (long long v = 0; v < nv; ++v) keys[v] = {read.vertexTags[v], -1, -1};  // ascending, as the vertices
  const NumberedEntities numbered = numberEntities(
      comm, std::move(keys), 1, [&](const Key& key) { return byTag.others(key, 1, comm.getRank()); });
  const std::vector<GlobalOrdinal>& ids = numbered.ids;
  const std::vector<int>& owners = numbered.owners;
  count = numbered.count;

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
          keys.push_back(sortedVertexKey(ids, 2));
        }
    } else {
      for (int f = 0; f <= d; ++f) {
        for (int v = 0, n = 0; v <= d; ++v)
          if (v != f) ids[n++] = sharing.ids[cell[v]];
        keys.push_back(sortedVertexKey(ids, 3));
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
    for (int r : sharing.others(sortedVertexKey(ids, d), d, comm.getRank(), true)) {
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

MeshPart latticePartOfSplitMesh(const RCP<const Comm>& comm, GmshMeshPart&& read, long long resolution) {
  const int d = read.mesh.dim;
  const long long numCells = read.mesh.numCells();
  if (numCells == 0) throw Error("split mesh: rank " + std::to_string(comm->getRank()) + " holds no cells");
  MeshPart part;
  long long numVertices = 0;
  const VertexSharing sharing = numberVertices(*comm, read, part, numVertices);
  part.mesh = std::move(read.mesh);
  read = GmshMeshPart();

  long long firstCell = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, 1, &numCells, &firstCell);
  firstCell -= numCells;
  part.globalCells.resize(numCells);
  std::iota(part.globalCells.begin(), part.globalCells.end(), firstCell);

  // Edges hold lattice points from resolution 2 on, faces (3D) from 3 on.
  long long counts[2] = {0, 0};
  for (int size = 2; size <= std::min(d, static_cast<int>(std::min<long long>(resolution, 3))); ++size) {
    const std::vector<Key> cellKeys = cellEntityKeys(part.mesh, sharing, size);
    const NumberedEntities entities = numberEntities(
        *comm, cellKeys, size, [&](const Key& key) { return sharing.others(key, size, comm->getRank()); });
    addCellEntities(entities, cellKeys, size == 2 ? part.cellEdges : part.cellFaces,
                    size == 2 ? part.edgeOwners : part.faceOwners);
    counts[size - 2] = entities.count;
  }
  addBoundary(*comm, sharing, part);
  part.entityCounts = {numVertices, counts[0], counts[1], sumOverRanks(*comm, numCells)};
  return part;
}

}  // namespace signorini::detail
