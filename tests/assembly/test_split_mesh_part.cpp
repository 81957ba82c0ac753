// A Gmsh mesh written in parts, one file per rank (gmsh -part N -part_split), read by every
// rank on its own against the same mesh read whole by rank 0: the same discrete problem, so
// the same unknowns, constraints and optimal value, on any rank count, P1 to P3, as is and
// refined. Part files that do not fit the run are refused on every rank. The ranks' numbering
// of the lattice points of parts scattered cell by cell over a box is checked against the
// geometry: one id per point, owned by the lowest rank that holds it, on the box faces it lies on.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gmsh.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/CoarseMeshLattice.hpp"
#include "core/NeighbourExchange.hpp"
#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::gmshPressedProblem;

// A unit square (2D) or cube (3D) with groups "bottom" (y or z = 0), "top" and "body", meshed
// at size h by rank 0 and written whole as whole.msh and in `parts` parts as split_k.msh.
std::string writeMeshes(const Comm& comm, int dim, double h, int parts) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/split-mesh-test-" + std::to_string(dim) +
                                "d-np" + std::to_string(comm.getSize()) + "-" + std::to_string(parts);
  if (comm.getRank() == 0) {
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    signorini::testing::meshUnitBox(dim, h);
    gmsh::write(directory + "/whole.msh");
    gmsh::option::setNumber("Mesh.PartitionSplitMeshFiles", 1);
    gmsh::model::mesh::partition(parts);
    gmsh::write(directory + "/split.msh");
    gmsh::finalize();
  }
  comm.barrier();
  return directory;
}

double optimalValue(const AssembledProblem& p) {
  const SolveResult r = InteriorPointSolver(Teuchos::ParameterList()).solve(p.qp, p.multigrid);
  EXPECT_TRUE(r.converged()) << r.message;
  return r.objective;
}

class SplitMesh : public ::testing::TestWithParam<int> {};

TEST_P(SplitMesh, GivesTheProblemOfTheWholeFile) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  if (comm->getSize() == 1) GTEST_SKIP() << "a mesh in one part is a whole file";
  const std::string directory = writeMeshes(*comm, dim, dim == 2 ? 0.1 : 0.3, comm->getSize());
  struct Case {
    int degree, refinements;
  };
  for (const Case c : {Case{1, 0}, Case{2, 0}, Case{3, 0}, Case{1, 1}}) {
    if (dim == 3 && c.degree == 3) continue;  // P3 in 3D adds time, not coverage
    const std::string label = std::to_string(dim) + "D P" + std::to_string(c.degree) + ", " +
                              std::to_string(c.refinements) + " refinement(s)";
    const AssembledProblem split = buildProblem(gmshPressedProblem(dim, "split.msh", c.degree, c.refinements), comm, directory);
    const AssembledProblem whole = buildProblem(gmshPressedProblem(dim, "whole.msh", c.degree, c.refinements), comm, directory);
    EXPECT_EQ(split.space->numGlobalNodes(), whole.space->numGlobalNodes()) << label;
    EXPECT_EQ(split.space->numGlobalCells(), whole.space->numGlobalCells()) << label;
    EXPECT_EQ(split.qp.d->getGlobalLength(), whole.qp.d->getGlobalLength()) << label;
    EXPECT_NEAR(split.qp.b->norm2(), whole.qp.b->norm2(), 1e-12 * whole.qp.b->norm2()) << label;
    const double a = optimalValue(split), b = optimalValue(whole);
    EXPECT_NEAR(a, b, 1e-9 * std::fabs(b)) << label;
  }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, SplitMesh, ::testing::Values(2, 3));

TEST(SplitMeshInput, PartsThatDoNotMatchTheRankCountAreRefused) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, 2, 0.25, comm->getSize() + 1);
  try {
    buildProblem(gmshPressedProblem(2, "split.msh", 1, 0), comm, directory);
    ADD_FAILURE() << "parts for another rank count were read";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("is written in " + std::to_string(comm->getSize() + 1) + " parts"), std::string::npos)
        << message;
  }
}

TEST(SplitMeshInput, AWholeMeshAmongThePartsIsRefused) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeMeshes(*comm, 2, 0.25, 2);
  if (comm->getRank() == 0)
    for (int k = 1; k <= comm->getSize(); ++k)
      std::filesystem::copy_file(directory + "/whole.msh", directory + "/lone_" + std::to_string(k) + ".msh",
                                 std::filesystem::copy_options::overwrite_existing);
  comm->barrier();
  try {
    buildProblem(gmshPressedProblem(2, "lone.msh", 1, 0), comm, directory);
    ADD_FAILURE() << "a whole mesh was read as a part";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not one part of a partitioned mesh"), std::string::npos) << e.what();
  }
}

