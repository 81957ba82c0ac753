// Mortar contact between two bodies meshed independently: two stacked blocks whose interface
// meshes do not match (2D: 10 slave and 7 master segments, and a perturbed slave side; 3D:
// unit cubes meshed at different sizes). The rows
// of A move with the bodies (a common rigid translation leaves every weighted gap unchanged),
// an initial gap is weighted as it should, and the contact patch test passes: pressed
// uniformly, the multipliers, nodal pressures of the dual basis, equal the exact pressure;
// a P2 node whose multiplier function has no positive weight on the covered part is refused;
// a pair whose slave boundary faces every way reports its force along the last axis.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Tuple.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "core/Collectives.hpp"
#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/assembly/ContactStatistics.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/GeometricGrid.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;

// Two blocks, the unit square "lower" [0,1]^2 and "upper" [0,width] x [1 + gap, 2 + gap],
// meshed apart (Geometry.AutoCoherence = 0 keeps their interface points distinct): the lower
// one's top "lower top" in 10 segments (their inner points moved by `perturbation` along it),
// the upper one's bottom "upper bottom" in 7. Boundaries "bottom", "top", "sides". A facet
// is in one group: `groups` "left" splits the lower top into "lower top left" (its first 6
// segments) and "lower top right", "surface" makes its top and sides "lower surface" (and
// "sides" the upper block's only). Written by rank 0.
std::string writeBlocks(const Comm& comm, double gap, double perturbation, double width = 1.0,
                        const std::string& groups = "top") {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  std::ostringstream name;
  name << std::string(binary ? binary : "/tmp") << "/mortar-np" << comm.getSize();
  const std::string directory = name.str();
  std::ostringstream file;
  file << "blocks-" << gap << "-" << perturbation << "-" << width << "-" << groups << ".geo";
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(directory);
    std::ofstream geo(directory + "/" + file.str());
    geo << "Geometry.AutoCoherence = 0;\ng = " << gap << ";\nh = 0.12;\n"
        << "Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(4) = {0, 1, 0, h};\n"
        << "Point(3) = {1, 1, 0, h};\n";
    // The lower top's inner points, moved along it to break any regularity.
    for (int i = 1; i < 10; ++i)
      geo << "Point(" << 100 + i << ") = {" << i / 10.0 + perturbation * std::sin(7.0 * i) << ", 1, 0, h};\n";
    geo << "w = " << width << ";\n"
        << "Point(5) = {0, 1 + g, 0, h}; Point(6) = {w, 1 + g, 0, h}; Point(7) = {w, 2 + g, 0, h};\n"
        << "Point(8) = {0, 2 + g, 0, h};\n"
        << "Line(1) = {1, 2}; Line(2) = {2, 3};\n"
        << "Line(110) = {3, 109};\n";
    for (int i = 9; i > 1; --i) geo << "Line(" << 100 + i << ") = {" << 100 + i << ", " << 99 + i << "};\n";
    geo << "Line(101) = {101, 4};\nLine(4) = {4, 1};\n"
        << "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};\n"
        << "Transfinite Curve{5} = 8;\n"
        << "Curve Loop(1) = {1, 2, 110, 109, 108, 107, 106, 105, 104, 103, 102, 101, 4}; Plane Surface(1) = {1};\n"
        << "Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};\n"
        << "Physical Curve(\"bottom\") = {1}; Physical Curve(\"top\") = {7};\n"
        << (groups == "surface" ? "Physical Curve(\"sides\") = {6, 8};\n"
                                   "Physical Curve(\"lower surface\") = {2, 4, 101:110};\n"
                                 : "Physical Curve(\"sides\") = {2, 4, 6, 8};\n")
        << (groups == "left" ? "Physical Curve(\"lower top left\") = {101:106};\n"
                               "Physical Curve(\"lower top right\") = {107:110};\n"
                             : groups == "top" ? "Physical Curve(\"lower top\") = {101:110};\n" : "")
        << "Physical Curve(\"upper bottom\") = {5};\n"
        << "Physical Surface(\"lower\") = {1}; Physical Surface(\"upper\") = {2};\n";
  }
  comm.barrier();
  return directory + "/" + file.str();
}

// Two unit cubes, "lower" [0,1]^3 and "upper" [0,1]^2 x [1 + gap, 2 + gap], meshed apart at
// sizes h and H (OpenCASCADE boxes without a boolean fragment keep their own faces), so
// that their interface triangles do not match. Boundaries "bottom", "top", "sides" (x = 0, 1),
// "y sides", "lower top" and "upper bottom"; with `surface`, "lower surface" the lower cube's
// top and sides instead of its "lower top", and the sides groups the upper cube's only.
// Written by rank 0.
std::string writeCubes(const Comm& comm, double gap, double h, double H, bool surface = false) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  std::ostringstream name, file;
  name << std::string(binary ? binary : "/tmp") << "/mortar-np" << comm.getSize();
  file << name.str() << "/cubes-" << gap << "-" << h << "-" << H << (surface ? "-surface" : "") << ".geo";
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(name.str());
    std::ofstream geo(file.str());
    geo << "SetFactory(\"OpenCASCADE\");\n"
        << "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {0, 0, " << 1 + gap << ", 1, 1, 1};\n"
        << "MeshSize{PointsOf{Volume{1};}} = " << h << ";\nMeshSize{PointsOf{Volume{2};}} = " << H << ";\n"
        << "Physical Surface(\"bottom\") = {5};\n"
        << "Physical Surface(\"upper bottom\") = {11}; Physical Surface(\"top\") = {12};\n"
        << (surface ? "Physical Surface(\"lower surface\") = {1, 2, 3, 4, 6};\n"
                      "Physical Surface(\"sides\") = {7, 8}; Physical Surface(\"y sides\") = {9, 10};\n"
                    : "Physical Surface(\"lower top\") = {6};\n"
                      "Physical Surface(\"sides\") = {1, 2, 7, 8}; Physical Surface(\"y sides\") = {3, 4, 9, 10};\n")
        << "Physical Volume(\"lower\") = {1}; Physical Volume(\"upper\") = {2};\n";
  }
  comm.barrier();
  return file.str();
}

