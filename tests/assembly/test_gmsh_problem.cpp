// A problem on a Gmsh mesh: made in the test by the Gmsh API from a small geometry (a
// 2 x 1 rectangle with physical groups), read back through the Gmsh SDK on rank 0, partitioned,
// assembled with the boundaries found by their physical group names, and solved.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

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

std::string writeRectangleMesh(const std::string& directory, const std::string& name, double h) {
  const std::string path = directory + "/" + name;
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::model::add("rectangle");
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

// The rectangle's mesh (rectangle.msh) and a finer one (rectangle-fine.msh, whose P1 grid has
// Delaunay coarse grids below it), written by rank 0 into a directory of its own per rank count.
std::string rectangleMeshDirectory(const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/gmsh-test-np" + std::to_string(comm.getSize());
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    writeRectangleMesh(directory, "rectangle.msh", 0.1);
    writeRectangleMesh(directory, "rectangle-fine.msh", 0.025);
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

  const DistributedSpace& ds = distributedSpace(*p.space);
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
  SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_GT(r.activeConstraints, 0);
  EXPECT_LT(r.objective, 0.0);
}

// MueLu alone, and the default geometric multigrid on `assembled` (Q a matrix) and on
// `matrixFree` (Q never assembled): all reach the same optimal value, the matrix-free path in
// at most 1.5 times the CG iterations of the assembled one.
struct ThreePaths {
  SolveResult algebraic, geometric, matrixFree;
};
ThreePaths solveThreeWays(const AssembledProblem& assembled, const AssembledProblem& matrixFree,
                          const std::string& label) {
  EXPECT_TRUE(assembledStiffness(matrixFree.qp, matrixFree.multigrid).is_null()) << label;
  Teuchos::ParameterList algebraic;
  algebraic.sublist("Preconditioner").set("hierarchy", "algebraic");
  ThreePaths r{InteriorPointSolver(algebraic).solve(assembled.qp, assembled.multigrid),
               InteriorPointSolver().solve(assembled.qp, assembled.multigrid),
               InteriorPointSolver().solve(matrixFree.qp, matrixFree.multigrid)};
  EXPECT_TRUE(r.algebraic.converged() && r.geometric.converged() && r.matrixFree.converged()) << label;
  const double reference = r.algebraic.objective;
  EXPECT_NEAR(r.geometric.objective, reference, 1e-9 * std::fabs(reference)) << label;
  EXPECT_NEAR(r.matrixFree.objective, reference, 1e-9 * std::fabs(reference)) << label;
  EXPECT_LE(r.matrixFree.krylovIterations, 1.5 * r.geometric.krylovIterations) << label;
  return r;
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
    problem.set("mesh: coarse grids", "none");
    const AssembledProblem assembled = rectangle(problem, comm);
    const ContactQP& qp = assembled.qp;
    const MultigridInput& mg = assembled.multigrid;
    ASSERT_TRUE(mg.grid != nullptr) << label;
    ASSERT_TRUE(mg.grid->coarser() == nullptr) << label;

    const CrsMatrix& Q = *assembledStiffness(qp, mg);
    const GeometricMultigridPreconditioner multigrid(*mg.grid, Q.getRowMap(), prescribedRows(Q), *mg.coordinates,
                                                     2, 1, 0, Teuchos::ParameterList(), Teuchos::ParameterList(), 3);
    ASSERT_EQ(multigrid.geometricLevels(), 1) << label;
    const RCP<const CrsMatrix> P = multigrid.prolongator(0);
    CrsMatrix PtQP(P->getDomainMap(), 0);
    Tpetra::TripleMatrixMultiply::MultiplyRAP(*P, true, Q, false, *P, false, PtQP);
    const RCP<const CrsMatrix> grid = assembleGridStiffness(distributedSpace(*assembled.space), assembled.definition, *mg.grid);
    const Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node> toCoarseRows(grid->getRowMap(), PtQP.getRowMap());
    const RCP<CrsMatrix> gridOnCoarseRows = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(
        grid, toCoarseRows, PtQP.getDomainMap(), PtQP.getRangeMap());
    const RCP<CrsMatrix> difference = Tpetra::MatrixMatrix::add(1.0, false, PtQP, -1.0, false, *gridOnCoarseRows);
    EXPECT_LT(difference->getFrobeniusNorm(), 1e-12 * PtQP.getFrobeniusNorm()) << label;

    problem.set("stiffness: operator", "matrix-free");
    const ThreePaths solves = solveThreeWays(assembled, rectangle(problem, comm), label);
    EXPECT_LT(solves.geometric.krylovIterations, solves.algebraic.krylovIterations) << label;
  }
}

