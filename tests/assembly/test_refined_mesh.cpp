// A Gmsh mesh refined by every rank on its own part (Problem/mesh: refinements) against the
// same mesh refined by Gmsh itself and read whole, on any rank count, with the refinement
// levels as the geometric multigrid's grids. In 2D both split triangles at their edge
// midpoints: the same discrete problem, so the same optimal value. In 3D both split a
// tetrahedron into eight but may cut its inner octahedron along different diagonals (Gmsh
// keeps Bey's, Signorini takes the shortest): the same nodes and constraints, a nearby
// optimal value; the patch test checks that the refined mesh is conforming.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gmsh.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::gmshPressedProblem;

// A unit square (2D) or cube (3D) with groups "bottom", "top" and "sides", meshed at size h, written
// as coarse.msh and, refined by Gmsh `times` times, as fine<times>.msh, by rank 0.
std::string writeMeshes(const Comm& comm, int dim, double h) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/refined-mesh-test-" + std::to_string(dim) +
                                "d-np" + std::to_string(comm.getSize());
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::model::add("unit");
    const int body = dim == 2 ? gmsh::model::occ::addRectangle(0, 0, 0, 1, 1) : gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair points;
    gmsh::model::getBoundary({{dim, body}}, points, false, false, true);
    gmsh::model::mesh::setSize(points, h);
    const auto [bottom, top] = signorini::testing::unitBoxBottomAndTop(dim, body);
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{dim, body}}, faces, false, false, false);
    std::vector<int> sides;
    for (const auto& [faceDim, tag] : faces)
      if (tag != bottom && tag != top) sides.push_back(tag);
    gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {bottom}), "bottom");
    gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {top}), "top");
    gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, sides), "sides");
    gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, {body}), "body");
    gmsh::model::mesh::generate(dim);
    gmsh::write(directory + "/coarse.msh");
    for (int times = 1; times <= 2; ++times) {
      gmsh::model::mesh::refine();
      gmsh::write(directory + "/fine" + std::to_string(times) + ".msh");
    }
    gmsh::finalize();
  }
  comm.barrier();
  return directory;
}

int gridLevels(const GeometricGrid* grid) {
  int levels = 0;
  for (; grid; grid = grid->coarser().get()) ++levels;
  return levels;
}

class RefinedMesh : public ::testing::TestWithParam<int> {};

TEST_P(RefinedMesh, SolvesTheProblemOfTheMeshGmshRefines) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, dim, dim == 2 ? 0.125 : 0.34);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  double difference[3][3] = {};  // relative, of the optimal values in 3D, per degree and refinements
  for (int degree : {1, 2})
    for (int refinements : {1, 2}) {
      if (dim == 3 && degree == 2 && refinements == 2) continue;  // the largest case adds nothing
      const std::string label = std::to_string(dim) + "D P" + std::to_string(degree) + ", " +
                                std::to_string(refinements) + " refinement(s)";
      const AssembledProblem refined = buildProblem(gmshPressedProblem(dim, "coarse.msh", degree, refinements), comm, base);
      Teuchos::ParameterList asIs = gmshPressedProblem(dim, "fine" + std::to_string(refinements) + ".msh", degree, 0);
      asIs.set("mesh: coarse grids", "none");  // the mesh's own P1 grid, MueLu below
      const AssembledProblem whole = buildProblem(asIs, comm, base);
      EXPECT_EQ(refined.space->numGlobalNodes(), whole.space->numGlobalNodes()) << label;
      EXPECT_EQ(refined.space->numGlobalCells(), whole.space->numGlobalCells()) << label;
      EXPECT_EQ(refined.qp.d->getGlobalLength(), whole.qp.d->getGlobalLength()) << label;
      // Every refinement is a grid, the coarse mesh the coarsest.
      EXPECT_EQ(gridLevels(refined.multigrid.grid.get()), refinements + 1) << label;

      const SolveResult a = InteriorPointSolver().solve(refined.qp, refined.multigrid), b = InteriorPointSolver().solve(whole.qp, whole.multigrid);
      ASSERT_TRUE(a.converged() && b.converged()) << label << ": " << a.message << " / " << b.message;
      if (dim == 2) {
        EXPECT_NEAR(a.objective, b.objective, 1e-9 * std::fabs(b.objective)) << label;
        EXPECT_EQ(a.activeConstraints, b.activeConstraints) << label;
      } else {  // two discretisations of one problem: they converge to one optimal value
        difference[degree][refinements] = std::fabs(a.objective - b.objective) / std::fabs(b.objective);
        EXPECT_LT(difference[degree][refinements], 1e-2) << label;
      }
      EXPECT_GT(a.activeConstraints, 0) << label;
      // The nested grids do at least as well as the mesh's own P1 grid with MueLu below.
      EXPECT_LE(a.krylovIterations, b.krylovIterations) << label;
    }
  if (dim == 3) {
    EXPECT_LT(difference[1][2], 0.8 * difference[1][1]);
  }
}

