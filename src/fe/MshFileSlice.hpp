#pragma once
// One rank's slice of a Gmsh mesh file that all ranks of a run read together, so that no rank
// holds the whole mesh. The Gmsh SDK reads a file whole, so this reader scans the file itself
// and parses only the lines of its slice. It knows the part of the MSH 4.1 ASCII format that
// describes a linear simplex mesh (Gmsh's default output); readMshSlice says why a file
// is outside it, and such a file is read whole by Gmsh (readGmshMesh), which also words the
// errors of an unsupported file.
#include <map>
#include <string>
#include <vector>

namespace signorini {

struct MshFileSlice {
  // As readGmshMesh reads the file: dim is the highest dimension of its elements; the cells
  // are the elements of that dimension in the physical groups of that dimension (its bodies),
  // all of them if there are none; the boundary facets are the elements of the physical
  // groups of dimension dim - 1, one entry per (group, element). Names as readGmshMesh gives.
  int dim = 0;
  std::map<std::string, int> boundaryTags, bodyTags;
  long long numCells = 0;  // in the whole file

  // The slice's cells: of the file's cells in the file's order, those of index in
  // [sliceStart(numCells, slice, numSlices), sliceStart(numCells, slice + 1, numSlices)).
  std::vector<long long> cellElements;  // Gmsh element tag of each
  std::vector<long long> cellNodes;     // dim + 1 Gmsh node tags per cell, Gmsh's order
  std::vector<int> cellBodies;          // body tag per cell; empty when the file has no bodies
  // The slice's boundary facets, cut as the cells are (by index among the facet elements).
  std::vector<long long> facetElements, facetNodes;  // dim node tags per facet
  std::vector<int> facetTags;

  // The nodes whose tag sliceOfNode puts in this slice (a slice of the file's tag range), in
  // the file's order, and their x, y, z. Nodes no cell uses are among them.
  std::vector<long long> nodeTags;
  std::vector<double> nodeCoordinates;

  // The first of `total` items (cells, facets) in slice `slice` of `numSlices`.
  static long long sliceStart(long long total, int slice, int numSlices);
  // The rank that holds node `tag` in slices of the same file cut into `numSlices`.
  static int sliceOfNode(long long tag, long long minTag, long long maxTag, int numSlices);
  long long minNodeTag = 0, maxNodeTag = 0;  // of the file
};

// Slice `slice` of `numSlices` of the file at `path`. If the reader cannot read the file (not
// MSH 4.1 ASCII, a partitioned mesh, cells or boundary facets other than linear simplices, no
// elements of dimension 2 or 3, two physical groups of one dimension with one name, not well
// formed where the headers are), `unsupported` says why and the slice is empty (dim 0); it
// finds out from the headers, before parsing any coordinate. Throws InputError, with the path
// in the message, if the file cannot be opened or a line of the slice is malformed.
MshFileSlice readMshSlice(const std::string& path, int slice, int numSlices, std::string& unsupported);

}  // namespace signorini
