#pragma once
// A stiffness matrix assembled cell by cell on each rank's overlap rows, then summed on the
// rows' owners: the rows are the DOFs of the overlap nodes (owned nodes first), in local
// indices from the start. The graph goes from the cells' node lists straight into CSR
// arrays: every component row of a node gets all components of its neighbours, and an owned
// row also the neighbours its node has through other ranks' cells, so that the ghost rows
// sent to the owners find their entries. The owned rows are a prefix of the overlap rows:
// the owned matrix keeps the same arrays, and only the ghost rows travel.
#include <vector>

#include <Tpetra_CrsMatrix_decl.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class OverlapStiffness {
 public:
  // The graph of the local cells, entries zero. Collective.
  explicit OverlapStiffness(const DistributedSpace& space);

  // Local row and column of space DOF dim * (space node) + component.
  LocalOrdinal row(long long spaceDof) const { return row_[spaceDof]; }
  LocalOrdinal column(long long spaceDof) const { return column_[spaceDof]; }

  // Adds the (dim * npc)^2 element matrix Ke, row-major, at local rows and columns.
  void addElementMatrix(int dim, int npc, const LocalOrdinal* rows, const LocalOrdinal* cols, const double* Ke);
  void add(LocalOrdinal row, LocalOrdinal column, double value) { values_(find(row, column)) += value; }

  // The owned rows summed over the ranks; domain and range: the owned DOF map. Collective;
  // the arrays pass to the matrix, so nothing may be added afterwards.
  RCP<CrsMatrix> sumOnOwners();

 private:
  using LocalGraph = CrsMatrix::local_graph_device_type;
  using RowOffsets = LocalGraph::row_map_type::non_const_type;
  using Columns = LocalGraph::entries_type::non_const_type;
  using Values = CrsMatrix::local_matrix_device_type::values_type;

  // Position of (row, column) in the CSR arrays; rows are sorted.
  std::size_t find(LocalOrdinal row, LocalOrdinal column) const;

  RCP<const Map> ownedDofs_, overlapDofs_, columnMap_;
  std::vector<LocalOrdinal> row_, column_;
  RowOffsets offsets_;
  Columns columns_;
  Values values_;
};

}  // namespace signorini
