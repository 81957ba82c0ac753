// The connected pieces of a distributed mesh: one for a box, two for two squares meshed apart
// (whatever the ranks' parts cut), the nodes of each square in one piece.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <Tpetra_Core.hpp>
#include <Tpetra_MultiVector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/MeshPieces.hpp"
#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// Squares [0,1]^2 and [2,3] x [0,1] (a gap between them), written by rank 0.
std::string writeTwoSquares(const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/pieces-np" + std::to_string(comm.getSize());
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    std::ofstream(directory + "/squares.geo")
        << "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\nRectangle(2) = {2, 0, 0, 1, 1};\n"
           "MeshSize{ PointsOf{ Surface{1, 2}; } } = 0.2;\n"
           "Physical Curve(\"left\") = Curve In BoundingBox{-0.1, -0.1, -0.1, 0.1, 1.1, 0.1};\n"
           "Physical Surface(\"squares\") = {1, 2};\n";
  }
  comm.barrier();
  return directory + "/squares.geo";
}

TEST(MeshPieces, ABoxIsOnePiece) {
  const AssembledProblem p = buildProblem(signorini::testing::boxProblem(2, 6, 1), Tpetra::getDefaultComm());
  EXPECT_EQ(meshPieces(distributedSpace(*p.space)).count, 1);
  EXPECT_TRUE(p.multigrid.nodeBodies.empty());
}

TEST(MeshPieces, SquaresMeshedApartAreTwoPieces) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", writeTwoSquares(*Tpetra::getDefaultComm()));
  const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  const DistributedSpace& ds = distributedSpace(*p.space);
  const MeshPieces& pieces = meshPieces(ds);
  EXPECT_EQ(pieces.count, 2);
  EXPECT_EQ(&meshPieces(ds), &pieces);  // found once per space, then kept
  // Each square's nodes all in one piece, the two pieces different.
  const MultiVector& x = *p.multigrid.coordinates;
  int lowest[2] = {2, 2}, highest[2] = {-1, -1};
  for (std::size_t i = 0; i < x.getLocalLength(); ++i) {
    const int square = x.getData(0)[i] > 1.5 ? 1 : 0;
    lowest[square] = std::min(lowest[square], pieces.ofOwnedNode[i]);
    highest[square] = std::max(highest[square], pieces.ofOwnedNode[i]);
  }
  for (int square : {0, 1}) {
    EXPECT_EQ(minOverRanks(*ds.comm(), lowest[square]), maxOverRanks(*ds.comm(), highest[square])) << square;
  }
  EXPECT_NE(minOverRanks(*ds.comm(), lowest[0]), minOverRanks(*ds.comm(), lowest[1]));
  EXPECT_EQ(p.multigrid.nodeBodies, pieces.ofOwnedNode);
}

// The right square, which nothing holds, is refused by the rigid body check, named by where
// it is (the left one is clamped).
TEST(MeshPieces, AnUnheldPieceIsNamedByWhereItIs) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", writeTwoSquares(*Tpetra::getDefaultComm()));
  problem.sublist("Dirichlet").sublist("left").set("displacement: x", "0");
  problem.sublist("Dirichlet").sublist("left").set("displacement: y", "0");
  const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
  try {
    InteriorPointSolver().solve(p.qp, p.multigrid);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();  // the centroid of its nodes: (2.5, 0.5) up to the mesh
    EXPECT_EQ(message.rfind("the body around (2.5, 0.5", 0), 0u) << message;
    EXPECT_NE(message.find(") is free to move by a "), std::string::npos) << message;
  }
}

}  // namespace