// A unit square turned by 30 degrees about the origin, its boundary "square boundary" but for
// the fifth of one side next to the origin ("square rest"), under a block "upper" whose bottom
// "upper bottom" touches the square's top corner; meshed apart. Written by rank 0.
std::string writeTurnedSquareUnderBlock(const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  std::ostringstream name, file;
  name << std::string(binary ? binary : "/tmp") << "/mortar-np" << comm.getSize();
  file << name.str() << "/turned-square.geo";
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(name.str());
    std::ofstream geo(file.str());
    geo << "Geometry.AutoCoherence = 0;\nh = 0.1;\nc = Cos(Pi / 6); s = Sin(Pi / 6);\n"
        << "Point(1) = {0, 0, 0, h}; Point(2) = {c, s, 0, h}; Point(3) = {c - s, s + c, 0, h};\n"
        << "Point(4) = {-s, c, 0, h}; Point(9) = {-0.2 * s, 0.2 * c, 0, h};\n"
        << "Point(5) = {-1, s + c, 0, h}; Point(6) = {1.5, s + c, 0, h}; Point(7) = {1.5, s + c + 1, 0, h};\n"
        << "Point(8) = {-1, s + c + 1, 0, h};\n"
        << "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 9}; Line(9) = {9, 1};\n"
        << "Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};\n"
        << "Curve Loop(1) = {1:4, 9}; Plane Surface(1) = {1};\nCurve Loop(2) = {5:8}; Plane Surface(2) = {2};\n"
        << "Physical Curve(\"square boundary\") = {1:4}; Physical Curve(\"square rest\") = {9};\n"
        << "Physical Curve(\"upper bottom\") = {5};\n"
        << "Physical Curve(\"upper rest\") = {6:8};\n"
        << "Physical Surface(\"square\") = {1}; Physical Surface(\"upper\") = {2};\n";
  }
  comm.barrier();
  return file.str();
}

// Two triangular prisms meshed apart: "lower", under the triangle (0,0,0), (1,0,0), (0,1,0)
// ("lower top", one facet) down to z = -1 ("lower base" its other faces), and "upper", 0.1 high
// on the sliver (0,0,0), (s,0,0), (0,t,0) ("upper bottom"; "top" its top, "upper sides").
// Written by rank 0.
std::string writeSliverOnPrism(const Comm& comm, double s, double t) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  std::ostringstream name, file;
  name << std::string(binary ? binary : "/tmp") << "/mortar-np" << comm.getSize();
  file << name.str() << "/sliver-" << s << "-" << t << ".geo";
  if (comm.getRank() == 0) {
    std::filesystem::create_directories(name.str());
    std::ofstream geo(file.str());
    geo << "Geometry.AutoCoherence = 0;\n";
    // Prism `first`: points first+1..first+6, lines first+1..first+9, surfaces first+1 (at
    // z = high), first+2 (at z = low) and first+3..first+5 (the sides).
    const auto prism = [&](int first, double a, double b, double low, double high, double size) {
      const double x[3][2] = {{0, 0}, {a, 0}, {0, b}};
      for (int level = 0; level < 2; ++level)
        for (int i = 0; i < 3; ++i)
          geo << "Point(" << first + 1 + 3 * level + i << ") = {" << x[i][0] << ", " << x[i][1] << ", "
              << (level == 0 ? high : low) << ", " << size << "};\n";
      for (int level = 0; level < 2; ++level)
        for (int i = 0; i < 3; ++i)
          geo << "Line(" << first + 1 + 3 * level + i << ") = {" << first + 1 + 3 * level + i << ", "
              << first + 1 + 3 * level + (i + 1) % 3 << "};\n";
      for (int i = 0; i < 3; ++i) geo << "Line(" << first + 7 + i << ") = {" << first + 1 + i << ", " << first + 4 + i << "};\n";
      geo << "Curve Loop(" << first + 1 << ") = {" << first + 1 << ", " << first + 2 << ", " << first + 3 << "};\n"
          << "Curve Loop(" << first + 2 << ") = {" << first + 4 << ", " << first + 5 << ", " << first + 6 << "};\n";
      for (int i = 0; i < 3; ++i)
        geo << "Curve Loop(" << first + 3 + i << ") = {" << first + 1 + i << ", " << first + 7 + (i + 1) % 3 << ", -"
            << first + 4 + i << ", -" << first + 7 + i << "};\n";
      for (int i = 1; i <= 5; ++i) geo << "Plane Surface(" << first + i << ") = {" << first + i << "};\n";
      geo << "Surface Loop(" << first + 1 << ") = {" << first + 1 << ":" << first + 5 << "};\n"
          << "Volume(" << first + 1 << ") = {" << first + 1 << "};\n";
    };
    prism(0, 1.0, 1.0, -1.0, 0.0, 2.0);
    prism(100, s, t, 0.0, 0.1, 0.1);
    geo << "Transfinite Curve{1, 2, 3} = 2;\n"  // the lower top stays one triangle
        << "Physical Surface(\"lower top\") = {1}; Physical Surface(\"lower base\") = {2:5};\n"
        << "Physical Surface(\"upper bottom\") = {102}; Physical Surface(\"top\") = {101};\n"
        << "Physical Surface(\"upper sides\") = {103:105};\n"
        << "Physical Volume(\"lower\") = {1}; Physical Volume(\"upper\") = {101};\n";
  }
  comm.barrier();
  return file.str();
}

