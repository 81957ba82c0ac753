// A Gmsh mesh refined by every rank on its own part (Problem/mesh: refinements) against the
// same mesh refined by Gmsh itself (RefineMesh: triangles at their edge midpoints, tetrahedra
// into eight) and read whole: the same discrete problem, so the same optimal value, on any
// rank count, with the refinement levels as the geometric multigrid's grids.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gmsh.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"

namespace {

using namespace signorini;

// A unit square (2D) or cube (3D) with groups "bottom" and "top", meshed at size h, written
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
    // The bounding faces y = 0 / y = 1 (2D) or z = 0 / z = 1 (3D).
    int bottom = -1, top = -1;
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{dim, body}}, faces, false, false, false);
    for (const auto& [faceDim, tag] : faces) {
      double x0, y0, z0, x1, y1, z1;
      gmsh::model::getBoundingBox(faceDim, tag, x0, y0, z0, x1, y1, z1);
      const double low = dim == 2 ? y1 : z1, high = dim == 2 ? y0 : z0;
      if (std::fabs(low) < 1e-6) bottom = tag;
      if (std::fabs(high - 1) < 1e-6) top = tag;
    }
    gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {bottom}), "bottom");
    gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {top}), "top");
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

// The body clamped on top, pressed onto the rigid plane under it by a varying weight.
Teuchos::ParameterList problem(int dim, const std::string& file, int refinements, int degree) {
  Teuchos::ParameterList p("Problem");
  p.set("mesh: type", "gmsh");
  p.set("mesh: file", file);
  p.set("mesh: refinements", refinements);
  p.set("element: degree", degree);
  p.set(dim == 2 ? "body force: y" : "body force: z", "-(1 + 8*(x - 0.5)^2)");
  auto& top = p.sublist("Dirichlet").sublist("top");
  for (const char* axis : {"x", "y", "z"})
    if (dim == 3 || std::string(axis) != "z") top.set(std::string("displacement: ") + axis, "0");
  p.sublist("Contact").set("boundary", "bottom");
  return p;
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
  for (int degree : {1, 2})
    for (int refinements : {1, 2}) {
      if (dim == 3 && degree == 2 && refinements == 2) continue;  // the largest case adds nothing
      const std::string label = std::to_string(dim) + "D P" + std::to_string(degree) + ", " +
                                std::to_string(refinements) + " refinement(s)";
      const AssembledProblem refined = buildProblem(problem(dim, "coarse.msh", refinements, degree), comm, base);
      const AssembledProblem whole =
          buildProblem(problem(dim, "fine" + std::to_string(refinements) + ".msh", 0, degree), comm, base);
      EXPECT_EQ(refined.space->numGlobalNodes(), whole.space->numGlobalNodes()) << label;
      EXPECT_EQ(refined.space->numGlobalCells(), whole.space->numGlobalCells()) << label;
      EXPECT_EQ(refined.qp.d->getGlobalLength(), whole.qp.d->getGlobalLength()) << label;
      // Every refinement is a grid, the coarse mesh the coarsest.
      EXPECT_EQ(gridLevels(refined.qp.grid.get()), refinements + 1) << label;

      const SolveResult a = InteriorPointSolver().solve(refined.qp), b = InteriorPointSolver().solve(whole.qp);
      ASSERT_TRUE(a.converged() && b.converged()) << label << ": " << a.message << " / " << b.message;
      EXPECT_NEAR(a.objective, b.objective, 1e-9 * std::fabs(b.objective)) << label;
      EXPECT_EQ(a.activeConstraints, b.activeConstraints) << label;
      EXPECT_GT(a.activeConstraints, 0) << label;
      // The nested grids do at least as well as the mesh's own P1 grid with MueLu below.
      EXPECT_LE(a.krylovIterations, b.krylovIterations) << label;
    }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RefinedMesh, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

// More refinements than memory holds are refused before any refinement, with the numbers.
TEST(RefinedMeshInput, TooManyRefinementsAreRefusedBeforeRefining) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, 3, 0.5);
  const std::string base = comm->getRank() == 0 ? directory : directory + "/nowhere";
  try {
    buildProblem(problem(3, "coarse.msh", 9, 1), comm, base);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh: refinements"), std::string::npos) << e.what();
  }
}

}  // namespace
