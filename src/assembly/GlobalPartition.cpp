#include "assembly/GlobalPartition.hpp"

#include <algorithm>

#include "fe/MeshPartition.hpp"

namespace signorini::detail {
namespace {

// CSR of the items [0, part.size()) grouped by part, in increasing item order within a part.
void groupByPart(const std::vector<int>& part, int numParts, std::vector<long long>& start,
                 std::vector<long long>& items) {
  start.assign(numParts + 1, 0);
  for (int p : part) ++start[p + 1];
  for (int p = 0; p < numParts; ++p) start[p + 1] += start[p];
  items.resize(part.size());
  std::vector<long long> next(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < part.size(); ++i) items[next[part[i]]++] = static_cast<long long>(i);
}

template <class T>
std::size_t capacityBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace

GlobalPartition::GlobalPartition(const SimplexMesh& mesh, int degree, int numParts)
    : mesh_(mesh), space_(mesh, degree) {
  cellPart_ = partitionCells(mesh_, numParts);
  nodeOwner_ = nodeOwners(space_, cellPart_);

  // Contiguous renumbering: rank r owns [offset_r, offset_{r+1}), nodes kept in space order.
  const long long numNodes = space_.numNodes();
  std::vector<long long> next(numParts + 1, 0);
  for (long long n = 0; n < numNodes; ++n) ++next[nodeOwner_[n] + 1];
  for (int r = 0; r < numParts; ++r) next[r + 1] += next[r];
  newId_.resize(numNodes);
  for (long long n = 0; n < numNodes; ++n) newId_[n] = next[nodeOwner_[n]]++;

  groupByPart(cellPart_, numParts, cellStart_, partCells_);
  std::vector<int> facetPart(mesh_.numFacets());
  for (long long f = 0; f < mesh_.numFacets(); ++f) facetPart[f] = cellPart_[space_.facetCell(f).first];
  groupByPart(facetPart, numParts, facetStart_, partFacets_);

  tags_ = mesh_.facetTags;
  std::sort(tags_.begin(), tags_.end());
  tags_.erase(std::unique(tags_.begin(), tags_.end()), tags_.end());
  for (int tag : tags_) tagNodes_.push_back(space_.boundaryNodes(tag));
  localNode_.assign(numNodes, -1);
}

MeshPart GlobalPartition::part(int rank) {
  const int d = mesh_.dim, npc = space_.nodesPerCell();
  MeshPart part;
  SimplexMesh& mesh = part.mesh;
  mesh.dim = d;
  mesh.boundaryTags = mesh_.boundaryTags;
  mesh.bodyTags = mesh_.bodyTags;
  part.globalCells.assign(partCells_.begin() + cellStart_[rank], partCells_.begin() + cellStart_[rank + 1]);

  // Vertices in global order; a vertex's node id is its vertex id in either space.
  std::vector<long long> globalNodes;
  for (long long cell : part.globalCells)
    for (int v = 0; v <= d; ++v) {
      const long long vertex = mesh_.cells[(d + 1) * cell + v];
      if (localNode_[vertex] == -1) {
        localNode_[vertex] = 0;
        globalNodes.push_back(vertex);
      }
    }
  std::sort(globalNodes.begin(), globalNodes.end());
  mesh.vertices.reserve(d * globalNodes.size());
  for (std::size_t i = 0; i < globalNodes.size(); ++i) {
    localNode_[globalNodes[i]] = static_cast<long long>(i);
    mesh.vertices.insert(mesh.vertices.end(), mesh_.vertices.begin() + d * globalNodes[i],
                         mesh_.vertices.begin() + d * (globalNodes[i] + 1));
  }
  mesh.cells.reserve((d + 1) * part.globalCells.size());
  for (long long cell : part.globalCells)
    for (int v = 0; v <= d; ++v) mesh.cells.push_back(localNode_[mesh_.cells[(d + 1) * cell + v]]);
  if (!mesh_.cellTags.empty())
    for (long long cell : part.globalCells) mesh.cellTags.push_back(mesh_.cellTags[cell]);
  for (long long i = facetStart_[rank]; i < facetStart_[rank + 1]; ++i) {
    const long long facet = partFacets_[i];
    for (int v = 0; v < d; ++v) mesh.facets.push_back(localNode_[mesh_.facets[d * facet + v]]);
    mesh.facetTags.push_back(mesh_.facetTags[facet]);
  }

  // The other nodes as LagrangeSpace numbers them on the part's mesh: in order of first
  // appearance in the loop over the cells, cells in the same order and with the same
  // vertex order as in the global mesh.
  for (long long cell : part.globalCells) {
    const long long* nodes = space_.cellNodes(cell);
    for (int local = d + 1; local < npc; ++local)
      if (localNode_[nodes[local]] == -1) {
        localNode_[nodes[local]] = static_cast<long long>(globalNodes.size());
        globalNodes.push_back(nodes[local]);
      }
  }
  part.nodeIds.reserve(globalNodes.size());
  part.nodeOwners.reserve(globalNodes.size());
  for (long long node : globalNodes) {
    part.nodeIds.push_back(newId_[node]);
    part.nodeOwners.push_back(nodeOwner_[node]);
  }
  const auto& coordinates = space_.nodeCoordinates();
  for (std::size_t i = mesh.numVertices(); i < globalNodes.size(); ++i)
    part.nodeCoordinates.insert(part.nodeCoordinates.end(), coordinates.begin() + d * globalNodes[i],
                                coordinates.begin() + d * (globalNodes[i] + 1));

  part.boundaryTags = tags_;
  part.boundaryStart.push_back(0);
  for (const std::vector<long long>& nodes : tagNodes_) {
    const std::size_t first = part.boundaryNodes.size();
    for (long long node : nodes)
      if (localNode_[node] >= 0) part.boundaryNodes.push_back(localNode_[node]);
    std::sort(part.boundaryNodes.begin() + first, part.boundaryNodes.end());
    part.boundaryStart.push_back(static_cast<long long>(part.boundaryNodes.size()));
  }

  for (long long node : globalNodes) localNode_[node] = -1;
  return part;
}

std::size_t GlobalPartition::bytes() const {
  std::size_t tagNodes = 0;
  for (const auto& nodes : tagNodes_) tagNodes += capacityBytes(nodes);
  return space_.bytes() + capacityBytes(cellPart_) + capacityBytes(nodeOwner_) + capacityBytes(newId_) + capacityBytes(cellStart_) +
         capacityBytes(partCells_) + capacityBytes(facetStart_) + capacityBytes(partFacets_) + capacityBytes(tags_) +
         tagNodes + capacityBytes(localNode_);
}

}  // namespace signorini::detail