// The blocks on rollers (sides), the lower one on the ground, the upper one's top moved down
// by `approach`; "lower top" the slave side.
Teuchos::ParameterList pressedBlocks(const std::string& file, double approach, int degree = 1, int dim = 2) {
  const std::string vertical = dim == 2 ? "displacement: y" : "displacement: z";
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", file);
  problem.set("element: degree", degree);
  problem.set("material: poisson ratio", 0.3);
  problem.sublist("Dirichlet").sublist("sides").set("displacement: x", "0");
  if (dim == 3) problem.sublist("Dirichlet").sublist("y sides").set("displacement: y", "0");
  problem.sublist("Dirichlet").sublist("bottom").set(vertical, "0");
  std::ostringstream down;
  down.precision(17);
  down << -approach;
  problem.sublist("Dirichlet").sublist("top").set(vertical, down.str());
  problem.sublist("Contact").set("boundary", "lower top");
  problem.sublist("Contact").set("master boundary", "upper bottom");
  return problem;
}

AssembledProblem build(const Teuchos::ParameterList& problem) {
  auto comm = Tpetra::getDefaultComm();
  return buildProblem(problem, comm);
}

// Each row's entries summed per component: A applied to a translation of both bodies.
double largestRowSum(const CrsMatrix& A, int component, int dim = 2) {
  Vector t(A.getDomainMap()), At(A.getRangeMap());
  auto data = t.getDataNonConst();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(data.size()); ++i)
    data[i] = A.getDomainMap()->getGlobalElement(i) % dim == component;
  data = Teuchos::null;
  A.apply(t, At);
  return At.normInf();
}

// The problem solved to KKT measures far below the 1e-8 asked of the pressure: the largest
// relative deviation of -lambda (the paper's sign, lambda <= 0) from `pressure` over every
// rank; infinite if the solver did not converge.
double largestPressureDeviation(const AssembledProblem& p, double pressure) {
  Teuchos::ParameterList solver;
  solver.set("kkt: tolerance", 1e-12);
  const SolveResult r = InteriorPointSolver(solver).solve(p.qp, p.multigrid);
  EXPECT_TRUE(r.converged()) << r.message;
  if (!r.converged()) return std::numeric_limits<double>::infinity();
  double local = 0;
  for (double value : r.lambda->getData()) local = std::max(local, std::abs(-value / pressure - 1.0));
  return maxOverRanks(*p.qp.A->getComm(), local);
}

TEST(MortarConstraints, RowsMoveWithTheBodies) {
  for (double perturbation : {0.0, 0.03}) {
    const AssembledProblem p =
        build(pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), 0.0, perturbation), 0.0));
    const CrsMatrix& A = *p.qp.A;
    EXPECT_EQ(static_cast<long long>(A.getGlobalNumRows()), 11) << perturbation;  // the slave nodes
    // Full coverage: the master terms of each row cancel its slave terms.
    EXPECT_LT(largestRowSum(A, 0), 1e-14) << perturbation;
    EXPECT_LT(largestRowSum(A, 1), 1e-14) << perturbation;
    EXPECT_LT(p.qp.d->normInf(), 1e-14) << perturbation;
  }
}

// An initial gap g along the slave normal: d_j = g times the integral of psi_j, whose sum
// over the slave nodes is the interface's length.
TEST(MortarConstraints, AnInitialGapIsWeightedByTheMultiplierFunctions) {
  const double gap = 0.05;
  const AssembledProblem p = build(pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), gap, 0.03), 0.0));
  auto d = p.qp.d->getData();
  double local = 0, smallest = 1;
  for (double value : d) {
    local += value;
    smallest = std::min(smallest, value);
  }
  EXPECT_NEAR(sumOverRanks(*p.qp.d->getMap()->getComm(), local), gap * 1.0, 1e-14);
  EXPECT_GT(minOverRanks(*p.qp.d->getMap()->getComm(), smallest), 0.0);
}

