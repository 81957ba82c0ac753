// The distributed space holds only its rank's part of the mesh, and that part agrees with the
// global mesh: cells, node ids, owners and boundary node sets (checked against a global
// space the test builds on every rank), with every global cell and boundary facet on
// exactly one rank. Both ways of making the parts: partitioned by rank 0, and made by every
// rank for its block of boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Map.hpp>

#include "assembly/DistributedSpace.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"

namespace {

using namespace signorini;

std::vector<long long> sumOverRanks(const Comm& comm, const std::vector<long long>& local) {
  std::vector<long long> global(local.size());
  if (!local.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

long long sumOverRanks(const Comm& comm, long long local) { return sumOverRanks(comm, std::vector<long long>{local})[0]; }

struct Case {
  int dim, degree;
  bool blocks;  // every rank makes its block of boxes, instead of rank 0 partitioning
};

class DistributedSpaceTest : public ::testing::TestWithParam<Case> {};

TEST_P(DistributedSpaceTest, EachRankHoldsOnlyItsPartOfTheGlobalMesh) {
  const Case k = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const BoxGrid box = k.dim == 2 ? BoxGrid(2, {7, 5, 1}, {1.0, 0.7, 1.0}) : BoxGrid(3, {3, 4, 3}, {1.0, 0.8, 0.6});
  const SimplexMesh global = makeBoxMesh(box.dim, box.cells, box.lengths);
  const LagrangeSpace globalSpace(global, k.degree);
  // Only rank 0 passes a mesh: the others have none to give.
  const DistributedSpace ds = k.blocks ? DistributedSpace(comm, box, k.degree)
                                       : DistributedSpace(comm, rank == 0 ? std::make_shared<const SimplexMesh>(global) : nullptr, k.degree);
  const SimplexMesh& mesh = ds.mesh();
  const LagrangeSpace& space = ds.space();
  const int d = k.dim, npc = space.nodesPerCell();

  EXPECT_EQ(ds.numGlobalCells(), global.numCells());
  EXPECT_EQ(ds.numGlobalNodes(), globalSpace.numNodes());
  if (k.blocks)
    EXPECT_EQ(ds.serialPhaseBytes(), 0u);
  else
    EXPECT_GT(ds.serialPhaseBytes(), global.bytes() + globalSpace.bytes());
  EXPECT_EQ(mesh.boundaryTags, global.boundaryTags);

  // Cells: a strict part on several ranks; together every global cell exactly once.
  EXPECT_GT(mesh.numCells(), 0);
  if (size > 1) {
    EXPECT_LT(mesh.numCells(), global.numCells());
    EXPECT_LT(mesh.numVertices(), global.numVertices());
    EXPECT_LT(space.numNodes(), globalSpace.numNodes());
  } else {
    EXPECT_EQ(mesh.numCells(), global.numCells());
  }
  EXPECT_EQ(sumOverRanks(*comm, mesh.numCells()), global.numCells());
  std::vector<long long> cellCount(global.numCells(), 0);
  for (long long c = 0; c < mesh.numCells(); ++c) ++cellCount[ds.globalCell(c)];
  for (long long count : sumOverRanks(*comm, cellCount)) ASSERT_EQ(count, 1);

  // Each local cell is its global cell: same vertex coordinates in the same order, and its
  // nodes sit where the global space's do.
  std::vector<double> x((d + 1) * d), y((d + 1) * d);
  std::vector<long long> idOfGlobalNode(globalSpace.numNodes(), -1);
  for (long long c = 0; c < mesh.numCells(); ++c) {
    const long long g = ds.globalCell(c);
    mesh.cellVertexCoordinates(c, x.data());
    global.cellVertexCoordinates(g, y.data());
    EXPECT_EQ(x, y) << "cell " << g;
    for (int i = 0; i < npc; ++i) {
      const long long node = space.cellNodes(c)[i], globalNode = globalSpace.cellNodes(g)[i];
      for (int j = 0; j < d; ++j)
        EXPECT_EQ(space.nodeCoordinates()[d * node + j], globalSpace.nodeCoordinates()[d * globalNode + j]);
      // One global node, one renumbered id, whichever cell reaches it.
      if (idOfGlobalNode[globalNode] == -1) idOfGlobalNode[globalNode] = ds.globalNode(node);
      EXPECT_EQ(idOfGlobalNode[globalNode], ds.globalNode(node));
    }
  }

  // Every node's id and owner are the same on every rank that has it; the owner has it, and
  // the ids are 0..N-1, each owned once, in contiguous ranges by rank.
  std::vector<long long> ownedTimes(globalSpace.numNodes(), 0), idSum(globalSpace.numNodes(), 0),
      holders(globalSpace.numNodes(), 0);
  for (long long g = 0; g < globalSpace.numNodes(); ++g)
    if (idOfGlobalNode[g] >= 0) {
      ++holders[g];
      idSum[g] = idOfGlobalNode[g];
    }
  for (long long c = 0; c < mesh.numCells(); ++c)
    for (int i = 0; i < npc; ++i) {
      const long long node = space.cellNodes(c)[i], globalNode = globalSpace.cellNodes(ds.globalCell(c))[i];
      if (ds.ownsNode(node) && ownedTimes[globalNode] == 0) ownedTimes[globalNode] = 1;
    }
  ownedTimes = sumOverRanks(*comm, ownedTimes);
  idSum = sumOverRanks(*comm, idSum);
  holders = sumOverRanks(*comm, holders);
  std::vector<long long> ids;
  for (long long g = 0; g < globalSpace.numNodes(); ++g) {
    ASSERT_EQ(ownedTimes[g], 1) << "node " << g;
    ASSERT_GE(holders[g], 1);
    if (idOfGlobalNode[g] >= 0) {
      EXPECT_EQ(idSum[g], holders[g] * idOfGlobalNode[g]) << "node " << g;
    }
    ids.push_back(idSum[g] / holders[g]);
  }
  std::sort(ids.begin(), ids.end());
  for (long long i = 0; i < static_cast<long long>(ids.size()); ++i) ASSERT_EQ(ids[i], i);
  const auto& owned = *ds.ownedNodeMap();
  EXPECT_EQ(static_cast<long long>(owned.getGlobalNumElements()), globalSpace.numNodes());
  for (std::size_t i = 1; i < owned.getNodeNumElements(); ++i)
    EXPECT_EQ(owned.getGlobalElement(i), owned.getGlobalElement(i - 1) + 1);

  // Boundaries: the global node set restricted to this rank's nodes, including nodes that
  // only another rank's facet reaches; each global facet on exactly one rank.
  std::vector<long long> globalOf(space.numNodes());
  for (long long c = 0; c < mesh.numCells(); ++c)
    for (int i = 0; i < npc; ++i) globalOf[space.cellNodes(c)[i]] = globalSpace.cellNodes(ds.globalCell(c))[i];
  for (const auto& [name, tag] : global.boundaryTags) {
    std::vector<long long> expected, got;
    const std::vector<long long> all = globalSpace.boundaryNodes(tag);
    for (long long node = 0; node < space.numNodes(); ++node)
      if (std::binary_search(all.begin(), all.end(), globalOf[node])) expected.push_back(node);
    got = ds.boundaryNodes(tag);
    EXPECT_EQ(got, expected) << name;
    EXPECT_EQ(sumOverRanks(*comm, static_cast<long long>(space.boundaryFacets(tag).size())),
              static_cast<long long>(globalSpace.boundaryFacets(tag).size()))
        << name;
  }
  EXPECT_EQ(sumOverRanks(*comm, mesh.numFacets()), global.numFacets());
}

INSTANTIATE_TEST_SUITE_P(BoxMeshes, DistributedSpaceTest,
                         ::testing::Values(Case{2, 1, false}, Case{2, 2, false}, Case{2, 3, false}, Case{3, 1, false},
                                           Case{3, 2, false}, Case{3, 3, false}, Case{2, 1, true}, Case{2, 2, true},
                                           Case{2, 3, true}, Case{3, 1, true}, Case{3, 2, true}, Case{3, 3, true}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::to_string(info.param.dim) + "D_P" + std::to_string(info.param.degree) +
                                  (info.param.blocks ? "_Blocks" : "_Rank0");
                         });

// With more ranks than the boxes can be cut into blocks for, rank 0 makes and partitions
// the mesh: the same space either way.
TEST(DistributedSpace, BoxWithTooFewBoxesForTheRanksIsPartitionedByRankZero) {
  auto comm = Tpetra::getDefaultComm();
  const BoxGrid box(2, {2, 2, 1}, {1.0, 1.0, 1.0});
  const DistributedSpace ds(comm, box, 2);
  const bool blocks = decomposeBox(2, box.cells, comm->getSize()).numBlocks() == comm->getSize();
  EXPECT_EQ(blocks, comm->getSize() != 3);  // 3 blocks need 3 boxes along an axis
  EXPECT_EQ(ds.serialPhaseBytes() > 0, !blocks);
  EXPECT_EQ(ds.numGlobalNodes(), 25);
  EXPECT_EQ(ds.numGlobalCells(), 8);
  EXPECT_EQ(static_cast<long long>(ds.ownedNodeMap()->getGlobalNumElements()), 25);
}

TEST(DistributedSpace, NoMeshOnRankZeroThrowsOnEveryRank) {
  auto comm = Tpetra::getDefaultComm();
  auto mesh = std::make_shared<const SimplexMesh>(makeBoxMesh(2, {2, 2, 1}, {1.0, 1.0, 1.0}));
  EXPECT_THROW(DistributedSpace(comm, comm->getRank() == 0 ? nullptr : mesh, 1), InputError);
}

TEST(DistributedSpace, BadDegreeThrowsOnEveryRank) {
  auto comm = Tpetra::getDefaultComm();
  auto mesh = std::make_shared<const SimplexMesh>(makeBoxMesh(2, {2, 2, 1}, {1.0, 1.0, 1.0}));
  EXPECT_THROW(DistributedSpace(comm, mesh, 4), InputError);
}

}  // namespace
