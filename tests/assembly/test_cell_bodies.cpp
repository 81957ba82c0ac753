// Bodies of their own material: a Gmsh mesh's physical groups of the domain's dimension are
// bodies, each cell assembled with its body's material and body force (Problem/Bodies), also
// after a refinement (children in their parent's body) and in the matrix-free operator. The
// check is a bar of two materials in series, pulled at its end: the exact solution is
// piecewise linear, which P1 and P2 reproduce.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

constexpr double kSoft = 1.0, kStiff = 4.0;  // Young's moduli of x < 1 and x > 1

// The bar [0,2] x [0,1](x [0,1]) as two bodies "soft" (x < 1) and "stiff" (x > 1) meshed
// together (their interface nodes shared), with boundaries "left" (x = 0), "right" (x = 2)
// and "bottom" (y = 0, or z = 0 in 3D). Written by rank 0; returns its directory.
std::string writeBar(const Comm& comm, int dim) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string directory = std::string(binary ? binary : "/tmp") + "/cell-bodies-np" +
                                std::to_string(comm.getSize());
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    std::ofstream geo(directory + "/bar" + std::to_string(dim) + "d.geo");
    if (dim == 2) {
      geo << "h = 0.25;\n"
             "Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {2, 0, 0, h};\n"
             "Point(4) = {2, 1, 0, h}; Point(5) = {1, 1, 0, h}; Point(6) = {0, 1, 0, h};\n"
             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};\n"
             "Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};\n"
             "Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};\n"
             "Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};\n"
             "Physical Curve(\"left\") = {6}; Physical Curve(\"right\") = {3};\n"
             "Physical Curve(\"bottom\") = {1, 2};\n"
             "Physical Surface(\"soft\") = {1}; Physical Surface(\"stiff\") = {2};\n";
    } else {
      geo << "SetFactory(\"OpenCASCADE\");\n"
             "Box(1) = {0, 0, 0, 1, 1, 1}; Box(2) = {1, 0, 0, 1, 1, 1};\n"
             "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
             "MeshSize{ PointsOf{ Volume{:}; } } = 0.5;\n"
             "e = 1e-6;\n"
             "Physical Surface(\"left\") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};\n"
             "Physical Surface(\"right\") = Surface In BoundingBox{2 - e, -e, -e, 2 + e, 1 + e, 1 + e};\n"
             "Physical Surface(\"bottom\") = Surface In BoundingBox{-e, -e, -e, 2 + e, 1 + e, e};\n"
             "Physical Volume(\"soft\") = Volume In BoundingBox{-e, -e, -e, 1 + e, 1 + e, 1 + e};\n"
             "Physical Volume(\"stiff\") = Volume In BoundingBox{1 - e, -e, -e, 2 + e, 1 + e, 1 + e};\n";
    }
  }
  comm.barrier();
  return directory;
}

// The bar pulled by a unit traction at x = 2, held at x = 0 along x and on its bottom across
// (every side but those free), nu = 0: the stress is uniaxial, sigma_xx = 1 everywhere.
Teuchos::ParameterList pulledBar(int dim, int degree, int refinements) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", "bar" + std::to_string(dim) + "d.geo");
  problem.set("mesh: refinements", refinements);
  problem.set("element: degree", degree);
  problem.set("stiffness: operator", "assembled");
  problem.set("material: young's modulus", kSoft);
  problem.set("material: poisson ratio", 0.0);
  problem.sublist("Bodies").sublist("stiff").set("material: young's modulus", kStiff);
  problem.sublist("Dirichlet").sublist("left").set("displacement: x", "0");
  auto& bottom = problem.sublist("Dirichlet").sublist("bottom");
  bottom.set("displacement: y", "0");
  if (dim == 3) {
    bottom.set("displacement: z", "0");
    problem.sublist("Dirichlet").sublist("left").set("displacement: y", "0");
  }
  problem.sublist("Traction").sublist("right").set("traction: x", "1");
  return problem;
}

AssembledProblem build(const Teuchos::ParameterList& problem, int dim) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = writeBar(*comm, dim);
  return buildProblem(problem, comm, comm->getRank() == 0 ? directory : directory + "/nowhere");
}

// u_x of the two materials in series: x / E_soft, then the soft half's 1 / E_soft plus
// (x - 1) / E_stiff.
double pulledUx(double x) { return x <= 1.0 ? x / kSoft : 1.0 / kSoft + (x - 1.0) / kStiff; }

