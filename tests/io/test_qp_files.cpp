// The QP as Matrix Market files: what writeQP writes, readQP reads back into node-aligned
// maps on any rank count, and the solve reaches the same optimum; files that disagree are
// refused in one message that names them.
#include "signorini/io/QPFiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

// An empty directory for this test and rank count, made by rank 0.
std::string scratch(const std::string& name, const Comm& comm) {
  const std::string dir = (fs::temp_directory_path() / ("signorini-qp-" + name + "-" +
                                                         std::to_string(comm.getSize()))).string();
  if (comm.getRank() == 0) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  comm.barrier();
  return dir;
}

// Paper problem `name` with Q assembled, written to `dir`.
AssembledProblem written(const std::string& name, const std::string& dir) {
  Teuchos::ParameterList problem = testing::shippedProblem("paper/" + name);
  problem.set("stiffness: operator", "assembled");
  AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  writeQP(p.qp, p.multigrid, dir);
  return p;
}

TEST(QPFiles, RoundTripReachesTheSameOptimumOnEveryRankCount) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* name : {"M", "H", "B"}) {
    const std::string dir = scratch(std::string("round-trip-") + name, *comm);
    const AssembledProblem direct = written(name, dir);
    const QPFromFiles files = readQP(dir, comm);
    const ContactQP& read = files.qp;
    EXPECT_EQ(files.multigrid.blockSize, direct.multigrid.blockSize) << name;
    EXPECT_EQ(read.b->getGlobalLength(), direct.qp.b->getGlobalLength()) << name;
    EXPECT_EQ(read.d->getGlobalLength(), direct.qp.d->getGlobalLength()) << name;
    // Whole nodes on every rank: the DOF count of each rank is a multiple of the block size.
    EXPECT_EQ(read.Q->getDomainMap()->getNodeNumElements() % files.multigrid.blockSize, 0u) << name;
    EXPECT_FALSE(files.multigrid.nearNullspace(read).is_null()) << name << ": no rigid body modes from the coordinates";
    const SolveResult a = InteriorPointSolver(Teuchos::ParameterList()).solve(direct.qp, direct.multigrid);
    const SolveResult b = InteriorPointSolver(Teuchos::ParameterList()).solve(read, files.multigrid);
    ASSERT_TRUE(a.converged() && b.converged()) << name << ": " << b.message;
    EXPECT_LT(std::abs(a.objective - b.objective), 1e-10 * std::abs(a.objective)) << name;
    EXPECT_LE(std::abs(a.outerIterations - b.outerIterations), 1) << name;
    EXPECT_EQ(a.activeConstraints, b.activeConstraints) << name;
  }
}

// The files of `dir` with the nodes renumbered: node v becomes permutation[v] (Q, b, A's
// columns and the coordinates; d and the constraints' order stay). Rank 0 rewrites them.
void renumberNodes(const std::string& dir, const std::vector<long long>& permutation, int dim, const Comm& comm) {
  if (comm.getRank() == 0) {
    const auto dof = [&](long long i) { return dim * permutation[i / dim] + i % dim; };
    const auto lines = [](const std::string& path) {
      std::ifstream in(path);
      std::vector<std::string> all;
      for (std::string line; std::getline(in, line);) all.push_back(line);
      return all;
    };
    // Coordinate files: header and size lines, then "row column value" from 1.
    for (const char* name : {"Q.mtx", "A.mtx"}) {
      const bool renumberRows = std::string(name) == "Q.mtx";
      const std::vector<std::string> in = lines(dir + "/" + name);
      std::ofstream out(dir + "/" + name);
      std::size_t k = 0;
      for (; in[k][0] == '%'; ++k) out << in[k] << '\n';
      out << in[k++] << '\n';
      for (; k < in.size(); ++k) {
        std::istringstream entry(in[k]);
        long long row = 0, column = 0;
        std::string value;
        entry >> row >> column >> value;
        out << (renumberRows ? dof(row - 1) + 1 : row) << ' ' << dof(column - 1) + 1 << ' ' << value << '\n';
      }
    }
    // Array files (column-major): b, one column of n, and the coordinates, dim columns of nodes.
    const auto permuteArray = [&](const std::string& name, int columns, const auto& newRow) {
      const std::vector<std::string> in = lines(dir + "/" + name);
      std::ofstream out(dir + "/" + name);
      std::size_t k = 0;
      for (; in[k][0] == '%'; ++k) out << in[k] << '\n';
      out << in[k++] << '\n';
      const long long count = static_cast<long long>(in.size() - k) / columns;
      std::vector<std::string> moved(in.size() - k);
      for (int c = 0; c < columns; ++c)
        for (long long i = 0; i < count; ++i) moved[c * count + newRow(i)] = in[k + c * count + i];
      for (const std::string& line : moved) out << line << '\n';
    };
    permuteArray("b.mtx", 1, dof);
    permuteArray("coords.mtx", dim, [&](long long node) { return permutation[node]; });
  }
  comm.barrier();
}

