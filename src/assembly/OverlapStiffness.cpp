#include "assembly/OverlapStiffness.hpp"

#include <algorithm>
#include <numeric>

#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Distributor.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Lists in CSR form: list i is items[start[i] .. start[i + 1]).
template <class T>
struct Lists {
  std::vector<std::size_t> start;
  std::vector<T> items;
};

// For each overlap node, its neighbours through the local cells (itself included), as
// overlap indices. Built in CSR form (a count pass and a fill pass, with a marker per node):
// a vector per node would leave the heap fragmented for the rest of the run.
Lists<int> localNeighbours(const DistributedSpace& ds) {
  const LagrangeSpace& space = ds.space();
  const int npc = space.nodesPerCell();
  const auto& overlap = ds.overlapSpaceNodes();
  const std::size_t numOverlap = overlap.size();
  std::vector<int> localIndex(space.numNodes(), -1);
  for (std::size_t i = 0; i < numOverlap; ++i) localIndex[overlap[i]] = static_cast<int>(i);

  // node -> local cells
  const long long numCells = ds.mesh().numCells();
  std::vector<std::size_t> cellStart(numOverlap + 1, 0);
  for (long long c = 0; c < numCells; ++c)
    for (int i = 0; i < npc; ++i) ++cellStart[localIndex[space.cellNodes(c)[i]] + 1];
  for (std::size_t i = 0; i < numOverlap; ++i) cellStart[i + 1] += cellStart[i];
  std::vector<LocalOrdinal> cellsOfNode(cellStart.back());  // local cell ids
  {
    std::vector<std::size_t> next(cellStart.begin(), cellStart.end() - 1);
    for (long long c = 0; c < numCells; ++c)
      for (int i = 0; i < npc; ++i) cellsOfNode[next[localIndex[space.cellNodes(c)[i]]]++] = static_cast<LocalOrdinal>(c);
  }

  // `visit` calls f once per neighbour of node i.
  std::vector<std::size_t> lastSeenBy(numOverlap, numOverlap);
  const auto visit = [&](std::size_t i, auto&& f) {
    for (std::size_t k = cellStart[i]; k < cellStart[i + 1]; ++k) {
      const long long* nodes = space.cellNodes(cellsOfNode[k]);
      for (int j = 0; j < npc; ++j) {
        const int n = localIndex[nodes[j]];
        if (lastSeenBy[n] != i) {
          lastSeenBy[n] = i;
          f(n);
        }
      }
    }
  };
  Lists<int> neighbours{std::vector<std::size_t>(numOverlap + 1, 0), {}};
  for (std::size_t i = 0; i < numOverlap; ++i) visit(i, [&](int) { ++neighbours.start[i + 1]; });
  for (std::size_t i = 0; i < numOverlap; ++i) neighbours.start[i + 1] += neighbours.start[i];
  neighbours.items.resize(neighbours.start.back());
  std::fill(lastSeenBy.begin(), lastSeenBy.end(), numOverlap);
  for (std::size_t i = 0; i < numOverlap; ++i) {
    std::size_t next = neighbours.start[i];
    visit(i, [&](int n) { neighbours.items[next++] = n; });
  }
  return neighbours;
}

