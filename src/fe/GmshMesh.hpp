#pragma once
// Reading a Gmsh mesh file (.msh, format 2.2 or 4.x), or meshing a Gmsh geometry (.geo),
// into a SimplexMesh through the Gmsh SDK (libgmsh): the file format is parsed by Gmsh,
// never here.
#include <string>
#include <vector>

#include "fe/SimplexMesh.hpp"

namespace signorini {

// Reads the Gmsh mesh file at `path`; a .geo file is meshed first, in its own dimension,
// with linear elements and its mesh sizes multiplied by `sizeFactor` (Mesh.MeshSizeFactor).
//
// - dim is the highest dimension of the elements in the file (2 or 3). The cells are the
//   elements of that dimension in the physical groups of that dimension if the file has
//   any, otherwise all elements of that dimension, in increasing Gmsh element tag. An
//   element is taken once even if it is in several groups, or repeated with the same nodes
//   (as MSH 2 files store an element in several groups). They must be linear triangles (2D)
//   or linear tetrahedra (3D).
// - In 2D the vertices keep x and y; every |z| must be <= 1e-12 times the mesh's extent.
// - The vertices are the nodes used by the cells, numbered 0.. in increasing Gmsh node tag.
// - Every cell is positively oriented (two vertices swapped where Gmsh's order is not).
// - notes: of a .geo file that selects Gmsh's HXT 3D mesher (Mesh.Algorithm3D = 10), that
//   its mesh changes from run to run (Gmsh 4.8.4's does, even on one thread).
// - The boundary facets are the elements of the physical groups of dimension dim - 1, one
//   entry per (group, element): a facet in two groups is listed twice. Each must be a face
//   of a cell (not necessarily on the boundary: interfaces are allowed). Their vertex order
//   is Gmsh's. boundaryTags maps each group's physical name ("physical<tag>" when unnamed)
//   to its physical tag, which is the facets' tag.
//
// Throws InputError, with the path in the message, if the file is missing or unreadable, a
// .msh file does not start with $MeshFormat,
// holds no triangle or tetrahedron, has cells of another type (quadrangles, hexahedra,
// second-order elements...), a degenerate cell, a 2D node off the plane z = 0, a boundary
// element that is not a face of a cell, or two boundary groups with the same name.
//
// Gmsh reads the file in a child process (fork), which sends the mesh back through a pipe:
// Gmsh 4.8's readers crash on some malformed files and its .geo parser does not recover from
// a syntax error, and neither reaches this process, where a crash becomes an InputError and
// Gmsh's state (a Gmsh session the caller has open, its models and options) is left as it was.
// A malformed file can also send Gmsh's reader into an endless loop: a child that has not
// answered after `timeLimitSeconds` is stopped, and that too is an InputError. A negative
// limit is the default: a minute plus a second per MB for a .msh file, none for a .geo file
// (meshing takes as long as the geometry asks).
SimplexMesh readGmshMesh(const std::string& path, double sizeFactor = 1.0, double timeLimitSeconds = -1);

// One part of a mesh that Gmsh partitioned and wrote as one file per part (gmsh -part N
// -part_split, or Mesh.PartitionSplitMeshFiles = 1: files name_1.msh .. name_N.msh).
struct GmshMeshPart {
  // The part's cells, read as readGmshMesh reads a whole file: the boundary facets are the
  // part's elements of the boundary groups (the interfaces Gmsh makes between the parts are
  // no boundary); vertices numbered in increasing Gmsh node tag.
  SimplexMesh mesh;
  int part = -1;  // which part, from 0: file name_k.msh holds part k - 1
  // Per vertex: its Gmsh node tag (the same in every part) and the parts whose cells hold it,
  // ascending, this one among them (CSR).
  std::vector<long long> vertexTags;
  std::vector<long long> sharerStart;
  std::vector<int> sharers;
};

// Reads one part file as readGmshMesh reads a .msh file, with the same errors, and also
// throws InputError if the file is not one part of a partitioned mesh.
GmshMeshPart readGmshMeshPart(const std::string& path, double timeLimitSeconds = -1);

// The closest point of the .geo geometry at `path` on entity (dims[i], entities[i]) to point i
// (x, y, z per point; Gmsh's orthogonal projection), for each point. The geometry is loaded,
// not meshed, in a child process as above. Throws InputError if Gmsh cannot load it or has no
// such entity.
std::vector<double> closestPointsOnGeometry(const std::string& path, const std::vector<int>& dims,
                                            const std::vector<int>& entities, const std::vector<double>& points);

}  // namespace signorini
