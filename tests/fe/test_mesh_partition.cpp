#include "fe/MeshPartition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

void expectValidPartition(const std::vector<int>& part, long long numCells, int numParts) {
  ASSERT_EQ(static_cast<long long>(part.size()), numCells);
  std::vector<long long> size(numParts, 0);
  for (int p : part) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, numParts);
    ++size[p];
  }
  for (int p = 0; p < numParts; ++p) EXPECT_GT(size[p], 0) << "part " << p << " is empty";
}

TEST(MeshPartition, SquareIntoThreeParts) {
  const SimplexMesh mesh = makeBoxMesh(2, {20, 20, 0}, {1, 1, 0});
  const std::vector<int> part = partitionCells(mesh, 3);
  expectValidPartition(part, mesh.numCells(), 3);
  EXPECT_EQ(partitionCells(mesh, 3), part) << "not deterministic";
}

TEST(MeshPartition, CubeIntoFourParts) {
  const SimplexMesh mesh = makeBoxMesh(3, {6, 6, 6}, {1, 1, 1});
  expectValidPartition(partitionCells(mesh, 4), mesh.numCells(), 4);
}

TEST(MeshPartition, OnePartAndBadCount) {
  const SimplexMesh mesh = makeBoxMesh(2, {4, 4, 0}, {1, 1, 0});
  EXPECT_EQ(partitionCells(mesh, 1), std::vector<int>(mesh.numCells(), 0));
  EXPECT_THROW(partitionCells(mesh, 0), InputError);
}

TEST(MeshPartition, NodeOwnersAreSmallestPartOfContainingCells) {
  const SimplexMesh mesh = makeBoxMesh(2, {20, 20, 0}, {1, 1, 0});
  const std::vector<int> part = partitionCells(mesh, 3);
  for (int k = 1; k <= 3; ++k) {
    const LagrangeSpace space(mesh, k);
    const std::vector<int> owner = nodeOwners(space, part);
    ASSERT_EQ(static_cast<long long>(owner.size()), space.numNodes());
    std::vector<std::vector<int>> partsOfNode(space.numNodes());
    for (long long cell = 0; cell < mesh.numCells(); ++cell)
      for (int local = 0; local < space.nodesPerCell(); ++local) partsOfNode[space.cellNodes(cell)[local]].push_back(part[cell]);
    std::vector<long long> owned(3, 0);
    for (long long node = 0; node < space.numNodes(); ++node) {
      ASSERT_FALSE(partsOfNode[node].empty());
      EXPECT_EQ(owner[node], *std::min_element(partsOfNode[node].begin(), partsOfNode[node].end()));
      ++owned[owner[node]];
    }
    for (int p = 0; p < 3; ++p) EXPECT_GT(owned[p], 0);
  }
  EXPECT_THROW(nodeOwners(LagrangeSpace(mesh, 1), std::vector<int>(3, 0)), InputError);
}

}  // namespace
}  // namespace signorini
