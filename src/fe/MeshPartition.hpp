#pragma once
// Partition of a mesh's cells into one part per rank, and the owner of each node it implies.
#include <vector>

#include "fe/LagrangeSpace.hpp"
#include "fe/SimplexMesh.hpp"

namespace signorini {

// Part of each cell, by METIS_PartMeshNodal: METIS partitions the graph of the mesh's
// vertices and gives each cell a part of its vertices. Deterministic (fixed seed); numParts
// == 1 gives all zeros without METIS.
// Throws InputError for numParts < 1, Error if METIS fails or the mesh is too large for its
// index type.
std::vector<int> partitionCells(const SimplexMesh& mesh, int numParts);

// Owner of each node of the space: the smallest part among the cells containing it.
// Throws InputError if a node lies in no cell.
std::vector<int> nodeOwners(const LagrangeSpace& space, const std::vector<int>& cellPart);

}  // namespace signorini