// For each owned node (overlap index below the owned count), its neighbours through other
// ranks' cells, as global node ids: every rank sends the local neighbour lists of its ghost
// nodes to their owners. Collective.
Lists<GlobalOrdinal> remoteNeighbours(const DistributedSpace& ds, const Lists<int>& local) {
  const auto& overlap = ds.overlapSpaceNodes();
  const std::size_t numOwned = ds.ownedNodeMap()->getNodeNumElements();
  // The ghosts follow the owned nodes sorted by global id, so grouped by owner: one message
  // per owner, [node, its neighbours...] per ghost.
  std::vector<int> owners;
  std::vector<std::size_t> counts;
  std::vector<GlobalOrdinal> exports;
  for (std::size_t g = numOwned; g < overlap.size(); ++g) {
    owners.push_back(ds.nodeOwner(overlap[g]));
    counts.push_back(1 + local.start[g + 1] - local.start[g]);
    exports.push_back(ds.globalNode(overlap[g]));
    for (std::size_t k = local.start[g]; k < local.start[g + 1]; ++k)
      exports.push_back(ds.globalNode(overlap[local.items[k]]));
  }
  Tpetra::Distributor distributor(ds.comm());
  std::vector<std::size_t> importCounts(distributor.createFromSends(Teuchos::ArrayView<const int>(owners)));
  distributor.doPostsAndWaits(Teuchos::ArrayView<const std::size_t>(counts), 1,
                              Teuchos::ArrayView<std::size_t>(importCounts));
  std::vector<GlobalOrdinal> imports(std::accumulate(importCounts.begin(), importCounts.end(), std::size_t(0)));
  distributor.doPostsAndWaits(Teuchos::ArrayView<const GlobalOrdinal>(exports),
                              Teuchos::ArrayView<const std::size_t>(counts), Teuchos::ArrayView<GlobalOrdinal>(imports),
                              Teuchos::ArrayView<const std::size_t>(importCounts));

  const Map& owned = *ds.ownedNodeMap();
  const auto ownedIndex = [&](std::size_t at) {
    const LocalOrdinal i = owned.getLocalElement(imports[at]);
    if (i == Teuchos::OrdinalTraits<LocalOrdinal>::invalid())
      throw Error("assembly: a rank sent the neighbours of a node it does not own to the wrong owner");
    return static_cast<std::size_t>(i);
  };
  Lists<GlobalOrdinal> remote{std::vector<std::size_t>(numOwned + 1, 0), {}};
  for (std::size_t m = 0, at = 0; m < importCounts.size(); at += importCounts[m++])
    remote.start[ownedIndex(at) + 1] += importCounts[m] - 1;
  for (std::size_t i = 0; i < numOwned; ++i) remote.start[i + 1] += remote.start[i];
  remote.items.resize(remote.start.back());
  std::vector<std::size_t> next(remote.start.begin(), remote.start.end() - 1);
  for (std::size_t m = 0, at = 0; m < importCounts.size(); at += importCounts[m++])
    for (std::size_t k = 1; k < importCounts[m]; ++k) remote.items[next[ownedIndex(at)]++] = imports[at + k];
  return remote;
}

// Column-map node indices: the owned nodes first, in their order, then every other column
// node by global id (`others`). `overlapColumn`: that of each overlap node; `columns`: each
// overlap node's column nodes, sorted, its local neighbours and, for an owned node, its
// remote ones.
struct ColumnNodes {
  std::vector<GlobalOrdinal> others;
  std::vector<LocalOrdinal> overlapColumn;
  Lists<LocalOrdinal> columns;
};
ColumnNodes columnNodes(const DistributedSpace& ds) {
  const auto& overlap = ds.overlapSpaceNodes();
  const std::size_t numOverlap = overlap.size(), numOwned = ds.ownedNodeMap()->getNodeNumElements();
  const Lists<int> local = localNeighbours(ds);
  const Lists<GlobalOrdinal> remote = remoteNeighbours(ds, local);

  const Map& owned = *ds.ownedNodeMap();
  ColumnNodes result;
  std::vector<GlobalOrdinal>& others = result.others;
  for (std::size_t g = numOwned; g < numOverlap; ++g) others.push_back(ds.globalNode(overlap[g]));
  for (GlobalOrdinal n : remote.items)
    if (!owned.isNodeGlobalElement(n)) others.push_back(n);
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  const auto columnOf = [&](GlobalOrdinal n) {
    const LocalOrdinal i = owned.getLocalElement(n);
    if (i != Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) return i;
    return static_cast<LocalOrdinal>(numOwned + (std::lower_bound(others.begin(), others.end(), n) - others.begin()));
  };
  std::vector<LocalOrdinal>& overlapColumn = result.overlapColumn;
  overlapColumn.resize(numOverlap);
  for (std::size_t i = 0; i < numOverlap; ++i)
    overlapColumn[i] = i < numOwned ? static_cast<LocalOrdinal>(i) : columnOf(ds.globalNode(overlap[i]));

  Lists<LocalOrdinal>& columns = result.columns;
  columns.start.assign(numOverlap + 1, 0);
  columns.items.reserve(local.items.size() + remote.items.size());
  for (std::size_t i = 0; i < numOverlap; ++i) {
    const auto first = columns.items.size();
    for (std::size_t k = local.start[i]; k < local.start[i + 1]; ++k)
      columns.items.push_back(overlapColumn[local.items[k]]);
    if (i < numOwned)
      for (std::size_t k = remote.start[i]; k < remote.start[i + 1]; ++k) columns.items.push_back(columnOf(remote.items[k]));
    std::sort(columns.items.begin() + first, columns.items.end());
    columns.items.erase(std::unique(columns.items.begin() + first, columns.items.end()), columns.items.end());
    columns.start[i + 1] = columns.items.size();
  }
  return result;
}

}  // namespace