// The multigrid's interpolation between the levels is the embedding of nested P1 spaces: a
// linear field on a coarser level interpolates to the same linear field on the finer one.
TEST_P(RefinedMesh, InterpolationKeepsLinearFields) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, dim, dim == 2 ? 0.25 : 0.5);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  Teuchos::ParameterList definition = gmshPressedProblem(dim, "coarse.msh", 1, 3);
  definition.sublist("Dirichlet").remove("top");  // no prescribed DOFs: every row interpolates
  const AssembledProblem p = buildProblem(definition, comm, base);
  const CrsMatrix& Q = *assembledStiffness(p.qp, p.multigrid);
  const GeometricMultigridPreconditioner multigrid(*p.multigrid.grid, Q.getRowMap(), std::vector<char>(Q.getNodeNumRows(), 0),
                                                   *p.multigrid.coordinates, dim, 1, 0, Teuchos::ParameterList(),
                                                   Teuchos::ParameterList(), 3);
  ASSERT_EQ(multigrid.geometricLevels(), 3);
  // u(x) = (1 + x + 2y + 3z, ...) with a different slope per component, at the nodes of a
  // level whose DOF map is given: its coordinates come from the grid below.
  const auto linear = [&](const Map& map, const GeometricGrid& grid, bool isFine) {
    Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal, Node> u(rcpFromRef(map));
    auto data = u.getDataNonConst();
    for (std::size_t i = 0; i < u.getLocalLength(); ++i) {
      const GlobalOrdinal dof = map.getGlobalElement(i);
      double x[3] = {0, 0, 0};
      if (isFine) {
        for (int c = 0; c < dim; ++c) x[c] = p.multigrid.coordinates->getData(c)[i / dim];
      } else {
        grid.vertexCoordinates(dof / dim, x);
      }
      const int c = static_cast<int>(dof % dim);
      data[i] = 1 + (c + 1) * x[0] + 2 * x[1] - (c + 2) * x[2];
    }
    return u;
  };
  const GeometricGrid* finer = p.multigrid.grid.get();
  for (int level = 0; level < 3; ++level, finer = finer->coarser().get()) {
    const RCP<const CrsMatrix> P = multigrid.prolongator(level);
    const auto coarse = linear(*P->getDomainMap(), *finer->coarser(), false);
    const auto fine = linear(*P->getRangeMap(), *finer, level == 0);
    Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal, Node> interpolated(P->getRangeMap());
    P->apply(coarse, interpolated);
    interpolated.update(-1.0, fine, 1.0);
    EXPECT_LT(interpolated.normInf(), 1e-12) << "level " << level;
  }
}

// The patch test: with every boundary clamped to an affine displacement and no load, the
// discrete solution is that field at every node (P1 and P2 hold it exactly) only if the
// refined cells fit together, every rank's and across the ranks.
TEST_P(RefinedMesh, PassesThePatchTest) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, dim, dim == 2 ? 0.25 : 0.5);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  const char* field[3] = {"0.01 + 0.02*x - 0.03*y + 0.01*z", "-0.02 + 0.01*x + 0.02*y - 0.02*z",
                          "0.03 - 0.01*x + 0.03*y + 0.02*z"};
  const auto exact = [](int c, const double* x) {
    const double z = x[2];
    return c == 0 ? 0.01 + 0.02 * x[0] - 0.03 * x[1] + 0.01 * z
           : c == 1 ? -0.02 + 0.01 * x[0] + 0.02 * x[1] - 0.02 * z
                    : 0.03 - 0.01 * x[0] + 0.03 * x[1] + 0.02 * z;
  };
  for (int degree : {1, 2}) {
    Teuchos::ParameterList p("Problem");
    p.set("mesh: type", "gmsh");
    p.set("mesh: file", "coarse.msh");
    p.set("mesh: refinements", 2);
    p.set("element: degree", degree);
    for (const char* boundary : {"bottom", "top", "sides"})
      for (int c = 0; c < dim; ++c)
        p.sublist("Dirichlet").sublist(boundary).set(std::string("displacement: ") + "xyz"[c], field[c]);
    const AssembledProblem problem = buildProblem(p, comm, base);
    const SolveResult r = InteriorPointSolver().solve(problem.qp, problem.multigrid);
    ASSERT_TRUE(r.converged()) << r.message;
    auto v = r.v->getData();
    double worst = 0.0;
    for (long i = 0; i < static_cast<long>(v.size()); ++i) {
      double x[3] = {0, 0, 0};
      for (int c = 0; c < dim; ++c) x[c] = problem.multigrid.coordinates->getData(c)[i / dim];
      worst = std::max(worst, std::fabs(v[i] - exact(static_cast<int>(i % dim), x)));
    }
    EXPECT_LT(worst, 1e-7) << "P" << degree;  // the iterative solve's accuracy on a field of size 0.1
  }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RefinedMesh, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

