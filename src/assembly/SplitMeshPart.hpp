#pragma once
// Private to the library: the part of a mesh that every rank reads on its own, from one file
// per part (GmshMeshPart), made into the MeshPart a CoarseMeshLattice holds. The ranks number
// the vertices, edges and faces together, each entity owned by the lowest rank among its
// cells, by exchanges with the ranks that share it: no rank holds the whole mesh.
#include "assembly/MeshPart.hpp"
#include "fe/GmshMesh.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

// Rank r passes part r. The part's mesh keeps its cells with their vertex order and its
// boundary facets; its vertices are reordered by global id. Collective. Throws Error if the
// parts do not fit together (a rank holds no cells, or the global numbers would overflow).
MeshPart latticePartOfSplitMesh(const RCP<const Comm>& comm, GmshMeshPart&& read);

}  // namespace signorini::detail