// A QP whose nodes are numbered without regard to position (as a code that numbers them cell
// by cell does) is read onto METIS' parts, which cut far fewer node couplings; the box's own
// numbering, whose equal shares are slabs, is kept. The optimum is the same either way.
TEST(QPFiles, ScatteredNodesAreRepartitionedByMetis) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratch("scattered", *comm);
  const AssembledProblem direct = written("M", dir);
  const QPFromFiles inOrder = readQP(dir, comm);
  EXPECT_FALSE(inOrder.repartitioned);
  const int dim = direct.multigrid.blockSize;
  std::vector<long long> permutation(direct.qp.b->getGlobalLength() / dim);
  std::iota(permutation.begin(), permutation.end(), 0LL);
  std::shuffle(permutation.begin(), permutation.end(), std::mt19937(7));
  renumberNodes(dir, permutation, dim, *comm);
  const QPFromFiles asWritten = readQP(dir, comm, QPPartition::AsWritten), automatic = readQP(dir, comm);
  EXPECT_FALSE(asWritten.repartitioned);
  EXPECT_EQ(automatic.repartitioned, comm->getSize() > 1);
  if (comm->getSize() > 1) {
    EXPECT_GT(automatic.crossRankCouplingsInFileOrder, 0.4);
    EXPECT_LT(automatic.crossRankCouplings, 0.25 * automatic.crossRankCouplingsInFileOrder);
  }
  EXPECT_FALSE(automatic.multigrid.nearNullspace(automatic.qp).is_null());
  const SolveResult a = InteriorPointSolver().solve(direct.qp, direct.multigrid);
  for (const QPFromFiles* files : {&asWritten, &automatic}) {
    const SolveResult b = InteriorPointSolver().solve(files->qp, files->multigrid);
    ASSERT_TRUE(a.converged() && b.converged()) << b.message;
    EXPECT_LT(std::abs(a.objective - b.objective), 1e-10 * std::abs(a.objective));
    EXPECT_EQ(a.activeConstraints, b.activeConstraints);
  }
}

// Nodal constraints are read onto the ranks of their nodes: every unknown a local row of A uses
// is a local unknown, so A's products need no communication. The QP is written by one rank,
// in the natural numbering of the box, whose bottom nodes (the contact) come first: an even
// split of the constraints would put most of them away from their nodes.
TEST(QPFiles, NodalConstraintsLiveWithTheirNodes) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratch("placement", *comm);
  if (comm->getRank() == 0) {
    Teuchos::ParameterList problem = testing::shippedProblem("paper/H");
    problem.set("stiffness: operator", "assembled");
    const AssembledProblem serial = testing::buildSerial(problem);
    writeQP(serial.qp, serial.multigrid, dir);
  }
  comm->barrier();
  const ContactQP read = readQP(dir, comm).qp;
  const Map& unknowns = *read.Q->getDomainMap();
  long long elsewhere = 0;
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(read.A->getNodeNumRows()); ++i) {
    CrsMatrix::local_inds_host_view_type columns;
    CrsMatrix::values_host_view_type values;
    read.A->getLocalRowView(i, columns, values);
    for (std::size_t k = 0; k < columns.extent(0); ++k)
      elsewhere += !unknowns.isNodeGlobalElement(read.A->getColMap()->getGlobalElement(columns(k)));
  }
  EXPECT_EQ(elsewhere, 0);
  EXPECT_EQ(read.A->getGlobalNumRows(), read.d->getGlobalLength());
  EXPECT_TRUE(read.d->getMap()->isSameAs(*read.A->getRangeMap()));
}

// The message of the InputError that readQP throws, "" if none.
std::string readError(const std::string& dir) {
  try {
    readQP(dir, Tpetra::getDefaultComm());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(QPFiles, MissingOrInconsistentFilesAreNamed) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratch("refused", *comm);
  written("M", dir);
  if (comm->getRank() == 0) fs::rename(dir + "/d.mtx", dir + "/d.mtx.away");
  comm->barrier();
  EXPECT_NE(readError(dir).find(dir + "/d.mtx: cannot be opened"), std::string::npos) << readError(dir);
  if (comm->getRank() == 0) {
    std::ofstream(dir + "/d.mtx") << "%%MatrixMarket matrix array real general\n12 1\n";  // one row too many
  }
  comm->barrier();
  const std::string message = readError(dir);
  EXPECT_NE(message.find("A.mtx: 11 x 242, expected 12 x 242"), std::string::npos) << message;
}

// cells.mtx is optional; one that cannot be the mesh of coords.mtx's nodes is refused.
TEST(QPFiles, CellsMustFitTheNodes) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratch("cells", *comm);
  written("M", dir);  // 2D: three vertices per cell
  if (comm->getRank() == 0)
    std::ofstream(dir + "/cells.mtx") << "%%MatrixMarket matrix array real general\n1 2\n0\n1\n";
  comm->barrier();
  EXPECT_NE(readError(dir).find("cells.mtx: 2 columns"), std::string::npos) << readError(dir);
  if (comm->getRank() == 0)
    std::ofstream(dir + "/cells.mtx") << "%%MatrixMarket matrix array real general\n1 3\n0\n1\n100000\n";
  comm->barrier();
  EXPECT_NE(readError(dir).find("names node 100000"), std::string::npos) << readError(dir);
}

}  // namespace
}  // namespace signorini