// Rank r's part of `mesh` when cell c goes to rank cellRank[c], as a part file would give it:
// the cells, their boundary facets, each vertex's tag (id + 1) and the ranks holding it.
GmshMeshPart scatteredPart(const SimplexMesh& mesh, const std::vector<int>& cellRank, int rank) {
  const int d = mesh.dim;
  std::vector<std::set<int>> holders(mesh.numVertices());
  for (long long c = 0; c < mesh.numCells(); ++c)
    for (int v = 0; v <= d; ++v) holders[mesh.cells[(d + 1) * c + v]].insert(cellRank[c]);
  GmshMeshPart part;
  part.part = rank;
  part.mesh.dim = d;
  part.mesh.boundaryTags = mesh.boundaryTags;
  std::map<long long, long long> local;
  for (long long v = 0; v < mesh.numVertices(); ++v)
    if (holders[v].count(rank)) {
      local[v] = static_cast<long long>(part.vertexTags.size());
      part.vertexTags.push_back(v + 1);
      part.mesh.vertices.insert(part.mesh.vertices.end(), &mesh.vertices[d * v], &mesh.vertices[d * v + d]);
      part.sharerStart.push_back(static_cast<long long>(part.sharers.size()));
      part.sharers.insert(part.sharers.end(), holders[v].begin(), holders[v].end());
    }
  part.sharerStart.push_back(static_cast<long long>(part.sharers.size()));
  std::set<std::vector<long long>> ownFaces;  // sorted vertices of the part's cells' faces
  for (long long c = 0; c < mesh.numCells(); ++c) {
    if (cellRank[c] != rank) continue;
    const long long* cell = &mesh.cells[(d + 1) * c];
    for (int v = 0; v <= d; ++v) part.mesh.cells.push_back(local.at(cell[v]));
    for (int omit = 0; omit <= d; ++omit) {
      std::vector<long long> face;
      for (int v = 0; v <= d; ++v)
        if (v != omit) face.push_back(cell[v]);
      std::sort(face.begin(), face.end());
      ownFaces.insert(face);
    }
  }
  for (long long f = 0; f < mesh.numFacets(); ++f) {
    std::vector<long long> face(&mesh.facets[d * f], &mesh.facets[d * f + d]);
    std::sort(face.begin(), face.end());
    if (!ownFaces.count(face)) continue;
    for (int v = 0; v < d; ++v) part.mesh.facets.push_back(local.at(mesh.facets[d * f + v]));
    part.mesh.facetTags.push_back(mesh.facetTags[f]);
  }
  return part;
}

TEST(SplitMeshLattice, ScatteredPartsNumberEveryPointOnceAndFindItsBoundaries) {
  auto comm = Tpetra::getDefaultComm();
  const int size = comm->getSize(), rank = comm->getRank();
  const SimplexMesh mesh = makeBoxMesh(3, {3, 2, 2}, {1, 1, 1});
  std::vector<int> cellRank(mesh.numCells());
  for (long long c = 0; c < mesh.numCells(); ++c) cellRank[c] = static_cast<int>((7 * c + 3) % size);
  const int n = 4;  // lattice points on every edge, face and cell
  const detail::CoarseMeshLattice lattice(comm, scatteredPart(mesh, cellRank, rank), n);

  // Every lattice point of resolution 4 of every cell: coordinates, id, owner, rank, and
  // whether it is on each of the box's six faces (tags 1..6), to rank 0.
  const SimplexRefinement refinement(3, 2);
  std::vector<std::vector<double>> toRank(size);
  for (long long c = 0; c < lattice.mesh().numCells(); ++c)
    for (const LatticePoint& a : refinement.points(2)) {
      double x[3];
      lattice.pointCoordinates(c, a, n, x);
      toRank[0].insert(toRank[0].end(), x, x + 3);
      toRank[0].push_back(static_cast<double>(lattice.pointId(c, a, n)));
      toRank[0].push_back(lattice.pointOwner(c, a));
      toRank[0].push_back(rank);
      for (int tag = 1; tag <= 6; ++tag) toRank[0].push_back(lattice.onBoundary(c, a, tag));
    }
  const std::vector<double> all = exchangeWithRanks(*comm, toRank);
  if (rank != 0) return;
  constexpr int kRecord = 12;
  std::map<long long, std::vector<const double*>> byId;
  std::map<std::array<double, 3>, std::set<long long>> idsAt;
  for (std::size_t at = 0; at < all.size(); at += kRecord) {
    byId[static_cast<long long>(all[at + 3])].push_back(&all[at]);
    idsAt[{all[at], all[at + 1], all[at + 2]}].insert(static_cast<long long>(all[at + 3]));
  }
  ASSERT_EQ(static_cast<long long>(byId.size()), lattice.numPoints(n));
  EXPECT_EQ(byId.begin()->first, 0);
  EXPECT_EQ(byId.rbegin()->first, lattice.numPoints(n) - 1);
  for (const auto& [x, ids] : idsAt) EXPECT_EQ(ids.size(), 1u) << "point (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  for (const auto& [id, records] : byId) {
    int lowest = size;
    for (const double* r : records) lowest = std::min(lowest, static_cast<int>(r[5]));
    for (const double* r : records) {
      EXPECT_EQ(static_cast<int>(r[4]), lowest) << "owner of point " << id;
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(r[6 + 2 * axis] != 0, r[axis] == 0.0) << "point " << id << " on face " << 2 * axis + 1;
        EXPECT_EQ(r[7 + 2 * axis] != 0, r[axis] == 1.0) << "point " << id << " on face " << 2 * axis + 2;
      }
    }
  }
}

}  // namespace