// A coarse mesh too large for the direct solver gets Delaunay coarse grids below it (the
// default Problem/mesh: coarse grids): a grid per refinement, then coarsenings of the coarse
// mesh's vertices, which the multigrid takes as levels of its own. The QP is the same as with
// MueLu below the coarse mesh (coarse grids "none"), so is its solution.
TEST_P(RefinedMesh, LargeCoarseMeshHasDelaunayCoarseGridsBelowIt) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, dim, dim == 2 ? 0.04 : 0.15);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  Teuchos::ParameterList definition = gmshPressedProblem(dim, "coarse.msh", 1, 1);
  const AssembledProblem delaunay = buildProblem(definition, comm, base);
  definition.set("mesh: coarse grids", "none");
  const AssembledProblem none = buildProblem(definition, comm, base);
  const GeometricGrid& coarseMesh = *delaunay.multigrid.grid->coarser();
  ASSERT_GT(coarseMesh.numVertices(), 300);
  ASSERT_NE(coarseMesh.coarser(), nullptr);
  EXPECT_LT(coarseMesh.coarser()->numVertices(), coarseMesh.numVertices() / 2);
  EXPECT_NE(coarseMesh.coarser()->description().find("Delaunay"), std::string::npos);
  EXPECT_EQ(gridLevels(none.multigrid.grid.get()), 2);
  EXPECT_GT(gridLevels(delaunay.multigrid.grid.get()), 2);

  Teuchos::ParameterList solver;  // a direct solve of the coarse mesh would leave nothing below it
  solver.sublist("Preconditioner").set("geometric: direct solve size", 200);
  const CrsMatrix& Q = *assembledStiffness(delaunay.qp, delaunay.multigrid);
  const GeometricMultigridPreconditioner multigrid(*delaunay.multigrid.grid, Q.getRowMap(), prescribedRows(Q),
                                                   *delaunay.multigrid.coordinates, dim, 1, 200, Teuchos::ParameterList(),
                                                   Teuchos::ParameterList(), 3);
  EXPECT_EQ(multigrid.geometricLevels(), 2);  // below the fine grid: the coarse mesh, one Delaunay grid
  const SolveResult a = InteriorPointSolver(solver).solve(delaunay.qp, delaunay.multigrid);
  const SolveResult b = InteriorPointSolver(solver).solve(none.qp, none.multigrid);
  ASSERT_TRUE(a.converged() && b.converged()) << a.message << " / " << b.message;
  EXPECT_NEAR(a.objective, b.objective, 1e-9 * std::fabs(b.objective));
  EXPECT_EQ(a.activeConstraints, b.activeConstraints);
}

// A .geo geometry's curved boundary stays curved: the refinement's new vertices on it are
// placed on the geometry (the Hertz examples' half-disk, a circle of radius 1 about (0, 1),
// and half-ball, a sphere about (0, 0, 1)), where edge midpoints would lie inside it by
// about h^2 / 8.
TEST(RefinedMeshGeometry, NewBoundaryVerticesLieOnTheGeometry) {
  auto comm = Tpetra::getDefaultComm();
  for (const std::string name : {"half-disk-2d", "half-ball-3d"}) {
    Teuchos::ParameterList p("Problem");
    p.set("mesh: type", "gmsh");
    p.set("mesh: file", name + ".geo");
    p.set("mesh: size factor", name == "half-disk-2d" ? 4.0 : 3.0);
    p.set("mesh: refinements", 2);
    const AssembledProblem problem = buildProblem(p, comm, signorini::testing::sourceDir() + "/examples/hertz");
    const DistributedSpace& ds = distributedSpace(*problem.space);
    const int dim = ds.dim();
    double worst = 0.0;
    long long count = 0;
    for (long long node : ds.boundaryNodes(ds.mesh().tag("contact"))) {
      const double* x = &ds.space().nodeCoordinates()[dim * node];
      double squared = 0.0;
      for (int c = 0; c < dim; ++c) squared += (x[c] - (c == dim - 1 ? 1.0 : 0.0)) * (x[c] - (c == dim - 1 ? 1.0 : 0.0));
      worst = std::max(worst, std::fabs(std::sqrt(squared) - 1.0));
      ++count;
    }
    EXPECT_GT(count, 0) << name;
    EXPECT_LT(worst, 1e-9) << name;
  }
}

// More refinements than memory holds are refused before any refinement, with the numbers.
TEST(RefinedMeshInput, TooManyRefinementsAreRefusedBeforeRefining) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, 3, 0.5);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  try {
    buildProblem(gmshPressedProblem(3, "coarse.msh", 1, 9), comm, base);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh: refinements"), std::string::npos) << e.what();
  }
}

}  // namespace
