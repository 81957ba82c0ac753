#pragma once
// Private to the library: a whole Gmsh mesh file read by all ranks together, none of them
// holding the mesh. Each rank reads a slice of the file (MshFileSlice); the ranks sort the
// cells along a Morton curve of their centroids, so that each holds a compact region, and
// each pairs its cells' faces; a directory of faces pairs those left across ranks, PT-Scotch
// partitions the cells' dual graph, and each rank receives its part's cells, their nodes' coordinates from a
// directory of node tags, and the boundary facets of its cells: the part that
// readGmshMeshPart reads from a mesh Gmsh partitioned, for the same path on
// (latticePartOfSplitMesh).
#include <string>

#include "fe/GmshMesh.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

// Rank r's part, part r, of the mesh in the .msh file at `path`, read as readGmshMesh reads
// it, or an empty part (`part` = -1) on every rank if some rank cannot open the file or the
// file is outside what MshFileSlice reads (`unsupported` says why). Collective. Throws InputError on every rank for a malformed
// file or mesh: a cell's node the file does not define, a degenerate cell, a 2D node off the
// plane z = 0, a face held by more than two cells, a boundary facet that is no face of a cell,
// fewer cells than ranks. Throws Error if PT-Scotch fails.
GmshMeshPart readMshInParallel(const RCP<const Comm>& comm, const std::string& path, std::string& unsupported);

}  // namespace signorini::detail
