// A whole .msh file read by all ranks together (Problem/mesh: read = "all ranks") against the
// same file read by rank 0: the same discrete problem (unknowns, constraints, load, optimal
// value) on any rank count, P1 and P2, as is and refined; the parts cover the mesh once; a file
// outside the parallel reader's format is read by rank 0; a bad mesh is one InputError on
// every rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmsh.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/ParallelMshRead.hpp"
#include "core/Collectives.hpp"
#include "fe/GmshMesh.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::gmshPressedProblem;

std::string testDirectory(const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  return std::string(binary ? binary : "/tmp") + "/parallel-msh-test-np" + std::to_string(comm.getSize());
}

// A unit square (2D) or cube (3D) with groups "bottom" (y or z = 0), "top" and "body", meshed
// at size h by rank 0 and written as unit<dim>d.msh in the format `version` (4.1 or 2.2).
std::string writeMesh(const Comm& comm, int dim, double h, double version = 4.1) {
  const std::string directory = testDirectory(comm);
  const std::string name = "unit" + std::to_string(dim) + "d-v" + std::to_string(static_cast<int>(10 * version)) + ".msh";
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    signorini::testing::meshUnitBox(dim, h);
    gmsh::write(directory + "/" + name);
    gmsh::finalize();
  }
  comm.barrier();
  return name;
}

double optimalValue(const AssembledProblem& p) {
  const SolveResult r = InteriorPointSolver(Teuchos::ParameterList()).solve(p.qp, p.multigrid);
  EXPECT_TRUE(r.converged()) << r.message;
  return r.objective;
}

Teuchos::ParameterList readByAllRanks(Teuchos::ParameterList problem) {
  problem.set("mesh: read", "all ranks");
  return problem;
}

Teuchos::ParameterList readByRank0(Teuchos::ParameterList problem) {
  problem.set("mesh: read", "rank 0");
  return problem;
}

class ParallelMshRead : public ::testing::TestWithParam<int> {};

TEST_P(ParallelMshRead, GivesTheProblemOfTheFileReadByRank0) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string file = writeMesh(*comm, dim, dim == 2 ? 0.1 : 0.3);
  struct Case {
    int degree, refinements;
  };
  for (const Case c : {Case{1, 0}, Case{2, 0}, Case{1, 1}}) {
    const std::string label = std::to_string(dim) + "D P" + std::to_string(c.degree) + ", " +
                              std::to_string(c.refinements) + " refinement(s)";
    const Teuchos::ParameterList problem = gmshPressedProblem(dim, file, c.degree, c.refinements);
    const AssembledProblem all = buildProblem(readByAllRanks(problem), comm, testDirectory(*comm));
    const AssembledProblem root = buildProblem(readByRank0(problem), comm, testDirectory(*comm));
    EXPECT_EQ(all.space->numGlobalNodes(), root.space->numGlobalNodes()) << label;
    EXPECT_EQ(all.space->numGlobalCells(), root.space->numGlobalCells()) << label;
    EXPECT_EQ(all.qp.d->getGlobalLength(), root.qp.d->getGlobalLength()) << label;
    EXPECT_NEAR(all.qp.b->norm2(), root.qp.b->norm2(), 1e-12 * root.qp.b->norm2()) << label;
    const double a = optimalValue(all), b = optimalValue(root);
    EXPECT_NEAR(a, b, 1e-9 * std::fabs(b)) << label;
  }
}

TEST_P(ParallelMshRead, PartsHoldEveryCellAndFacetOnce) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const std::string path = testDirectory(*comm) + "/" + writeMesh(*comm, dim, dim == 2 ? 0.1 : 0.3);
  long long cells = 0, facets = 0;
  if (comm->getRank() == 0) {
    const SimplexMesh whole = readGmshMesh(path);
    cells = whole.numCells();
    facets = whole.numFacets();
  }
  std::string unsupported;
  const GmshMeshPart part = detail::readMshInParallel(comm, path, unsupported);
  ASSERT_EQ(unsupported, "");
  EXPECT_EQ(part.part, comm->getRank());
  EXPECT_GT(part.mesh.numCells(), 0);
  EXPECT_EQ(sumOverRanks(*comm, part.mesh.numCells()), sumOverRanks(*comm, cells));
  EXPECT_EQ(sumOverRanks(*comm, part.mesh.numFacets()), sumOverRanks(*comm, facets));
  ASSERT_EQ(part.sharerStart.size(), part.vertexTags.size() + 1);
  for (std::size_t v = 0; v < part.vertexTags.size(); ++v) {
    const int* first = part.sharers.data() + part.sharerStart[v];
    const int* last = part.sharers.data() + part.sharerStart[v + 1];
    EXPECT_TRUE(std::is_sorted(first, last));
    EXPECT_NE(std::find(first, last, comm->getRank()), last) << "vertex " << part.vertexTags[v];
  }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, ParallelMshRead, ::testing::Values(2, 3));

