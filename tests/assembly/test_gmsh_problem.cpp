// A problem on a Gmsh mesh: made in the test by the Gmsh API from a small geometry (a
// 2 x 1 rectangle with physical groups), read back through the Gmsh SDK on rank 0, partitioned,
// assembled with the boundaries found by their physical group names, and solved.
#include <gtest/gtest.h>

#include <filesystem>

#include <gmsh.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"

namespace {

using namespace signorini;

std::string writeRectangleMesh(const std::string& directory) {
  const std::string path = directory + "/rectangle.msh";
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::model::add("rectangle");
  const double h = 0.1;
  const int p1 = gmsh::model::geo::addPoint(0, 0, 0, h), p2 = gmsh::model::geo::addPoint(2, 0, 0, h),
            p3 = gmsh::model::geo::addPoint(2, 1, 0, h), p4 = gmsh::model::geo::addPoint(0, 1, 0, h);
  const int bottom = gmsh::model::geo::addLine(p1, p2), right = gmsh::model::geo::addLine(p2, p3),
            top = gmsh::model::geo::addLine(p3, p4), left = gmsh::model::geo::addLine(p4, p1);
  const int loop = gmsh::model::geo::addCurveLoop({bottom, right, top, left});
  const int surface = gmsh::model::geo::addPlaneSurface({loop});
  gmsh::model::geo::synchronize();
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {bottom}), "foundation");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {top}), "clamp");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {left, right}), "sides");
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "body");
  gmsh::model::mesh::generate(2);
  gmsh::write(path);
  gmsh::finalize();
  return path;
}

TEST(GmshProblem, BoundariesAreFoundByPhysicalNames) {
  auto comm = Tpetra::getDefaultComm();
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/gmsh-test-np" + std::to_string(comm->getSize());
  if (comm->getRank() == 0) {
    std::filesystem::create_directories(directory);
    writeRectangleMesh(directory);
  }
  comm->barrier();

  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", "rectangle.msh");  // relative to the base directory
  problem.set("element: degree", 2);
  problem.set("body force: y", "-1");
  auto& clamp = problem.sublist("Dirichlet").sublist("clamp");
  clamp.set("displacement: x", "0");
  clamp.set("displacement: y", "0");
  problem.sublist("Traction").sublist("sides").set("traction: x", "-0.1*(x - 1)");
  problem.sublist("Contact").set("boundary", "foundation");
  // Only rank 0 reads the file: the other ranks get a base directory where it is not.
  AssembledProblem p = buildProblem(problem, comm, comm->getRank() == 0 ? directory : directory + "/nowhere");

  const DistributedSpace& ds = *p.space;
  EXPECT_EQ(p.definition.dim, 2);
  EXPECT_EQ(ds.dim(), 2);
  long long ownedContactNodes = 0, contactNodes = 0;
  for (long long node : ds.boundaryNodes(ds.mesh().tag("foundation"))) ownedContactNodes += ds.ownsNode(node);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &ownedContactNodes, &contactNodes);
  EXPECT_GT(contactNodes, 20);  // h = 0.1 on a side of length 2, P2: about 41 nodes
  EXPECT_EQ(static_cast<long long>(p.qp.d->getGlobalLength()), contactNodes);
  EXPECT_EQ(static_cast<long long>(p.qp.b->getGlobalLength()), 2 * ds.numGlobalNodes());

  // Each rank holds its part of the mesh only.
  long long cells = 0;
  const long long localCells = ds.mesh().numCells();
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &localCells, &cells);
  EXPECT_EQ(cells, ds.numGlobalCells());
  EXPECT_GT(localCells, 0);
  if (comm->getSize() > 1) {
    EXPECT_LT(localCells, ds.numGlobalCells());
  }

  // The body sags onto the foundation: it converges, with contact somewhere.
  SolveResult r = InteriorPointSolver().solve(p.qp);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_GT(r.activeConstraints, 0);
  EXPECT_LT(r.objective, 0.0);
}

// Rank 0 alone reads the file, but every rank learns that it is missing.
TEST(GmshProblem, MissingFileThrowsOnEveryRank) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", "/nonexistent/mesh.msh");
  EXPECT_THROW(buildProblem(problem, Tpetra::getDefaultComm()), InputError);
}

}  // namespace
