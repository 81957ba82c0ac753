#pragma once
// Private to the library: what rank 0 sends each rank of a DistributedSpace. The rank's
// cells form a mesh of their own; the P_k space built on it numbers its nodes like any
// LagrangeSpace, and the part says for each of those nodes its renumbered global id and
// its owner.
#include <vector>

#include "fe/SimplexMesh.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

struct MeshPart {
  // The rank's cells in global cell order, their vertices in global vertex order, the
  // boundary facets of these cells (each global facet is in exactly one part) and every
  // boundary name.
  SimplexMesh mesh;
  std::vector<long long> globalCells;  // global id of each cell of mesh
  // Per node of LagrangeSpace(mesh, degree): renumbered (Tpetra) id and owner rank.
  std::vector<GlobalOrdinal> nodeIds;
  std::vector<int> nodeOwners;
  // Coordinates of the nodes past the vertices, taken from the global space (see LagrangeSpace).
  std::vector<double> nodeCoordinates;
  // Nodes of that space on each tagged boundary of the global mesh, sorted, as CSR over
  // boundaryTags: a node of this part may lie on a facet that only another part holds.
  std::vector<int> boundaryTags;
  std::vector<long long> boundaryStart, boundaryNodes;
};

// Point-to-point transfer from rank 0 (blocking; parts of any size).
void sendMeshPart(const Comm& comm, const MeshPart& part, int destination);
MeshPart receiveMeshPart(const Comm& comm, int source);

}  // namespace signorini::detail
