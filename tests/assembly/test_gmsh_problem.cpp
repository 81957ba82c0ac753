// A problem on a Gmsh mesh: made in the test by the Gmsh API from a small geometry (a
// 2 x 1 rectangle with physical groups), read back through the Gmsh SDK on rank 0, partitioned,
// assembled with the boundaries found by their physical group names, and solved.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <gmsh.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include <TpetraExt_MatrixMatrix.hpp>
#include <TpetraExt_TripleMatrixMultiply.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"
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

// The rectangle's mesh, written by rank 0 into a directory of its own per rank count.
std::string rectangleMeshDirectory(const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/gmsh-test-np" + std::to_string(comm.getSize());
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    writeRectangleMesh(directory);
  }
  comm.barrier();
  return directory;
}

// The rectangle sagging onto its foundation under its weight, clamped on top.
Teuchos::ParameterList rectangleProblem(int degree) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", "rectangle.msh");  // relative to the base directory
  problem.set("element: degree", degree);
  problem.set("body force: y", "-1");
  auto& clamp = problem.sublist("Dirichlet").sublist("clamp");
  clamp.set("displacement: x", "0");
  clamp.set("displacement: y", "0");
  problem.sublist("Traction").sublist("sides").set("traction: x", "-0.1*(x - 1)");
  problem.sublist("Contact").set("boundary", "foundation");
  return problem;
}

// Only rank 0 reads the file: the other ranks get a base directory where it is not.
AssembledProblem rectangle(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm) {
  const std::string directory = rectangleMeshDirectory(*comm);
  return buildProblem(problem, comm, comm->getRank() == 0 ? directory : directory + "/nowhere");
}

TEST(GmshProblem, BoundariesAreFoundByPhysicalNames) {
  auto comm = Tpetra::getDefaultComm();
  AssembledProblem p = rectangle(rectangleProblem(2), comm);

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

// A P_k space on a Gmsh mesh has its mesh's P1 grid: the P1 stiffness on it is P^T Q P for
// the multigrid's interpolation P, so a matrix-free Q needs no assembled one, and the
// P_k -> P1 step with MueLu below reaches the optimal value of MueLu alone in fewer CG
// iterations.
TEST(GmshProblem, PkSpaceGoesToP1OnItsOwnMesh) {
  auto comm = Tpetra::getDefaultComm();
  for (int degree : {2, 3}) {
    const std::string label = "P" + std::to_string(degree);
    Teuchos::ParameterList problem = rectangleProblem(degree);
    problem.set("stiffness: operator", "assembled");
    const AssembledProblem assembled = rectangle(problem, comm);
    const ContactQP& qp = assembled.qp;
    ASSERT_TRUE(qp.grid != nullptr) << label;

    const CrsMatrix& Q = *qp.Qmatrix();
    const GeometricMultigridPreconditioner multigrid(*qp.grid, Q.getRowMap(), prescribedRows(Q), *qp.coordinates,
                                                     2, 1, 0, Teuchos::ParameterList(), Teuchos::ParameterList(), 3);
    ASSERT_EQ(multigrid.geometricLevels(), 1) << label;
    const RCP<const CrsMatrix> P = multigrid.prolongator(0);
    CrsMatrix PtQP(P->getDomainMap(), 0);
    Tpetra::TripleMatrixMultiply::MultiplyRAP(*P, true, Q, false, *P, false, PtQP);
    const RCP<const CrsMatrix> grid = assembleGridStiffness(*assembled.space, assembled.definition, *qp.grid);
    const Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node> toCoarseRows(grid->getRowMap(), PtQP.getRowMap());
    const RCP<CrsMatrix> gridOnCoarseRows = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(
        grid, toCoarseRows, PtQP.getDomainMap(), PtQP.getRangeMap());
    const RCP<CrsMatrix> difference = Tpetra::MatrixMatrix::add(1.0, false, PtQP, -1.0, false, *gridOnCoarseRows);
    EXPECT_LT(difference->getFrobeniusNorm(), 1e-12 * PtQP.getFrobeniusNorm()) << label;

    problem.set("stiffness: operator", "matrix-free");
    const AssembledProblem matrixFree = rectangle(problem, comm);
    EXPECT_TRUE(matrixFree.qp.Qmatrix().is_null()) << label;
    Teuchos::ParameterList algebraic;
    algebraic.sublist("Preconditioner").set("hierarchy", "algebraic");
    const SolveResult a = InteriorPointSolver(algebraic).solve(qp);
    const SolveResult g = InteriorPointSolver().solve(qp);
    const SolveResult f = InteriorPointSolver().solve(matrixFree.qp);
    ASSERT_TRUE(a.converged() && g.converged() && f.converged()) << label;
    EXPECT_NEAR(g.objective, a.objective, 1e-9 * std::fabs(a.objective)) << label;
    EXPECT_NEAR(f.objective, a.objective, 1e-9 * std::fabs(a.objective)) << label;
    EXPECT_LT(g.krylovIterations, a.krylovIterations) << label;
    EXPECT_LE(f.krylovIterations, 1.5 * g.krylovIterations) << label;
  }
}

// Rank 0 alone reads the file, but every rank learns that it is missing.
TEST(GmshProblem, MissingFileThrowsOnEveryRank) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", "/nonexistent/mesh.msh");
  EXPECT_THROW(buildProblem(problem, Tpetra::getDefaultComm()), InputError);
}

}  // namespace