// Uniaxial strain (rollers on the sides): sigma_yy = -M approach / 2 in both blocks,
// M = E (1 - nu) / ((1 + nu)(1 - 2 nu)); every multiplier is that pressure (with the
// paper's sign, lambda = -p), P1 and P2, on the meshes read and refined once (every level a
// multigrid grid, whose points of the two bodies meet at the interface's ends).
TEST(MortarConstraints, PassTheContactPatchTest) {
  const double approach = 0.01, nu = 0.3, pressure = (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * approach / 2;
  for (int refinements : {0, 1})
  for (int degree : {1, 2})
  for (double perturbation : {0.0, 0.03}) {
    Teuchos::ParameterList problem =
        pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), 0.0, perturbation), approach, degree);
    problem.set("mesh: refinements", refinements);
    EXPECT_LT(largestPressureDeviation(build(problem), pressure), 1e-8)
        << perturbation << " P" << degree << " r" << refinements;
  }
}

// Of degree 2 the geometric multigrid goes to the P1 grid of the mesh's vertices first, found
// by their coordinates: where the two bodies have a vertex at one place (the interface's ends,
// (0, 1) and (1, 1)), each body's node finds its own body's vertex.
TEST(MortarConstraints, GridsTellTheBodiesApartWhereTheirNodesMeet) {
  const AssembledProblem p = build(pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), 0.0, 0.0), 0.0, 2));
  const GeometricGrid& grid = *p.multigrid.grid;
  ASSERT_EQ(p.multigrid.nodeBodies.size(), p.multigrid.coordinates->getLocalLength());
  auto x = p.multigrid.coordinates->getData(0), y = p.multigrid.coordinates->getData(1);
  // Per corner and body, the vertex found + 1 (0: no owned node there), the largest over ranks.
  std::vector<long long> found(4, 0), all(4);
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(x.size()); ++i)
    for (int corner = 0; corner < 2; ++corner)
      if (x[i] == corner && y[i] == 1.0) {
        const double at[2] = {x[i], y[i]};
        const long long v = grid.vertexOfBodyAt(at, p.multigrid.nodeBodies[i]);
        ASSERT_GE(v, 0);
        found[2 * corner + p.multigrid.nodeBodies[i]] = v + 1;
      }
  Teuchos::reduceAll(*p.qp.A->getComm(), Teuchos::REDUCE_MAX, 4, found.data(), all.data());
  for (int corner = 0; corner < 2; ++corner) {
    EXPECT_GT(all[2 * corner], 0);
    EXPECT_GT(all[2 * corner + 1], 0);
    EXPECT_NE(all[2 * corner], all[2 * corner + 1]) << corner;
  }
}

// The same under a uniform pressure on the top: the upper block is held vertically by the
// contact alone, a motion of that body only, which the rigid body check finds and the solver
// handles on every rank count. Every multiplier is the applied pressure.
TEST(MortarConstraints, PassTheContactPatchTestUnderAPressure) {
  const double pressure = 0.01;
  for (int degree : {1, 2})
  for (double perturbation : {0.0, 0.03}) {
    Teuchos::ParameterList problem =
        pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), 0.0, perturbation), 0.0, degree);
    problem.sublist("Dirichlet").remove("top");
    problem.sublist("Traction").sublist("top").set("traction: y", "-0.01");
    const AssembledProblem p = build(problem);
    EXPECT_EQ(p.multigrid.bodyMotions(p.qp)->getNumVectors(), 6u);  // two bodies' modes
    EXPECT_LT(largestPressureDeviation(p, pressure), 1e-8) << perturbation << " P" << degree;
  }
}

// Two contact pairs in one problem, one sublist each: the lower block stands on the rigid
// ground ("ground", dual mortar constraints on its bottom) instead of being clamped, and the
// upper one on it ("interface"). Under a uniform pressure on the top every multiplier of both
// pairs is the applied pressure, each pair carries the whole load, and the interface's action
// and reaction balance.
TEST(MortarConstraints, SeveralPairsPassThePatchTestTogether) {
  const double pressure = 0.01;
  for (int degree : {1, 2}) {
    Teuchos::ParameterList problem =
        pressedBlocks(writeBlocks(*Tpetra::getDefaultComm(), 0.0, 0.03), 0.0, degree);
    problem.sublist("Dirichlet").remove("top");
    problem.sublist("Dirichlet").remove("bottom");
    problem.sublist("Traction").sublist("top").set("traction: y", "-0.01");
    problem.remove("Contact");
    Teuchos::ParameterList& ground = problem.sublist("Contact").sublist("ground");
    ground.set("boundary", "bottom");
    ground.set("formulation", "dual mortar");
    Teuchos::ParameterList& interface = problem.sublist("Contact").sublist("interface");
    interface.set("boundary", "lower top");
    interface.set("master boundary", "upper bottom");
    const AssembledProblem p = build(problem);
    ASSERT_EQ(p.definition.contacts.size(), 2u);
    EXPECT_EQ(p.definition.contacts[1].name, "interface");
    // Not given, the interface's obstacle direction points from the master into the slave body.
    EXPECT_EQ(p.definition.contacts[1].obstacleDirection, (std::array<double, 3>{{0.0, -1.0, 0.0}}));
    EXPECT_LT(largestPressureDeviation(p, pressure), 1e-8) << "P" << degree;

    Teuchos::ParameterList solver;
    solver.set("kkt: tolerance", 1e-12);
    const SolveResult r = InteriorPointSolver(solver).solve(p.qp, p.multigrid);
    ASSERT_TRUE(r.converged()) << r.message;
    const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
    for (std::size_t pair = 0; pair < 2; ++pair) {
      const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap(), pair);
      const RCP<Vector> pressures = recovery.pressure(*r.lambda, *active);
      const ContactStatistics s = contactStatistics(recovery, *pressures, *p.qp.A, *r.lambda, *active,
                                                    p.definition.contacts[pair].obstacleDirection);
      EXPECT_NEAR(s.normalForce, pressure, 1e-8 * pressure) << "pair " << pair << " P" << degree;
      EXPECT_NEAR(s.peakPressure, pressure, 1e-8 * pressure) << "pair " << pair << " P" << degree;
      EXPECT_NEAR(s.area, 1.0, 1e-12) << "pair " << pair << " P" << degree;
      EXPECT_EQ(s.masterForce.has_value(), pair == 1);
      for (int c = 0; s.masterForce && c < 2; ++c) EXPECT_NEAR((*s.masterForce)[c], -s.force[c], 1e-10 * pressure);
    }
  }
}