// A mesh read as is has Delaunay coarse grids below its P1 grid (P1: the space's own): the
// geometric multigrid then reaches MueLu's optimal value in fewer CG iterations than with MueLu
// below the P1 grid, on any rank count.
TEST(GmshProblem, UnrefinedMeshHasDelaunayCoarseGridsBelowItsP1Grid) {
  auto comm = Tpetra::getDefaultComm();
  for (int degree : {1, 2}) {
    const std::string label = "P" + std::to_string(degree);
    Teuchos::ParameterList problem = rectangleProblem(degree);
    problem.set("mesh: file", "rectangle-fine.msh");
    problem.set("stiffness: operator", "assembled");
    const AssembledProblem assembled = rectangle(problem, comm);
    const MultigridInput& mg = assembled.multigrid;
    ASSERT_TRUE(mg.grid != nullptr && mg.grid->coarser() != nullptr) << label;
    const CrsMatrix& Q = *assembledStiffness(assembled.qp, mg);
    const GeometricMultigridPreconditioner multigrid(*mg.grid, Q.getRowMap(), prescribedRows(Q), *mg.coordinates,
                                                     2, 1, 0, Teuchos::ParameterList(), Teuchos::ParameterList(), 3);
    EXPECT_GE(multigrid.geometricLevels(), degree == 1 ? 2 : 3) << label;

    Teuchos::ParameterList algebraic;
    algebraic.sublist("Preconditioner").set("hierarchy", "algebraic");
    const SolveResult reference = InteriorPointSolver(algebraic).solve(assembled.qp, mg);
    const SolveResult geometric = InteriorPointSolver().solve(assembled.qp, mg);
    problem.set("mesh: coarse grids", "none");
    const AssembledProblem withMueLuBelow = rectangle(problem, comm);
    const SolveResult mueluBelow = InteriorPointSolver().solve(withMueLuBelow.qp, withMueLuBelow.multigrid);
    ASSERT_TRUE(reference.converged() && geometric.converged() && mueluBelow.converged()) << label;
    EXPECT_NEAR(geometric.objective, reference.objective, 1e-9 * std::fabs(reference.objective)) << label;
    EXPECT_LT(geometric.krylovIterations, mueluBelow.krylovIterations) << label;
  }
}

// u^T K u for K on its own row map and u(x) given per node, from the space's coordinates:
// K's DOFs are dim * (global node) + component.
double energy(const CrsMatrix& K, const DistributedSpace& ds, const std::function<void(const double*, double*)>& u) {
  const int dim = ds.dim();
  Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal, Node> v(K.getDomainMap()), Kv(K.getRangeMap());
  auto data = v.getDataNonConst();
  for (std::size_t i = 0; i < v.getLocalLength(); ++i) {
    const GlobalOrdinal dof = K.getDomainMap()->getGlobalElement(i);
    const long long node = ds.overlapSpaceNodes()[ds.overlapNodeMap()->getLocalElement(dof / dim)];
    double value[3];
    u(&ds.space().nodeCoordinates()[dim * node], value);
    data[i] = value[dof % dim];
  }
  data = Teuchos::null;
  K.apply(v, Kv);
  return v.dot(Kv);
}

// Refined at the nodes, the grid is the P1 space of the mesh split at its nodes: its
// stiffness is not Q's, but gives linear fields Q's energy (both integrate them exactly) and
// rigid motions none; the multigrid on it reaches the same optimal value.
TEST(GmshProblem, RefinedAtNodesTheGridIsTheRefinedMeshsP1Space) {
  auto comm = Tpetra::getDefaultComm();
  for (int degree : {2, 3}) {
    const std::string label = "P" + std::to_string(degree);
    Teuchos::ParameterList problem = rectangleProblem(degree);
    problem.set("stiffness: operator", "assembled");
    problem.set("stiffness: P1 grid", "refined at nodes");
    const AssembledProblem refined = rectangle(problem, comm);
    const MultigridInput& mg = refined.multigrid;
    ASSERT_TRUE(mg.grid != nullptr && mg.grid->refinesFineCells()) << label;
    EXPECT_EQ(mg.grid->numVertices(), refined.space->numGlobalNodes()) << label;
    ASSERT_FALSE(mg.gridStiffness.is_null()) << label;

    ProblemDefinition free = refined.definition;  // no Dirichlet rows: the energies of whole fields
    free.dirichlet.clear();
    const RCP<const CrsMatrix> K = assembleGridStiffness(distributedSpace(*refined.space), free, *mg.grid);
    const RCP<const CrsMatrix> Q =
        Teuchos::rcp_dynamic_cast<const CrsMatrix>(assembleContactQP(distributedSpace(*refined.space), free).Q);
    const auto linear = [](const double* x, double* u) {
      u[0] = 0.3 + 1.1 * x[0] - 0.4 * x[1];
      u[1] = -0.2 + 0.7 * x[0] + 0.9 * x[1];
    };
    const auto rotation = [](const double* x, double* u) {
      u[0] = 0.5 - x[1];
      u[1] = -0.25 + x[0];
    };
    const double exact = energy(*Q, distributedSpace(*refined.space), linear);
    EXPECT_GT(exact, 0.0) << label;
    EXPECT_NEAR(energy(*K, distributedSpace(*refined.space), linear), exact, 1e-12 * exact) << label;
    EXPECT_NEAR(energy(*K, distributedSpace(*refined.space), rotation), 0.0, 1e-12 * exact) << label;
    EXPECT_LT(K->getGlobalNumEntries(), Q->getGlobalNumEntries()) << label;  // P1 couplings only
    // Every node is a vertex of some piece: a row of its own with a positive diagonal.
    ASSERT_EQ(K->getGlobalNumRows(), 2 * static_cast<Tpetra::global_size_t>(refined.space->numGlobalNodes())) << label;
    Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal, Node> diagonal(K->getRowMap());
    K->getLocalDiagCopy(diagonal);
    double smallest = 1.0;
    for (double d : diagonal.getData()) smallest = std::min(smallest, d);
    double globalSmallest = 0.0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &smallest, &globalSmallest);
    EXPECT_GT(globalSmallest, 0.0) << label;

    problem.set("stiffness: operator", "matrix-free");
    solveThreeWays(refined, rectangle(problem, comm), label);
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
