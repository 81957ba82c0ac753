// The P1 grid of a P_k space's own mesh, on a general (METIS-partitioned) mesh whose
// vertices were moved off any box grid: every vertex numbered once, every node of a rank's
// part located in a cell of it with weights that reproduce linear functions. Refined at the
// nodes, every node is a vertex with its own global id.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/MeshVertexGrid.hpp"
#include "signorini/core/Error.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

std::shared_ptr<const SimplexMesh> distortedMesh(int dim) {
  return std::make_shared<const SimplexMesh>(signorini::testing::distortedBoxMesh(dim, dim == 2 ? 6 : 3));
}

struct Case {
  int dim, degree;
};

std::shared_ptr<const DistributedSpace> space(const Case& k) {
  auto comm = Tpetra::getDefaultComm();
  auto mesh = distortedMesh(k.dim);
  return std::make_shared<const DistributedSpace>(comm, comm->getRank() == 0 ? mesh : nullptr, k.degree);
}

std::string name(const Case& k) { return std::to_string(k.dim) + "D P" + std::to_string(k.degree); }

TEST(MeshVertexGrid, NumbersEveryVertexOnce) {
  for (const Case k : {Case{2, 2}, Case{3, 3}}) {
    const auto ds = space(k);
    const MeshVertexGrid grid(ds);
    const long long globalVertices = distortedMesh(k.dim)->numVertices();
    EXPECT_EQ(grid.numVertices(), globalVertices) << name(k);
    // The owned vertices' ids, over all ranks, are 0 .. numVertices - 1 once each.
    std::vector<long long> seen(globalVertices, 0), counts(globalVertices, 0);
    const int dim = k.dim;
    for (long long v = 0; v < ds->mesh().numVertices(); ++v) {
      const double* x = &ds->space().nodeCoordinates()[dim * v];
      const long long id = grid.vertexAt(x);
      ASSERT_GE(id, 0) << name(k);
      ASSERT_LT(id, globalVertices) << name(k);
      double back[3];
      grid.vertexCoordinates(id, back);
      for (int c = 0; c < dim; ++c) EXPECT_EQ(back[c], x[c]) << name(k);
      if (ds->ownsNode(v)) ++seen[id];
    }
    Teuchos::reduceAll(*ds->comm(), Teuchos::REDUCE_SUM, static_cast<int>(globalVertices), seen.data(), counts.data());
    for (long long id = 0; id < globalVertices; ++id) EXPECT_EQ(counts[id], 1) << name(k) << ": vertex " << id;
    // Nodes that are not vertices, and points that are no node, have no vertex.
    for (long long node = ds->mesh().numVertices(); node < ds->space().numNodes(); ++node)
      EXPECT_EQ(grid.vertexAt(&ds->space().nodeCoordinates()[dim * node]), -1) << name(k);
    const double nowhere[3] = {0.123456, 0.654321, 0.5};
    EXPECT_EQ(grid.vertexAt(nowhere), -1) << name(k);
    double unused[3];
    EXPECT_THROW(grid.vertexCoordinates(globalVertices, unused), Error) << name(k);
  }
}

TEST(MeshVertexGrid, WeightsReproduceLinearFunctionsAtEveryNode) {
  for (const Case k : {Case{2, 2}, Case{2, 3}, Case{3, 2}, Case{3, 3}}) {
    const auto ds = space(k);
    const MeshVertexGrid grid(ds);
    const int dim = k.dim;
    for (long long node = 0; node < ds->space().numNodes(); ++node) {
      const double* x = &ds->space().nodeCoordinates()[dim * node];
      long long vertices[4];
      double weights[4], sum = 0, at[3] = {0, 0, 0};
      grid.interpolation(x, vertices, weights);
      for (int v = 0; v <= dim; ++v) {
        EXPECT_GE(weights[v], 0.0) << name(k);
        sum += weights[v];
        double y[3];
        grid.vertexCoordinates(vertices[v], y);
        for (int c = 0; c < dim; ++c) at[c] += weights[v] * y[c];
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << name(k);
      for (int c = 0; c < dim; ++c) EXPECT_NEAR(at[c], x[c], 1e-13) << name(k) << ", node " << node;
    }
    const double nowhere[3] = {0.123456, 0.654321, 0.5};
    long long vertices[4];
    double weights[4];
    EXPECT_THROW(grid.interpolation(nowhere, vertices, weights), Error) << name(k);
  }
}

TEST(MeshVertexGrid, RefinedAtNodesEveryNodeIsItsOwnVertex) {
  for (const Case k : {Case{2, 2}, Case{3, 3}}) {
    const auto ds = space(k);
    const MeshVertexGrid grid(ds, MeshVertexGrid::Refinement::atNodes);
    const int dim = k.dim;
    EXPECT_TRUE(grid.refinesFineCells()) << name(k);
    EXPECT_FALSE(MeshVertexGrid(ds).refinesFineCells()) << name(k);
    EXPECT_EQ(grid.numVertices(), ds->numGlobalNodes()) << name(k);
    for (long long node = 0; node < ds->space().numNodes(); ++node) {
      const double* x = &ds->space().nodeCoordinates()[dim * node];
      ASSERT_EQ(grid.vertexAt(x), ds->globalNode(node)) << name(k);
      double back[3];
      grid.vertexCoordinates(ds->globalNode(node), back);
      for (int c = 0; c < dim; ++c) EXPECT_EQ(back[c], x[c]) << name(k);
      long long vertices[4];
      double weights[4], sum = 0;
      grid.interpolation(x, vertices, weights);
      for (int v = 0; v <= dim; ++v) {
        EXPECT_EQ(vertices[v], ds->globalNode(node)) << name(k);
        sum += weights[v];
      }
      EXPECT_EQ(weights[0], 1.0) << name(k);
      EXPECT_EQ(sum, 1.0) << name(k);
    }
    const double nowhere[3] = {0.123456, 0.654321, 0.5};
    EXPECT_EQ(grid.vertexAt(nowhere), -1) << name(k);
  }
}

}  // namespace