// A slave boundary that faces every way (a turned square's boundary but a fifth of one side:
// its mean outward normal is 0.05 long, along that side's normal) gives no direction from the
// master into the slave body: without an obstacle: direction, the pair reports its normal
// force along the last axis.
TEST(MortarConstraints, ASlaveBoundaryFacingEveryWayReportsAlongTheLastAxis) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: type", "gmsh");
  problem.set("mesh: file", writeTurnedSquareUnderBlock(*Tpetra::getDefaultComm()));
  problem.sublist("Contact").set("boundary", "square boundary");
  problem.sublist("Contact").set("master boundary", "upper bottom");
  const AssembledProblem p = build(problem);
  EXPECT_EQ(p.definition.contacts.front().obstacleDirection, (std::array<double, 3>{{0.0, 1.0, 0.0}}));
}

// The solution of a problem solved to KKT measures far below the differences asked of it.
SolveResult solvedTightly(const AssembledProblem& p) {
  Teuchos::ParameterList solver;
  solver.set("kkt: tolerance", 1e-12);
  SolveResult r = InteriorPointSolver(solver).solve(p.qp, p.multigrid);
  EXPECT_TRUE(r.converged()) << r.message;
  return r;
}

// The largest difference of two vectors on maps with the same elements, relative to the
// first's largest entry, over every rank.
double relativeDifference(const Vector& a, const Vector& b) {
  auto x = a.getData(), y = b.getData();
  EXPECT_EQ(x.size(), y.size());
  double local = 0;
  for (Teuchos::ArrayRCP<const double>::size_type i = 0; i < std::min(x.size(), y.size()); ++i)
    local = std::max(local, std::abs(x[i] - y[i]));
  return maxOverRanks(*a.getMap()->getComm(), local) / a.normInf();
}

// The master boundary may cover the slave boundary in part: here the lower block's top and
// sides are the slave side, and the sides face no master facet. Only the nodes of the top
// have constraints, and the patch test passes as with the top alone (P1 and P2, 2D and 3D;
// the lower block's rollers on the whole slave side, which the uniaxial strain of the exact
// solution satisfies on its top too).
TEST(MortarConstraints, SlaveFacetsThatNoMasterCoversHaveNoConstraints) {
  const Comm& comm = *Tpetra::getDefaultComm();
  const double pressure = 0.01;
  for (int dim : {2, 3})
  for (int degree : {1, 2}) {
    const auto pressed = [&](const std::string& file) {
      Teuchos::ParameterList problem = pressedBlocks(file, 0.0, degree, dim);
      problem.sublist("Dirichlet").remove("top");
      problem.sublist("Traction").sublist("top").set(dim == 2 ? "traction: y" : "traction: z", "-0.01");
      return problem;
    };
    const Teuchos::ParameterList top =
        pressed(dim == 2 ? writeBlocks(comm, 0.0, 0.03) : writeCubes(comm, 0.0, 0.3, 0.22));
    Teuchos::ParameterList surface =
        pressed(dim == 2 ? writeBlocks(comm, 0.0, 0.03, 1.0, "surface") : writeCubes(comm, 0.0, 0.3, 0.22, true));
    surface.sublist("Contact").set("boundary", "lower surface");
    surface.sublist("Dirichlet").sublist("lower surface").set("displacement: x", "0");
    if (dim == 3) surface.sublist("Dirichlet").sublist("lower surface").set("displacement: y", "0");
    const AssembledProblem p = build(surface);
    EXPECT_EQ(p.qp.A->getGlobalNumRows(), build(top).qp.A->getGlobalNumRows()) << dim << "D P" << degree;
    EXPECT_LT(largestPressureDeviation(p, pressure), 1e-8) << dim << "D P" << degree;
  }
}

