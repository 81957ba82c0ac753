// A body that the boundary conditions do not hold is refused before the solve, with the
// rigid body motion named; a body held by its contact alone is solved.
#include <gtest/gtest.h>

#include <string>

#include <Tpetra_Core.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "solver/RigidBodySupport.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::boxProblem;
using signorini::testing::contactBoxProblem;

std::string checkMessage(const AssembledProblem& p) {
  try {
    checkRigidBodyMotionsHeld(p.qp, p.multigrid);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string checkMessage(const Teuchos::ParameterList& problem) {
  return checkMessage(buildProblem(problem, Tpetra::getDefaultComm()));
}

// A 2D box whose bottom is in contact and whose sides may slide vertically only (u_x = 0 on
// xmin and xmax): only the vertical translation is left, and the contact stops it downwards.
Teuchos::ParameterList rollerBox(const char* topTraction) {
  Teuchos::ParameterList problem = boxProblem(2, 4, 1);
  for (const char* side : {"xmin", "xmax"}) problem.sublist("Dirichlet").sublist(side).set("displacement: x", "0");
  problem.sublist("Traction").sublist("ymax").set("traction: y", topTraction);
  problem.sublist("Contact").set("boundary", "ymin");
  return problem;
}

TEST(RigidBodySupport, ClampedBodyPasses) {
  for (int dim : {2, 3}) EXPECT_EQ(checkMessage(contactBoxProblem(dim, 3)), "") << "dim " << dim;
}

TEST(RigidBodySupport, FreeBodyWithoutContactIsRefused) {
  for (int dim : {2, 3}) {
    Teuchos::ParameterList problem = boxProblem(dim, 3, 1);
    problem.set("body force: x", "1");
    EXPECT_NE(checkMessage(problem).find("the body is free to move by a"), std::string::npos) << "dim " << dim;
  }
}

TEST(RigidBodySupport, SlidingAlongTheObstacleIsNamed) {
  // Only the vertical displacement of the top is prescribed: nothing stops a slide along x.
  Teuchos::ParameterList problem = contactBoxProblem(2, 3);
  problem.sublist("Dirichlet").sublist("ymax").remove("displacement: x");
  const std::string message = checkMessage(problem);
  EXPECT_NE(message.find("free to move by a translation along (1, 0)"), std::string::npos) << message;
  EXPECT_NE(message.find("Problem/Dirichlet"), std::string::npos) << message;
}

TEST(RigidBodySupport, BodyPressedOntoTheObstacleIsHeldByTheContact) {
  EXPECT_EQ(checkMessage(rollerBox("-1")), "");
  Teuchos::ParameterList params;
  const SolveResult r = InteriorPointSolver(params).solve(buildProblem(rollerBox("-1"), Tpetra::getDefaultComm()).qp);
  EXPECT_TRUE(r.converged()) << r.message;
}

TEST(RigidBodySupport, LoadPullingTheBodyOffIsRefusedByTheSolver) {
  const AssembledProblem problem = buildProblem(rollerBox("1"), Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  try {
    InteriorPointSolver(Teuchos::ParameterList()).solve(qp, problem.multigrid);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pulls the body off the obstacle by a translation along (0, 1)"),
              std::string::npos)
        << e.what();
  }
}

TEST(RigidBodySupport, RotationIsNamedByItsAxis) {
  // A free 3D body whose rigid body modes are the rotation about z alone.
  AssembledProblem p = buildProblem(boxProblem(3, 2, 1), Tpetra::getDefaultComm());
  const int aboutZ = 5;
  p.multigrid.nullspace = p.multigrid.nearNullspace(p.qp)->subCopy(Teuchos::tuple<std::size_t>(aboutZ));
  const std::string message = checkMessage(p);
  EXPECT_NE(message.find("free to move by a rotation about an axis along (0, 0, 1)"), std::string::npos) << message;
}

TEST(RigidBodySupport, QpWithoutModesIsNotChecked) {
  AssembledProblem p = buildProblem(boxProblem(2, 2, 1), Tpetra::getDefaultComm());
  p.multigrid.nullspace = Teuchos::null;
  p.multigrid.coordinates = Teuchos::null;
  EXPECT_EQ(checkMessage(p), "");
}

TEST(RigidBodySupport, ModesAreMadeFromCoordinatesOfQsNodesOnly) {
  AssembledProblem p = buildProblem(boxProblem(2, 2, 1), Tpetra::getDefaultComm());
  p.multigrid.nullspace = Teuchos::null;
  ASSERT_FALSE(p.multigrid.nearNullspace(p.qp).is_null());
  EXPECT_EQ(p.multigrid.nearNullspace(p.qp)->getNumVectors(), 3u);
  // One coordinate row more than Q's nodes on rank 0: no modes, on every rank.
  const auto comm = Tpetra::getDefaultComm();
  const std::size_t rows = p.multigrid.coordinates->getLocalLength() + (comm->getRank() == 0 ? 1 : 0);
  p.multigrid.coordinates = Teuchos::rcp(new MultiVector(
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), rows, 0, comm)), 2));
  EXPECT_TRUE(p.multigrid.nearNullspace(p.qp).is_null());
  EXPECT_EQ(checkMessage(p), "");
}

}  // namespace