OverlapStiffness::OverlapStiffness(const DistributedSpace& ds)
    : ownedDofs_(ds.ownedDofMap()), overlapDofs_(ds.overlapDofMap()) {
  const int dim = ds.dim();
  const auto& overlap = ds.overlapSpaceNodes();
  const std::size_t numOverlap = overlap.size(), numOwned = ds.ownedNodeMap()->getNodeNumElements();
  const ColumnNodes nodes = columnNodes(ds);

  std::vector<GlobalOrdinal> columnDofs;
  columnDofs.reserve(dim * (numOwned + nodes.others.size()));
  const auto addDofs = [&](GlobalOrdinal node) {
    for (int c = 0; c < dim; ++c) columnDofs.push_back(dim * node + c);
  };
  for (std::size_t i = 0; i < numOwned; ++i) addDofs(ds.globalNode(overlap[i]));
  for (GlobalOrdinal n : nodes.others) addDofs(n);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  columnMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(columnDofs), 0, ds.comm()));

  // Node i's dim rows each hold the dim components of its column nodes, in column order.
  const auto& columns = nodes.columns;
  offsets_ = RowOffsets(Kokkos::view_alloc(Kokkos::WithoutInitializing, "stiffness row offsets"), dim * numOverlap + 1);
  offsets_(0) = 0;
  for (std::size_t i = 0; i < numOverlap; ++i)
    for (int a = 0; a < dim; ++a)
      offsets_(dim * i + a + 1) = offsets_(dim * i + a) + dim * (columns.start[i + 1] - columns.start[i]);
  columns_ = Columns(Kokkos::view_alloc(Kokkos::WithoutInitializing, "stiffness columns"), offsets_(dim * numOverlap));
  for (std::size_t i = 0; i < numOverlap; ++i)
    for (int a = 0; a < dim; ++a) {
      std::size_t at = offsets_(dim * i + a);
      for (std::size_t k = columns.start[i]; k < columns.start[i + 1]; ++k)
        for (int c = 0; c < dim; ++c) columns_(at++) = dim * columns.items[k] + c;
    }
  values_ = Values("stiffness values", columns_.extent(0));

  row_.resize(dim * ds.space().numNodes());
  column_.resize(row_.size());
  for (std::size_t i = 0; i < numOverlap; ++i)
    for (int c = 0; c < dim; ++c) {
      row_[dim * overlap[i] + c] = static_cast<LocalOrdinal>(dim * i + c);
      column_[dim * overlap[i] + c] = dim * nodes.overlapColumn[i] + c;
    }
}

namespace {

// Position of column in a sorted row of the given length, or the length if it is absent. A
// binary search without branches on the comparisons: on unstructured meshes the branches of
// std::lower_bound mispredict at almost every step, and assembly makes one search per pair of
// a cell's nodes.
inline std::size_t positionInRow(const LocalOrdinal* row, std::size_t length, LocalOrdinal column) {
  if (length == 0) return 0;
  const LocalOrdinal* at = row;
  for (std::size_t rest = length; rest > 1;) {
    const std::size_t half = rest / 2;
    at = at[half] <= column ? at + half : at;
    rest -= half;
  }
  return *at == column ? static_cast<std::size_t>(at - row) : length;
}

}  // namespace