// A master boundary that ends at a slave node (the upper block 0.6 wide, the slave nodes 0.1
// apart): the slave nodes beyond have no constraint, and the problem is the one whose slave
// boundary stops there, with the same rows and the same solution.
TEST(MortarConstraints, AMasterEndingAtASlaveNodeTrimsTheSlaveBoundary) {
  const Comm& comm = *Tpetra::getDefaultComm();
  const std::string file = writeBlocks(comm, 0.0, 0.0, 0.6), split = writeBlocks(comm, 0.0, 0.0, 0.6, "left");
  for (int degree : {1, 2}) {
    Teuchos::ParameterList trimmed = pressedBlocks(split, 0.01, degree);
    trimmed.sublist("Contact").set("boundary", "lower top left");
    const AssembledProblem whole = build(pressedBlocks(file, 0.01, degree)), part = build(trimmed);
    ASSERT_EQ(whole.qp.A->getGlobalNumRows(), degree == 1 ? 7u : 13u);
    ASSERT_EQ(part.qp.A->getGlobalNumRows(), whole.qp.A->getGlobalNumRows());
    const SolveResult a = solvedTightly(whole), b = solvedTightly(part);
    EXPECT_LT(relativeDifference(*a.lambda, *b.lambda), 1e-9) << "P" << degree;
    EXPECT_LT(relativeDifference(*a.v, *b.v), 1e-9) << "P" << degree;
  }
}

// A master boundary that ends inside a slave facet (the upper block 0.63 wide): the covered
// part of the facet carries the constraint of its one covered node. The multiplier functions
// sum to one on the covered part, so that the rows applied to a unit pressure give each side
// a force of the covered length, and an initial gap g sums to g times that length. Pressed
// down, the action and reaction balance and the contact area stays within the covered part.
TEST(MortarConstraints, AMasterEndingInsideASlaveFacetCoversItsCoveredPart) {
  const Comm& comm = *Tpetra::getDefaultComm();
  const double gap = 0.05, covered = 0.63;
  for (int degree : {1, 2}) {
    const AssembledProblem p = build(pressedBlocks(writeBlocks(comm, gap, 0.0, covered), 0.0, degree));
    ASSERT_EQ(p.qp.A->getGlobalNumRows(), degree == 1 ? 7u : 13u);  // the nodes up to x = 0.6
    auto d = p.qp.d->getData();
    double sum = 0, smallest = 1;
    for (double value : d) {
      sum += value;
      smallest = std::min(smallest, value);
    }
    EXPECT_NEAR(sumOverRanks(comm, sum), gap * covered, 1e-14) << "P" << degree;
    EXPECT_GT(minOverRanks(comm, smallest), 0.0) << "P" << degree;
    Vector ones(p.qp.A->getRangeMap()), force(p.qp.A->getDomainMap());
    ones.putScalar(1.0);
    p.qp.A->apply(ones, force, Teuchos::TRANS);
    auto f = force.getData();
    auto y = p.multigrid.coordinates->getData(1);
    double onSides[2] = {0, 0};  // the vertical forces on the lower and the upper block
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(y.size()); ++i) onSides[y[i] > 1 + gap / 2] += f[2 * i + 1];
    EXPECT_NEAR(sumOverRanks(comm, onSides[0]), covered, 1e-12) << "P" << degree;
    EXPECT_NEAR(sumOverRanks(comm, onSides[1]), -covered, 1e-12) << "P" << degree;
  }
  const AssembledProblem p = build(pressedBlocks(writeBlocks(comm, 0.0, 0.0, covered), 0.01));
  const SolveResult r = solvedTightly(p);
  const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
  const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap(), 0);
  const ContactStatistics s = contactStatistics(recovery, *recovery.pressure(*r.lambda, *active), *p.qp.A,
                                                *r.lambda, *active, p.definition.contacts[0].obstacleDirection);
  ASSERT_TRUE(s.masterForce.has_value());
  for (int c = 0; c < 2; ++c) EXPECT_NEAR((*s.masterForce)[c], -s.force[c], 1e-10 * s.normalForce);
  EXPECT_GT(s.normalForce, 0.0);
  EXPECT_GT(s.area, 0.0);
  EXPECT_LE(s.area, covered + 1e-12);
}

// Hertz between two elastic bodies (examples/bodies/disk-on-block-2d.xml): a half-disk of
// radius 1 pressed onto a block, for equal moduli and a disk 100 times stiffer. For the
// computed force P and 1/E* = (1 - nu^2)(1/E_disk + 1/E_block): the peak of -lambda (the
// nodal pressures) and the half-width of the active set within 3% of Hertz' p0 = 2P/(pi a)
// and a = sqrt(4 P R / (pi E*)).
TEST(MortarConstraints, TwoElasticBodiesFollowHertz) {
  const std::string directory = signorini::testing::sourceDir() + "/examples/bodies";
  for (double disk : {1.0, 100.0}) {
    Teuchos::ParameterList problem =
        Teuchos::getParametersFromXmlFile(directory + "/disk-on-block-2d.xml")->sublist("Problem");
    problem.sublist("Bodies").sublist("disk").set("material: young's modulus", disk);
    const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm(), directory);
    const SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
    ASSERT_TRUE(r.converged()) << r.message;
    const DistributedSpace& ds = distributedSpace(*p.space);
    const OwnedContactNodes contact = ownedContactNodes(ds, p.definition);
    const RCP<Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
    auto lambda = r.lambda->getData();
    auto isActive = active->getData();
    double peak = 0, halfWidth = 0, force = 0;
    for (std::size_t k = 0; k < contact.nodes.size(); ++k) {
      peak = std::max(peak, -lambda[k]);
      if (isActive[k] != 0) halfWidth = std::max(halfWidth, std::abs(ds.space().nodeCoordinates()[2 * contact.nodes[k]]));
    }
    Vector reaction(p.qp.A->getDomainMap());  // the block's force on the disk: A^T lambda on the slave DOFs
    p.qp.A->apply(*r.lambda, reaction, Teuchos::TRANS);
    auto f = reaction.getData();
    for (long long node : contact.nodes) force += f[ds.ownedNodeMap()->getLocalElement(ds.globalNode(node)) * 2 + 1];
    const Comm& comm = *ds.comm();
    peak = maxOverRanks(comm, peak);
    halfWidth = maxOverRanks(comm, halfWidth);
    force = sumOverRanks(comm, force);
    const double eStar = 1.0 / ((1 - 0.3 * 0.3) * (1.0 / disk + 1.0)), a = std::sqrt(4 * force / (M_PI * eStar));
    EXPECT_NEAR(peak / (2 * force / (M_PI * a)), 1.0, 0.03) << disk;
    EXPECT_NEAR(halfWidth / a, 1.0, 0.03) << disk;
  }
}

