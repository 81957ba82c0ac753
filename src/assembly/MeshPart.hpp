#pragma once
// Private to the library: what rank 0 sends each rank of a DistributedSpace. The rank's
// cells form a mesh of their own; the P_k space built on it numbers its nodes like any
// LagrangeSpace, and the part says for each of those nodes its renumbered global id and
// its owner.
#include <memory>
#include <vector>

#include "fe/LagrangeSpace.hpp"
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

  // Only in a part of a mesh that is to be refined (see CoarseMeshLattice): the global ids and
  // owners of each cell's edges (in the order (0,1), (0,2), .., (d-1,d)) and, in 3D, faces
  // (the face opposite vertex f at f); the boundary facets with at least two vertices among
  // the part's, as renumbered vertex ids, and their tags; the global numbers of vertices,
  // edges, faces (3D) and cells.
  std::vector<long long> cellEdges, cellFaces;
  std::vector<int> edgeOwners, faceOwners;
  std::vector<long long> nearFacets;
  std::vector<int> nearFacetTags;
  std::vector<long long> entityCounts;
  // The same for the coarse mesh's geometry facets and edges (SimplexMesh::geometryFacets):
  // those with at least two vertices among the part's, with their geometry entities.
  std::vector<long long> nearGeometryFacets, nearGeometryEdges;
  std::vector<int> nearGeometryFacetEntities, nearGeometryEdgeEntities;
};

// A part that its rank made for itself (a box block, refined coarse cells), with the P_k space
// that numbered its nodes, so that the distributed space need not build it again.
struct PartWithSpace {
  MeshPart part;  // without its mesh and node coordinates: `mesh` and `space` hold them
  std::shared_ptr<const SimplexMesh> mesh;
  std::unique_ptr<LagrangeSpace> space;
  long long numGlobalNodes = 0, numGlobalCells = 0;
};

// The renumbered ids of a part's nodes, each named by a global `key` (the same on every rank
// that holds the node) and given its owner: owners number their nodes in the order of
// `order` (a permutation of the part's nodes; empty: the part's order), after those of the
// ranks before them, and the other ranks ask the owners for the ids of their keys (Error if
// an owner does not hold one). Returns the ids; `numGlobalNodes` is the sum of the owned
// counts. Collective.
std::vector<GlobalOrdinal> ownerOrderedIds(const RCP<const Comm>& comm, const std::vector<GlobalOrdinal>& keys,
                                           const std::vector<int>& owners, long long& numGlobalNodes,
                                           const std::vector<long long>& order = {});

// Point-to-point transfer from rank 0 (blocking; parts of any size).
void sendMeshPart(const Comm& comm, const MeshPart& part, int destination);
MeshPart receiveMeshPart(const Comm& comm, int source);

}  // namespace signorini::detail