// The largest deviation over all nodes of the solved displacement from the exact one,
// exactUx(x) along x and none across.
double largestError(const AssembledProblem& p, int dim, const std::function<double(double)>& exactUx) {
  Vector u(p.qp.b->getMap());
  EXPECT_GT(solveLinear(p.qp, p.multigrid, u, 1e-12), 0);
  const MultiVector& x = *p.multigrid.coordinates;
  auto ud = u.getData();
  double local = 0;
  for (std::size_t i = 0; i < x.getLocalLength(); ++i) {
    local = std::max(local, std::abs(ud[dim * i] - exactUx(x.getData(0)[i])));
    for (int c = 1; c < dim; ++c) local = std::max(local, std::abs(ud[dim * i + c]));
  }
  double global = 0;
  Teuchos::reduceAll(*p.space->comm(), Teuchos::REDUCE_MAX, 1, &local, &global);
  return global;
}

TEST(CellBodies, TwoMaterialsInSeriesGiveTheExactDisplacement) {
  for (int dim : {2, 3})
    for (int degree : {1, 2})
      for (int refinements : {0, 1}) {
        const std::string what = std::to_string(dim) + "D P" + std::to_string(degree) + ", " +
                                 std::to_string(refinements) + " refinement(s)";
        const AssembledProblem p = build(pulledBar(dim, degree, refinements), dim);
        EXPECT_LT(largestError(p, dim, pulledUx), 1e-8) << what;
      }
}

// Without the stiff body's own modulus the bar is uniform: the end moves by 2 / E_soft, which
// the two-material displacement is not (the check above can fail).
TEST(CellBodies, WithoutItsOwnMaterialTheBodyHasTheProblemLevelOne) {
  Teuchos::ParameterList problem = pulledBar(2, 1, 0);
  problem.sublist("Bodies").sublist("stiff").set("material: young's modulus", "auto");
  const AssembledProblem p = build(problem, 2);
  EXPECT_GT(largestError(p, 2, pulledUx), 0.5);  // at x = 2: 2 against 1.25
}

// The body force of a body acts on its cells only: a unit force along x on the stiff half
// alone, the bar held at x = 0 and free at x = 2.
TEST(CellBodies, ABodyForceActsOnItsBodyOnly) {
  Teuchos::ParameterList problem = pulledBar(2, 2, 0);
  problem.sublist("Traction").remove("right");
  problem.sublist("Bodies").sublist("stiff").set("body force: x", "1");
  const AssembledProblem p = build(problem, 2);
  // The axial stress is 1 for x < 1 and 2 - x for x > 1 (zero at the free end): u_x is its
  // integral over E, x / E_soft up to 1, then quadratic, which P2 holds exactly.
  const auto exactUx = [](double x) {
    return x <= 1.0 ? x / kSoft : 1.0 / kSoft + (2.0 * (x - 1.0) - (x * x - 1.0) / 2.0) / kStiff;
  };
  EXPECT_LT(largestError(p, 2, exactUx), 1e-8);
}

// The matrix-free operator applies each cell's material as the assembled matrix does.
TEST(CellBodies, MatrixFreeOperatorHasEachCellsMaterial) {
  for (int dim : {2, 3}) {
    Teuchos::ParameterList problem = pulledBar(dim, 2, 0);
    const AssembledProblem assembled = build(problem, dim);
    problem.set("stiffness: operator", "matrix-free");
    const AssembledProblem matrixFree = build(problem, dim);
    Vector v(assembled.qp.b->getMap()), Qv(v.getMap()), Mv(v.getMap());
    v.randomize();
    assembled.qp.Q->apply(v, Qv);
    matrixFree.qp.Q->apply(v, Mv);
    Mv.update(-1.0, Qv, 1.0);
    EXPECT_LT(Mv.norm2(), 1e-12 * Qv.norm2()) << dim << "D";
  }
}

TEST(CellBodies, AnUnknownBodyIsAnInputErrorNamingTheMeshsBodies) {
  Teuchos::ParameterList problem = pulledBar(2, 1, 0);
  problem.sublist("Bodies").sublist("steel").set("material: young's modulus", 2.0);
  try {
    build(problem, 2);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown body \"steel\"; the mesh has: \"soft\", \"stiff\""), std::string::npos)
        << e.what();
  }
  Teuchos::ParameterList box = boxProblem(2, 4, 1);
  box.sublist("Bodies").sublist("steel");
  EXPECT_THROW(buildProblem(box, Tpetra::getDefaultComm()), InputError);
}

}  // namespace