TEST(ParallelMshReadInput, AFileOutsideTheFormatIsReadByRank0) {
  auto comm = Tpetra::getDefaultComm();
  const std::string file = writeMesh(*comm, 2, 0.2, 2.2);
  std::string unsupported;
  const GmshMeshPart part = detail::readMshInParallel(comm, testDirectory(*comm) + "/" + file, unsupported);
  EXPECT_NE(unsupported.find("MSH 4.1 ASCII"), std::string::npos) << unsupported;
  EXPECT_EQ(part.part, -1);
  const Teuchos::ParameterList problem = gmshPressedProblem(2, file, 1, 0);
  const AssembledProblem all = buildProblem(readByAllRanks(problem), comm, testDirectory(*comm));
  const AssembledProblem root = buildProblem(readByRank0(problem), comm, testDirectory(*comm));
  EXPECT_EQ(all.space->numGlobalNodes(), root.space->numGlobalNodes());
}

// A file that only rank 0 can open (the other ranks are given a path that does not exist, as
// if the file were on a disk of rank 0's own) is read by rank 0.
TEST(ParallelMshReadInput, AFileThatNotEveryRankCanOpenIsReadByRank0) {
  auto comm = Tpetra::getDefaultComm();
  const std::string file = writeMesh(*comm, 2, 0.2);
  const std::string directory = testDirectory(*comm) + (comm->getRank() == 0 ? "" : "/nowhere");
  std::string unsupported;
  const GmshMeshPart part = detail::readMshInParallel(comm, directory + "/" + file, unsupported);
  if (comm->getSize() == 1) {  // one rank: it can open the file
    EXPECT_EQ(unsupported, "");
    return;
  }
  EXPECT_EQ(unsupported, "not every rank can open it");
  EXPECT_EQ(part.part, -1);
  BuildRecorder built;  // told why, for the run log
  const AssembledProblem read = buildProblem(readByAllRanks(gmshPressedProblem(2, file, 1, 0)), comm, directory,
                                             StiffnessNeed::AsConfigured, &built);
  EXPECT_GT(read.space->numGlobalNodes(), 0);
  ASSERT_EQ(built.notes.size(), 1u);
  EXPECT_NE(built.notes[0].find("read whole by rank 0, not by all ranks: not every rank can open it"),
            std::string::npos) << built.notes[0];
  BuildRecorder everyRank;  // a file that every rank opens: read as asked, nothing to say
  buildProblem(readByAllRanks(gmshPressedProblem(2, file, 1, 0)), comm, testDirectory(*comm),
               StiffnessNeed::AsConfigured, &everyRank);
  EXPECT_TRUE(everyRank.notes.empty());
}

// The unit square cut into four triangles around its centre (node 5), with the groups "bottom"
// (edge 1-2) and "inner" (edge 1-5, between two cells). Along the Morton curve the cells come
// bottom, left, right, top: on two ranks the cells sharing edge 1-5 are in one slice and the
// facet in the other, so that no directory sees that edge.
TEST(ParallelMshReadInput, AFacetInsideTheMeshIsFoundWhereverItsCellsAre) {
  auto comm = Tpetra::getDefaultComm();
  const std::string path = testDirectory(*comm) + "/inner.msh";
  if (comm->getRank() == 0) {
    std::filesystem::create_directories(testDirectory(*comm));
    std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 1 \"bottom\"\n1 2 \"inner\"\n"
                           "$EndPhysicalNames\n$Entities\n0 2 1 0\n1 0 0 0 1 0 0 1 1 0\n2 0 0 0 1 1 0 1 2 0\n"
                           "1 0 0 0 1 1 0 0 0\n$EndEntities\n$Nodes\n1 5 1 5\n2 1 0 5\n1\n2\n3\n4\n5\n"
                           "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n$EndNodes\n$Elements\n3 6 1 6\n1 1 1 1\n1 1 2\n"
                           "1 2 1 1\n2 1 5\n2 1 2 4\n3 1 2 5\n4 2 3 5\n5 3 4 5\n6 4 1 5\n$EndElements\n";
  }
  comm->barrier();
  std::string unsupported;
  const GmshMeshPart part = detail::readMshInParallel(comm, path, unsupported);
  ASSERT_EQ(unsupported, "");
  EXPECT_EQ(sumOverRanks(*comm, part.mesh.numCells()), 4);
  EXPECT_EQ(sumOverRanks(*comm, part.mesh.numFacets()), 2);
  EXPECT_EQ(sumOverRanks(*comm, static_cast<long long>(std::count(part.mesh.facetTags.begin(),
                                                                  part.mesh.facetTags.end(), 2))), 1);
}

// Two triangles of the unit square and a boundary "edge" 2-4 across it: no edge of a cell.
TEST(ParallelMshReadInput, ABoundaryFacetThatIsNoFaceIsOneInputErrorOnEveryRank) {
  auto comm = Tpetra::getDefaultComm();
  const std::string path = testDirectory(*comm) + "/diagonal.msh";
  if (comm->getRank() == 0) {
    std::filesystem::create_directories(testDirectory(*comm));
    std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 1 \"bottom\"\n"
                           "$EndPhysicalNames\n$Entities\n0 1 1 0\n1 0 0 0 1 1 0 1 1 0\n1 0 0 0 1 1 0 0 0\n"
                           "$EndEntities\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                           "$EndNodes\n$Elements\n2 3 1 3\n1 1 1 1\n1 2 4\n2 1 2 2\n2 1 2 3\n3 1 3 4\n$EndElements\n";
  }
  comm->barrier();
  std::string unsupported, message;
  try {
    detail::readMshInParallel(comm, path, unsupported);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(comm->getSize() <= 2 ? "edge of any cell" : "fewer than the"), std::string::npos)
      << message;
}

}  // namespace
