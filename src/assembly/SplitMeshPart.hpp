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
// boundary facets; its vertices are reordered by global id. Only the entities that hold
// lattice points of `resolution` (CoarseMeshLattice) are numbered: edges from 2 on, faces
// from 3. Collective. Throws Error if the parts do not fit together (a rank holds no cells, a
// shared entity gets no number).
MeshPart latticePartOfSplitMesh(const RCP<const Comm>& comm, GmshMeshPart&& read, long long resolution);

}  // namespace signorini::detail
