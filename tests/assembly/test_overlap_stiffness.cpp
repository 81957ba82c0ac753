// The overlap stiffness, with an element matrix of ones in every cell: the summed matrix must
// count, for each pair of DOFs, the global cells that hold both nodes. Checked against the
// same sums made without its graph (each rank's cells into an overlap vector, added on the
// owners), with no stored entry left at zero (the graph holds no pair that shares no cell),
// on both ways of making the parts and on any number of ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/OverlapStiffness.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"

namespace {

using namespace signorini;

struct Case {
  int dim, degree;
  bool blocks;  // every rank makes its block of boxes, instead of rank 0 partitioning
};

class OverlapStiffnessTest : public ::testing::TestWithParam<Case> {};

DistributedSpace makeSpace(const Case& k) {
  auto comm = Tpetra::getDefaultComm();
  const BoxGrid box = k.dim == 2 ? BoxGrid(2, {7, 5, 1}, {1.0, 0.7, 1.0}) : BoxGrid(3, {3, 4, 3}, {1.0, 0.8, 0.6});
  if (k.blocks) return DistributedSpace(comm, box, k.degree);
  auto global = comm->getRank() == 0 ? std::make_shared<const SimplexMesh>(makeBoxMesh(box.dim, box.cells, box.lengths))
                                     : nullptr;
  return DistributedSpace(comm, global, k.degree);
}

// The local rows and columns of a cell's DOFs.
void cellDofs(const DistributedSpace& ds, const OverlapStiffness& K, long long cell, std::vector<LocalOrdinal>& rows,
              std::vector<LocalOrdinal>& cols) {
  const int dim = ds.dim(), npc = ds.space().nodesPerCell();
  rows.resize(dim * npc);
  cols.resize(dim * npc);
  for (int i = 0; i < npc; ++i)
    for (int c = 0; c < dim; ++c) {
      const long long dof = dim * ds.space().cellNodes(cell)[i] + c;
      rows[dim * i + c] = K.row(dof);
      cols[dim * i + c] = K.column(dof);
    }
}

TEST_P(OverlapStiffnessTest, CountsTheCellsEachPairOfDofsShares) {
  const DistributedSpace ds = makeSpace(GetParam());
  const int dim = ds.dim(), npc = ds.space().nodesPerCell(), n = dim * npc;
  OverlapStiffness K(ds);
  const std::vector<double> ones(n * n, 1.0);
  std::vector<LocalOrdinal> rows, cols;
  for (long long cell = 0; cell < ds.mesh().numCells(); ++cell) {
    cellDofs(ds, K, cell, rows, cols);
    K.addElementMatrix(dim, npc, rows.data(), cols.data(), ones.data());
  }
  const RCP<CrsMatrix> Q = K.sumOnOwners();
  ASSERT_TRUE(Q->isFillComplete());
  EXPECT_TRUE(Q->getRowMap()->isSameAs(*ds.ownedDofMap()));

  // Every stored entry counts at least one cell.
  const auto local = Q->getLocalMatrixHost();
  std::size_t empty = 0;
  for (std::size_t k = 0; k < local.values.extent(0); ++k) empty += local.values(k) < 1.0;
  EXPECT_EQ(empty, 0u);

  // Q x against the same sums cell by cell: (Q x)_(I,a) = sum over the cells of I of the
  // sum of x over the cell's DOFs.
  Vector x(ds.ownedDofMap()), Qx(ds.ownedDofMap()), expected(ds.ownedDofMap());
  {
    auto data = x.getDataNonConst();
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < data.size(); ++i)
      data[i] = std::sin(0.37 * static_cast<double>(ds.ownedDofMap()->getGlobalElement(i)));
  }
  Q->apply(x, Qx);
  Vector xOverlap(ds.overlapDofMap()), sums(ds.overlapDofMap());
  xOverlap.doImport(x, Import(ds.ownedDofMap(), ds.overlapDofMap()), Tpetra::INSERT);
  {
    auto in = xOverlap.getData();
    auto out = sums.getDataNonConst();
    const Map& overlap = *ds.overlapDofMap();
    const auto entry = [&](long long node, int c) { return overlap.getLocalElement(dim * ds.globalNode(node) + c); };
    for (long long cell = 0; cell < ds.mesh().numCells(); ++cell) {
      const long long* nodes = ds.space().cellNodes(cell);
      double sum = 0;
      for (int j = 0; j < npc; ++j)
        for (int c = 0; c < dim; ++c) sum += in[entry(nodes[j], c)];
      for (int i = 0; i < npc; ++i)
        for (int c = 0; c < dim; ++c) out[entry(nodes[i], c)] += sum;
    }
  }
  expected.doExport(sums, Export(ds.overlapDofMap(), ds.ownedDofMap()), Tpetra::ADD);
  expected.update(-1.0, Qx, 1.0);
  EXPECT_LT(expected.normInf(), 1e-12 * Qx.normInf());
}

TEST_P(OverlapStiffnessTest, RefusesAnEntryOutsideTheGraph) {
  const DistributedSpace ds = makeSpace(GetParam());
  OverlapStiffness K(ds);
  // A node's other components are in its rows; the node of this rank farthest from it,
  // more than a cell's diameter away, is not.
  const int dim = ds.dim();
  const long long first = ds.space().cellNodes(0)[0];
  const double* x = &ds.space().nodeCoordinates()[dim * first];
  long long far = first;
  double farthest = 0;
  for (long long node = 0; node < ds.space().numNodes(); ++node) {
    double distance = 0;
    for (int c = 0; c < dim; ++c) distance += std::pow(ds.space().nodeCoordinates()[dim * node + c] - x[c], 2);
    if (distance > farthest) {
      farthest = distance;
      far = node;
    }
  }
  ASSERT_GT(std::sqrt(farthest), 0.6);  // a box cell is under 0.45 across
  EXPECT_NO_THROW(K.add(K.row(dim * first), K.column(dim * first + 1), 1.0));
  EXPECT_THROW(K.add(K.row(dim * first), K.column(dim * far), 1.0), Error);

  // The same through an element matrix: cell 0 with its last node's columns those of the far node.
  const int npc = ds.space().nodesPerCell();
  std::vector<LocalOrdinal> rows, cols;
  cellDofs(ds, K, 0, rows, cols);
  const std::vector<double> ones(dim * npc * dim * npc, 1.0);
  EXPECT_NO_THROW(K.addElementMatrix(dim, npc, rows.data(), cols.data(), ones.data()));
  for (int c = 0; c < dim; ++c) cols[dim * (npc - 1) + c] = K.column(dim * far + c);
  EXPECT_THROW(K.addElementMatrix(dim, npc, rows.data(), cols.data(), ones.data()), Error);
}

INSTANTIATE_TEST_SUITE_P(Spaces, OverlapStiffnessTest,
                         ::testing::Values(Case{2, 1, true}, Case{2, 2, false}, Case{3, 1, false}, Case{3, 2, true},
                                           Case{2, 3, true}),
                         [](const auto& info) {
                           const Case& k = info.param;
                           return std::to_string(k.dim) + "dP" + std::to_string(k.degree) +
                                  (k.blocks ? "Blocks" : "Partitioned");
                         });

}  // namespace