// The dim rows of a node share one column pattern, in which a neighbour's dim components are
// adjacent columns: one search per pair of element nodes finds all dim * dim entries of the
// pair, each still checked against its column.
void OverlapStiffness::addElementMatrix(int dim, int npc, const LocalOrdinal* rows, const LocalOrdinal* cols,
                                        const double* Ke) {
  const int n = dim * npc;
  for (int i = 0; i < npc; ++i) {
    const LocalOrdinal* row = rows + dim * i;
    for (int j = 0; j < npc; ++j) {
      const LocalOrdinal* col = cols + dim * j;
      const std::size_t first = offsets_(row[0]);  // an absent entry fails the check below
      const std::size_t offset = positionInRow(columns_.data() + first, offsets_(row[0] + 1) - first, col[0]);
      for (int a = 0; a < dim; ++a) {
        const std::size_t begin = offsets_(row[a]), end = offsets_(row[a] + 1);
        for (int e = 0; e < dim; ++e) {
          std::size_t k = begin + offset + e;
          if (k >= end || columns_(k) != col[e]) k = find(row[a], col[e]);
          values_(k) += Ke[(dim * i + a) * n + dim * j + e];
        }
      }
    }
  }
}

std::size_t OverlapStiffness::find(LocalOrdinal row, LocalOrdinal column) const {
  const std::size_t begin = offsets_(row);
  const std::size_t at = begin + positionInRow(columns_.data() + begin, offsets_(row + 1) - begin, column);
  if (at == offsets_(row + 1)) throw Error("assembly: an element entry lies outside the matrix graph");
  return at;
}

RCP<CrsMatrix> OverlapStiffness::sumOnOwners() {
  using Graph = Tpetra::CrsGraph<LocalOrdinal, GlobalOrdinal, Node>;
  const RCP<const Map>& owned = ownedDofs_;
  const Map& overlap = *overlapDofs_;
  const std::size_t ownedRows = owned->getNodeNumElements(), rows = overlap.getNodeNumElements();
  const std::size_t ownedEntries = offsets_(ownedRows), entries = columns_.extent(0);
  const auto prefix = Kokkos::make_pair(std::size_t(0), ownedEntries), suffix = Kokkos::make_pair(ownedEntries, entries);

  const auto ownedOffsets = Kokkos::subview(offsets_, Kokkos::make_pair(std::size_t(0), ownedRows + 1));
  auto ownedGraph = rcp(new Graph(owned, columnMap_, ownedOffsets, Kokkos::subview(columns_, prefix)));
  ownedGraph->expertStaticFillComplete(owned, owned);
  auto Q = rcp(new CrsMatrix(ownedGraph, Kokkos::subview(values_, prefix)));

  // The ghost rows: a matrix of their own on the same columns and arrays, exported.
  RowOffsets ghostOffsets("ghost row offsets", rows - ownedRows + 1);
  for (std::size_t i = 0; i < rows - ownedRows; ++i) ghostOffsets(i + 1) = offsets_(ownedRows + i + 1) - ownedEntries;
  std::vector<GlobalOrdinal> ghostDofs(rows - ownedRows);
  for (std::size_t i = 0; i < ghostDofs.size(); ++i) ghostDofs[i] = overlap.getGlobalElement(ownedRows + i);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto ghostMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ghostDofs), 0, owned->getComm()));
  auto ghostGraph = rcp(new Graph(ghostMap, columnMap_, ghostOffsets, Kokkos::subview(columns_, suffix)));
  ghostGraph->expertStaticFillComplete(owned, ghostMap, ownedGraph->getImporter());
  CrsMatrix ghosts(ghostGraph, Kokkos::subview(values_, suffix));
  Q->doExport(ghosts, Export(ghostMap, owned), Tpetra::ADD);
  Q->fillComplete(owned, owned);
  return Q;
}

}  // namespace signorini
