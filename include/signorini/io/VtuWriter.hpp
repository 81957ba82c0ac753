#pragma once
/// \file
/// ParaView output: VTK XML unstructured grids, one .vtu piece per rank plus a .pvtu index.
/// P1 cells are written as VTK_TRIANGLE / VTK_TETRA, P2 and P3 cells as VTK_LAGRANGE_TRIANGLE
/// / VTK_LAGRANGE_TETRAHEDRON with their nodes in VTK's order. Arrays are inline base64
/// "binary" data with UInt64 headers; connectivity and offsets are Int64.
#include <string>
#include <vector>

#include "signorini/assembly/FiniteElementSpace.hpp"

namespace signorini {

/// A field given per overlap node of this rank (FiniteElementSpace::numOverlapNodes(), in
/// that order), `components` values per node.
struct NodeField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// A field given per cell of this rank (FiniteElementSpace::numLocalCells(), in that order).
struct CellField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// Writes `directory/basename.pvtu` (rank 0) and `directory/basename_RANK.vtu` (every
/// rank): the cells of each rank with the nodes of its overlap, and the fields. 2D points
/// get z = 0 and 2-component fields are padded to 3, so ParaView shows them as vectors. Each
/// file is written under a temporary name in the same directory and then renamed; the
/// directory is created if absent. Collective over space.comm(); every rank passes the same
/// field names and component counts. Throws Error (on every rank) if a field has the wrong
/// size or a file or the directory cannot be written.
void writeVtu(const FiniteElementSpace& space, const std::vector<NodeField>& nodeFields,
              const std::vector<CellField>& cellFields, const std::string& directory,
              const std::string& basename = "solution");

}  // namespace signorini
