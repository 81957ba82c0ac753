// SimplexGrid: the P1 grid of a caller's own simplex mesh. Made from the cells each rank
// assembled, it gives a P_k QP the same P_k -> P1 step as the mesh's own grid
// (MeshVertexGrid, which the problem builder makes from its distributed space), and the same
// Delaunay coarse grids below it as a mesh read as is: the same optimal value in the same
// Krylov iterations.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <Tpetra_Core.hpp>

#include "assembly/MeshVertexGrid.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/SimplexGrid.hpp"
#include "solver/DelaunayCoarseGrid.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// The grid of this rank's cells of the space's mesh, as another code would give it: global
// vertex ids (the vertices' node ids), their coordinates, the cells.
std::shared_ptr<const SimplexGrid> gridOf(const DistributedSpace& ds,
                                          SimplexGrid::CoarseGrids coarseGrids = SimplexGrid::CoarseGrids::delaunay) {
  const SimplexMesh& mesh = ds.mesh();
  std::vector<long long> ids, cells;
  for (long long v = 0; v < mesh.numVertices(); ++v) ids.push_back(ds.globalNode(v));
  for (long long vertex : mesh.cells) cells.push_back(ds.globalNode(vertex));
  return std::make_shared<SimplexGrid>(ds.comm(), ds.dim(), ids, mesh.vertices, cells, SimplexGrid::Outside::error,
                                       coarseGrids);
}

TEST(SimplexGrid, GivesAPkSpaceThePOneStepOfItsMesh) {
  for (const std::string name : {"paper/B", "paper/H"})
    for (int degree : {2, 3}) {
      const std::string label = name + " P" + std::to_string(degree);
      Teuchos::ParameterList problem = signorini::testing::assembledShippedProblem(name);
      problem.set("element: degree", degree);
      AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
      p.multigrid.grid = std::make_shared<MeshVertexGrid>(distributedSpace(p.space));
      const SolveResult own = InteriorPointSolver().solve(p.qp, p.multigrid);
      const auto grid = gridOf(distributedSpace(*p.space), SimplexGrid::CoarseGrids::none);
      EXPECT_EQ(grid->numVertices(), p.multigrid.grid->numVertices()) << label;
      p.multigrid.grid = grid;
      const SolveResult given = InteriorPointSolver().solve(p.qp, p.multigrid);
      ASSERT_TRUE(own.converged() && given.converged()) << label;
      EXPECT_NEAR(given.objective, own.objective, 1e-10 * std::fabs(own.objective)) << label;
      EXPECT_EQ(given.krylovIterations, own.krylovIterations) << label;
    }
}

// Below a grid too large for the direct solver (more than 2500 unknowns), the Delaunay coarse
// grids of a caller's cells are those of the mesh's own grid, whatever the ranks hold.
TEST(SimplexGrid, HasTheDelaunayCoarseGridsOfItsMesh) {
  struct Case {
    int dim, cells, degree;
  };
  for (const Case c : {Case{2, 40, 1}, Case{2, 40, 2}, Case{3, 12, 1}}) {
    const std::string label = std::to_string(c.dim) + "D P" + std::to_string(c.degree);
    Teuchos::ParameterList problem = signorini::testing::contactBoxProblem(c.dim, c.cells);
    problem.set("element: degree", c.degree);
    problem.set(c.dim == 2 ? "body force: y" : "body force: z", "-(1 + 8*(x - 0.5)^2)");  // the family's load
    AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
    const auto space = distributedSpace(p.space);
    auto own = std::make_shared<MeshVertexGrid>(space);
    own->setCoarser(DelaunayCoarseGrid::hierarchyBelow(space->comm(), own->vertexGraph()));
    p.multigrid.grid = own;
    const SolveResult ofMesh = InteriorPointSolver().solve(p.qp, p.multigrid);
    // The caller numbers the vertices as the mesh's grid does, so that the levels are the same
    // matrices, not only the same grids.
    std::vector<long long> ids, cells;
    const SimplexMesh& mesh = space->mesh();
    for (long long v = 0; v < mesh.numVertices(); ++v) ids.push_back(own->vertexAt(&mesh.vertices[c.dim * v]));
    for (long long vertex : mesh.cells) cells.push_back(ids[vertex]);
    const auto given = std::make_shared<SimplexGrid>(space->comm(), c.dim, ids, mesh.vertices, cells);
    ASSERT_NE(given->coarser(), nullptr) << label;
    std::shared_ptr<const GeometricGrid> a = own, b = given;
    for (; a && b; a = a->coarser(), b = b->coarser()) EXPECT_EQ(b->numVertices(), a->numVertices()) << label;
    EXPECT_TRUE(!a && !b) << label << ": as many levels";
    p.multigrid.grid = given;
    const SolveResult caller = InteriorPointSolver().solve(p.qp, p.multigrid);
    ASSERT_TRUE(ofMesh.converged() && caller.converged()) << label << ": " << ofMesh.message << "; " << caller.message;
    EXPECT_NEAR(caller.objective, ofMesh.objective, 1e-10 * std::fabs(ofMesh.objective)) << label;
    EXPECT_EQ(caller.krylovIterations, ofMesh.krylovIterations) << label;
  }
}

TEST(SimplexGrid, LocatesPointsAndVertices) {
  auto comm = Tpetra::getDefaultComm();
  // Two triangles of the unit square, vertices 10, 11, 12, 13 counter-clockwise from (0, 0).
  const SimplexGrid grid(comm, 2, {13, 10, 11, 12}, {0, 1, 0, 0, 1, 0, 1, 1}, {10, 11, 12, 10, 12, 13});
  EXPECT_EQ(grid.numVertices(), 4);
  const double corner[2] = {1, 1}, inside[2] = {0.75, 0.25};
  EXPECT_EQ(grid.vertexAt(corner), 12);
  EXPECT_EQ(grid.vertexAt(inside), -1);
  long long vertices[3];
  double weights[3];
  grid.interpolation(inside, vertices, weights);  // in (10, 11, 12): 1 - x, x - y, y
  EXPECT_EQ(vertices[0], 10);
  EXPECT_NEAR(weights[0], 0.25, 1e-14);
  EXPECT_NEAR(weights[1], 0.5, 1e-14);
  EXPECT_NEAR(weights[2], 0.25, 1e-14);
  const double outside[2] = {2, 2};
  EXPECT_THROW(grid.interpolation(outside, vertices, weights), Error);
}

TEST(SimplexGrid, RefusesInconsistentInput) {
  auto comm = Tpetra::getDefaultComm();
  EXPECT_THROW(SimplexGrid(comm, 2, {0, 1, 2}, {0, 0, 1, 0}, {0, 1, 2}), InputError);       // coordinates
  EXPECT_THROW(SimplexGrid(comm, 2, {0, 1, 2}, {0, 0, 1, 0, 0, 1}, {0, 1, 3}), InputError);  // unknown vertex
  EXPECT_THROW(SimplexGrid(comm, 2, {0, 1, 2}, {0, 0, 1, 0, 2, 0}, {0, 1, 2}), InputError);  // flat cell
  EXPECT_THROW(SimplexGrid(comm, 4, {}, {}, {}), InputError);
}

}  // namespace