// The same in 3D, where each master triangle's projection is clipped to the slave triangles
// it covers: a translation of both bodies leaves every row unchanged, an initial gap g sums
// to g times the interface's area, and the patch test passes under a prescribed approach and
// under a pressure, for two pairs of mesh sizes and a coarse pair refined once, P1 and P2.
TEST(MortarConstraints, RowsMoveWithTheBodiesIn3D) {
  const Comm& comm = *Tpetra::getDefaultComm();
  for (const auto& [h, H] : {std::pair{0.3, 0.22}, std::pair{0.2, 0.33}}) {
    const AssembledProblem p = build(pressedBlocks(writeCubes(comm, 0.0, h, H), 0.0, 1, 3));
    for (int c = 0; c < 3; ++c) EXPECT_LT(largestRowSum(*p.qp.A, c, 3), 1e-14) << h;
    EXPECT_LT(p.qp.d->normInf(), 1e-14) << h;
  }
  const double gap = 0.05;
  const AssembledProblem p = build(pressedBlocks(writeCubes(comm, gap, 0.3, 0.22), 0.0, 1, 3));
  auto d = p.qp.d->getData();
  double local = 0;
  for (double value : d) local += value;
  EXPECT_NEAR(sumOverRanks(comm, local), gap * 1.0, 1e-14);
}

TEST(MortarConstraints, PassTheContactPatchTestIn3D) {
  const double approach = 0.01, nu = 0.3, modulus = (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  for (int degree : {1, 2})
  for (const auto& [h, H] : {std::pair{0.3, 0.22}, std::pair{0.2, 0.33}, std::pair{0.6, 0.45}})
    for (bool underAPressure : {false, true}) {
      const std::string file = writeCubes(*Tpetra::getDefaultComm(), 0.0, h, H);
      Teuchos::ParameterList problem = pressedBlocks(file, underAPressure ? 0.0 : approach, degree, 3);
      if (h > 0.5) problem.set("mesh: refinements", 1);  // coarse meshes, refined once
      const double pressure = underAPressure ? 0.01 : modulus * approach / 2;
      if (underAPressure) {
        problem.sublist("Dirichlet").remove("top");
        problem.sublist("Traction").sublist("top").set("traction: z", "-0.01");
      }
      EXPECT_LT(largestPressureDeviation(build(problem), pressure), 1e-8) << h << " " << underAPressure << " P" << degree;
    }
}

// Hertz between two elastic bodies in 3D (examples/bodies/ball-on-block-3d.xml, its coarsest
// mesh): a half-ball of radius 1 pressed onto a block, for equal moduli and a block 100 times
// stiffer. The pressure as users see it (recovered as Output/contact pressure's default
// does) peaks within 5% of Hertz' p0 = 3P/(2 pi a^2) and the active area's radius is within
// 5% of a = (3 P R / (4 E*))^(1/3), P the computed force.
TEST(MortarConstraints, TwoElasticBodiesFollowHertzIn3D) {
  const std::string directory = signorini::testing::sourceDir() + "/examples/bodies";
  for (double block : {1.0, 100.0}) {
    Teuchos::ParameterList problem =
        Teuchos::getParametersFromXmlFile(directory + "/ball-on-block-3d.xml")->sublist("Problem");
    problem.set("material: young's modulus", block);  // the block's; the ball's is its own
    const AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm(), directory);
    const SolveResult r = InteriorPointSolver().solve(p.qp, p.multigrid);
    ASSERT_TRUE(r.converged()) << r.message;
    const RCP<const Vector> active = activeIndicator(p.qp, *r.v, *r.lambda);
    const ContactPressure recovery(*p.space, p.definition, p.qp.A->getRangeMap());
    const RCP<Vector> pressure = recovery.recover(PressureRecovery::Auto, *r.lambda, *active);
    const ContactStatistics contact = contactStatistics(recovery, *pressure, *p.qp.A, *r.lambda, *active,
                                                        p.definition.contacts.front().obstacleDirection);
    const double eStar = 1.0 / ((1 - 0.3 * 0.3) * (1.0 + 1.0 / block));
    const double a = std::cbrt(3 * contact.normalForce / (4 * eStar)), p0 = 3 * contact.normalForce / (2 * M_PI * a * a);
    EXPECT_NEAR(contact.peakPressure / p0, 1.0, 0.05) << block;
    EXPECT_NEAR(std::sqrt(contact.area / M_PI) / a, 1.0, 0.05) << block;
    ASSERT_TRUE(contact.masterForce.has_value());  // action and reaction
    for (int c = 0; c < 3; ++c) EXPECT_NEAR((*contact.masterForce)[c], -contact.force[c], 1e-10 * contact.normalForce);
  }
}

