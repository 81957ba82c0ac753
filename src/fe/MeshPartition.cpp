#include "fe/MeshPartition.hpp"

#include <metis.h>

#include <algorithm>
#include <limits>
#include <string>

#include "signorini/core/Error.hpp"

namespace signorini {

std::vector<int> partitionCells(const SimplexMesh& mesh, int numParts) {
  if (numParts < 1) throw InputError("mesh partition: number of parts must be >= 1, got " + std::to_string(numParts));
  const long long numCells = mesh.numCells();
  if (numParts == 1 || numCells == 0) return std::vector<int>(numCells, 0);
  if (static_cast<long long>(mesh.cells.size()) > std::numeric_limits<idx_t>::max() ||
      mesh.numVertices() > std::numeric_limits<idx_t>::max())
    throw Error("mesh partition: mesh too large for METIS' " + std::to_string(8 * sizeof(idx_t)) + "-bit indices");

  idx_t ne = static_cast<idx_t>(numCells), nn = static_cast<idx_t>(mesh.numVertices());
  idx_t nparts = numParts, objval = 0;
  std::vector<idx_t> eptr(numCells + 1), eind(mesh.cells.begin(), mesh.cells.end());
  for (long long cell = 0; cell <= numCells; ++cell) eptr[cell] = static_cast<idx_t>((mesh.dim + 1) * cell);
  std::vector<idx_t> cellPart(numCells), vertexPart(mesh.numVertices());
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  // The nodal graph has a sixth of the dual graph's vertices in 3D: rank 0, which partitions
  // alone, builds and cuts it several times faster, for a somewhat larger interface.
  const int status = METIS_PartMeshNodal(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &nparts, nullptr,
                                         options, &objval, cellPart.data(), vertexPart.data());
  if (status != METIS_OK) throw Error("mesh partition: METIS_PartMeshNodal failed with status " + std::to_string(status));
  return std::vector<int>(cellPart.begin(), cellPart.end());
}

std::vector<int> nodeOwners(const LagrangeSpace& space, const std::vector<int>& cellPart) {
  const long long numCells = space.mesh().numCells();
  if (static_cast<long long>(cellPart.size()) != numCells)
    throw InputError("node owners: " + std::to_string(cellPart.size()) + " cell parts for " +
                     std::to_string(numCells) + " cells");
  std::vector<int> owner(space.numNodes(), std::numeric_limits<int>::max());
  for (long long cell = 0; cell < numCells; ++cell) {
    const long long* nodes = space.cellNodes(cell);
    for (int local = 0; local < space.nodesPerCell(); ++local)
      owner[nodes[local]] = std::min(owner[nodes[local]], cellPart[cell]);
  }
  for (long long node = 0; node < space.numNodes(); ++node)
    if (owner[node] == std::numeric_limits<int>::max())
      throw InputError("node owners: node " + std::to_string(node) + " lies in no cell");
  return owner;
}

}  // namespace signorini