TEST(MortarConstraints, BadPairsAreInputErrors) {
  const std::string file = writeBlocks(*Tpetra::getDefaultComm(), 0.0, 0.0);
  Teuchos::ParameterList same = pressedBlocks(file, 0.0);
  same.sublist("Contact").set("master boundary", "lower top");
  EXPECT_THROW(build(same), InputError);
  Teuchos::ParameterList nodal = pressedBlocks(file, 0.0);
  nodal.sublist("Contact").set("formulation", "nodal");
  EXPECT_THROW(build(nodal), InputError);
  Teuchos::ParameterList away = pressedBlocks(file, 0.0);  // the upper top faces away from the slave side
  away.sublist("Contact").set("master boundary", "top");
  EXPECT_THROW(build(away), InputError);
  Teuchos::ParameterList sameBody = pressedBlocks(file, 0.0);  // the lower block's bottom
  sameBody.sublist("Contact").set("master boundary", "bottom");
  EXPECT_THROW(build(sameBody), InputError);
  // Bodies that overlap at the start by half a facet; within the tolerance, they are posed.
  const Comm& comm = *Tpetra::getDefaultComm();
  EXPECT_THROW(build(pressedBlocks(writeBlocks(comm, -0.05, 0.0), 0.0)), InputError);
  EXPECT_THROW(build(pressedBlocks(writeCubes(comm, -0.1, 0.3, 0.22), 0.0, 1, 3)), InputError);
  EXPECT_LT(build(pressedBlocks(writeBlocks(comm, -0.001, 0.0), 0.0)).qp.d->normInf(), 0.001);
}

// A master boundary that covers of a P2 slave facet only the sliver from a vertex to just past
// the middle of one edge and a twentieth along the next: the multiplier function of that
// edge's middle node is negative over most of the sliver, its weight negative, and the node
// would carry no pressure. Refused in one line that names the node; with P1 multipliers, whose
// one covered node then takes the whole sliver, the same pair is posed.
TEST(MortarConstraints, ANodeWithoutPositiveWeightIsAnInputError) {
  const std::string file = writeSliverOnPrism(*Tpetra::getDefaultComm(), 0.525, 0.05);
  for (int degree : {1, 2}) {
    Teuchos::ParameterList problem("Problem");
    problem.set("mesh: type", "gmsh");
    problem.set("mesh: file", file);
    problem.set("element: degree", degree);
    for (const char* clamped : {"lower base", "top"})
      for (const char* c : {"displacement: x", "displacement: y", "displacement: z"})
        problem.sublist("Dirichlet").sublist(clamped).set(c, "0");
    problem.sublist("Contact").set("boundary", "lower top");
    problem.sublist("Contact").set("master boundary", "upper bottom");
    if (degree == 1) {
      EXPECT_EQ(build(problem).qp.A->getGlobalNumRows(), 1u);
      continue;
    }
    try {
      build(problem);
      ADD_FAILURE() << "a node whose multiplier function has a negative weight was posed";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("node at (0.5, 0, 0) has no positive integral"), std::string::npos) << message;
    }
  }
}

// Several pairs are sublists of Problem/Contact, each with a contact boundary of its own, and
// the pair parameters then stay in them.
TEST(MortarConstraints, BadPairListsAreInputErrors) {
  const std::string file = writeBlocks(*Tpetra::getDefaultComm(), 0.0, 0.0);
  const auto withPairs = [&](const std::string& first, const std::string& second) {
    Teuchos::ParameterList problem = pressedBlocks(file, 0.0);
    problem.remove("Contact");
    problem.sublist("Contact").sublist("one").set("boundary", first);
    problem.sublist("Contact").sublist("two").set("boundary", second);
    problem.sublist("Contact").sublist("two").set("master boundary", "upper bottom");
    return problem;
  };
  EXPECT_THROW(build(withPairs("lower top", "lower top")), InputError);  // one boundary in two pairs
  EXPECT_THROW(build(withPairs("", "lower top")), InputError);          // a pair without a boundary
  Teuchos::ParameterList both = withPairs("top", "lower top");
  both.sublist("Contact").set("boundary", "bottom");  // a pair given beside the sublists
  EXPECT_THROW(build(both), InputError);
  Teuchos::ParameterList outside = withPairs("top", "lower top");
  outside.sublist("Contact").set("formulation", "dual mortar");  // read by no pair
  EXPECT_THROW(build(outside), InputError);
  Teuchos::ParameterList sameSides = withPairs("upper bottom", "lower top");  // the message names the pair
  sameSides.sublist("Contact").sublist("one").set("master boundary", "upper bottom");
  try {
    build(sameSides);
    ADD_FAILURE() << "a pair with one boundary on both sides was posed";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("Problem/Contact/one: ", 0), 0u) << e.what();
  }
}

}  // namespace
