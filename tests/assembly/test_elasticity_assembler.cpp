// Assembly of the contact QP on 1 to 4 ranks: sizes of the benchmark family, agreement
// with a one-rank assembly, rigid body modes, patch test and convergence orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/ElasticityAssembler.hpp"
#include "core/Collectives.hpp"
#include "fe/SimplexQuadrature.hpp"
#include "signorini/core/Error.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

struct FamilyMember {
  const char* name;
  long long n, m;
};

// doc/benchmark-family.md
const FamilyMember kFamily[] = {{"A", 50, 5},     {"B", 375, 25},     {"C", 1995, 81},   {"D", 13203, 289},
                                {"E", 3993, 121}, {"F", 24783, 441},  {"G", 882, 21},    {"H", 3362, 41},
                                {"I", 7442, 61},  {"J", 20402, 101},  {"K", 5202, 51},   {"L", 27783, 441},
                                {"M", 242, 11}};

TEST(ElasticityAssembler, FamilySizesMatchTheTable) {
  auto comm = Tpetra::getDefaultComm();
  for (const auto& member : kFamily) {
    AssembledProblem p = buildProblem(shippedProblem(std::string("paper/") + member.name), comm);
    EXPECT_EQ(static_cast<long long>(p.qp.b->getGlobalLength()), member.n) << member.name;
    EXPECT_EQ(static_cast<long long>(p.qp.d->getGlobalLength()), member.m) << member.name;
    EXPECT_EQ(static_cast<long long>(p.qp.A->getGlobalNumEntries()), member.m) << member.name;
  }
}

// A fixed displacement defined by the coordinates, so that it is the same field whatever
// the numbering of the nodes.
void fillField(const DistributedSpace& ds, Vector& v) {
  const int dim = ds.dim();
  auto data = v.getDataNonConst();
  const std::size_t owned = ds.ownedNodeMap()->getNodeNumElements();
  for (std::size_t i = 0; i < owned; ++i) {
    const double* x = &ds.space().nodeCoordinates()[dim * ds.overlapSpaceNodes()[i]];
    for (int c = 0; c < dim; ++c) data[dim * i + c] = std::sin(1.0 + 2.0 * x[0] + (c + 1) * x[1] + (dim == 3 ? 0.5 * x[2] : 0.0));
  }
}

struct Invariants {
  double qNorm, bNorm, aNorm, dNorm, vQv, bv;
};

Invariants invariants(const AssembledProblem& p) {
  Vector v(p.qp.Q->getDomainMap()), Qv(p.qp.Q->getRangeMap());
  fillField(distributedSpace(*p.space), v);
  p.qp.Q->apply(v, Qv);
  return {assembledStiffness(p.qp, p.multigrid)->getFrobeniusNorm(), p.qp.b->norm2(), p.qp.A->getFrobeniusNorm(),
          p.qp.d->norm2(), v.dot(Qv), p.qp.b->dot(v)};
}

TEST(ElasticityAssembler, SameProblemOnEveryRankCount) {
  for (const char* name : {"G", "H", "I", "B", "C"}) {
    auto list = shippedProblem(std::string("paper/") + name);
    list.set("stiffness: operator", "assembled");  // its norm is compared
    const Invariants parallel = invariants(buildProblem(list, Tpetra::getDefaultComm()));
    const Invariants serial = invariants(buildSerial(list));
    EXPECT_NEAR(parallel.qNorm, serial.qNorm, 1e-12 * serial.qNorm) << name;
    EXPECT_NEAR(parallel.bNorm, serial.bNorm, 1e-12 * serial.bNorm) << name;
    EXPECT_NEAR(parallel.aNorm, serial.aNorm, 1e-12 * serial.aNorm) << name;
    EXPECT_NEAR(parallel.dNorm, serial.dNorm, 1e-12) << name;
    EXPECT_NEAR(parallel.vQv, serial.vQv, 1e-12 * std::abs(serial.vQv)) << name;
    EXPECT_NEAR(parallel.bv, serial.bv, 1e-12 * std::abs(serial.bv)) << name;
  }
}

// A caller that needs Q as a matrix gets it where the user left the choice to the program;
// a choice the user made stays.
TEST(ElasticityAssembler, StiffnessNeedAssemblesAnAutomaticOperatorOnly) {
  const auto comm = Tpetra::getDefaultComm();
  const auto assembled = [](const AssembledProblem& p) {
    return dynamic_cast<const CrsMatrix*>(p.qp.Q.get()) != nullptr;
  };
  Teuchos::ParameterList p2 = boxProblem(2, 4, 2);
  p2.set("stiffness: operator", "auto");
  EXPECT_FALSE(assembled(buildProblem(p2, comm)));
  EXPECT_TRUE(assembled(buildProblem(p2, comm, ".", StiffnessNeed::Assembled)));
  EXPECT_EQ(p2.get<std::string>("stiffness: operator"), "auto");  // the caller's list is not edited
  p2.set("stiffness: operator", "matrix-free");
  EXPECT_FALSE(assembled(buildProblem(p2, comm, ".", StiffnessNeed::Assembled)));
}

// The build reports its phases' times (the slowest rank's, the same on every rank) and every
// rank's setup memory to its observer.
TEST(ElasticityAssembler, BuildObserverReceivesThePhasesAndTheMemory) {
  const auto comm = Tpetra::getDefaultComm();
  BuildRecorder built;
  buildProblem(boxProblem(3, 6, 1), comm, ".", StiffnessNeed::AsConfigured, &built);
  EXPECT_GT(built.setupSeconds, 0.0);
  EXPECT_GT(built.assemblySeconds, 0.0);
  EXPECT_DOUBLE_EQ(maxOverRanks(*comm, built.assemblySeconds), minOverRanks(*comm, built.assemblySeconds));
  ASSERT_EQ(built.setupPeakMiB.size(), static_cast<std::size_t>(comm->getSize()));
  for (double growth : built.setupPeakMiB) EXPECT_GE(growth, 0.0);
}

TEST(ElasticityAssembler, RigidBodyModesAreInTheKernelOfTheFreeStiffness) {
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      AssembledProblem p = buildProblem(boxProblem(dim, dim == 2 ? 6 : 3, degree), Tpetra::getDefaultComm());
      const RCP<const MultiVector> nearNullspace = p.multigrid.nearNullspace(p.qp);
      const MultiVector& modes = *nearNullspace;
      MultiVector Qm(modes.getMap(), modes.getNumVectors());
      p.qp.Q->apply(modes, Qm);
      Teuchos::Array<double> norms(modes.getNumVectors()), modeNorms(modes.getNumVectors());
      Qm.normInf(norms());
      modes.normInf(modeNorms());
      const double qNorm = assembledStiffness(p.qp, p.multigrid)->getFrobeniusNorm();
      for (int k = 0; k < static_cast<int>(norms.size()); ++k)
        EXPECT_LT(norms[k], 1e-12 * qNorm * modeNorms[k]) << "dim " << dim << " P" << degree << " mode " << k;
    }
}

// Every boundary clamped to u(x) = B x + c, no body force: the discrete solution is u.
TEST(ElasticityAssembler, PatchTestReproducesLinearFields) {
  const char* axes = "xyz";
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      Teuchos::ParameterList list = boxProblem(dim, dim == 2 ? 5 : 3, degree);
      const std::string field[3] = {"0.1 + 0.3*x - 0.2*y + 0.05*z", "-0.2 + 0.1*x + 0.4*y - 0.1*z",
                                    "0.3 - 0.25*x + 0.15*y + 0.2*z"};
      for (const char* boundary : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
        if (dim == 2 && boundary[0] == 'z') continue;
        auto& bc = list.sublist("Dirichlet").sublist(boundary);
        for (int c = 0; c < dim; ++c) bc.set(std::string("displacement: ") + axes[c], field[c]);
      }
      AssembledProblem p = buildProblem(list, Tpetra::getDefaultComm());
      Vector v(p.qp.Q->getDomainMap());
      ASSERT_GT(solveLinear(p.qp, p.multigrid, v, 1e-13), 0);
      const DistributedSpace& ds = distributedSpace(*p.space);
      double localError = 0;
      auto data = v.getData();
      for (std::size_t i = 0; i < ds.ownedNodeMap()->getNodeNumElements(); ++i) {
        const double* x = &ds.space().nodeCoordinates()[dim * ds.overlapSpaceNodes()[i]];
        const double z = dim == 3 ? x[2] : 0.0;
        const double exact[3] = {0.1 + 0.3 * x[0] - 0.2 * x[1] + 0.05 * z, -0.2 + 0.1 * x[0] + 0.4 * x[1] - 0.1 * z,
                                 0.3 - 0.25 * x[0] + 0.15 * x[1] + 0.2 * z};
        for (int c = 0; c < dim; ++c) localError = std::max(localError, std::abs(data[dim * i + c] - exact[c]));
      }
      double error = 0;
      Teuchos::reduceAll(*ds.comm(), Teuchos::REDUCE_MAX, 1, &localError, &error);
      EXPECT_LT(error, 1e-9) << "dim " << dim << " P" << degree;
    }
}

// u = (sin(pi x) sin(pi y), 0) on the unit square, clamped on the boundary, plane strain,
// E = 1, nu = 0.3; f = -div sigma(u). The L2 error must fall as h^(k+1).
double manufacturedL2Error(int cells, int degree) {
  const double pi = M_PI, nu = 0.3, lambda = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1 / (2 * (1 + nu));
  Teuchos::ParameterList list = boxProblem(2, cells, degree);
  std::ostringstream fx, fy;
  fx.precision(17);
  fy.precision(17);
  fx << (lambda + 3 * mu) * pi * pi << "*sin(_pi*x)*sin(_pi*y)";
  fy << -(lambda + mu) * pi * pi << "*cos(_pi*x)*cos(_pi*y)";
  list.set("body force: x", fx.str());
  list.set("body force: y", fy.str());
  list.set("load: quadrature degree", 2 * degree + 6);
  for (const char* boundary : {"xmin", "xmax", "ymin", "ymax"}) {
    auto& bc = list.sublist("Dirichlet").sublist(boundary);
    bc.set("displacement: x", "0");
    bc.set("displacement: y", "0");
  }
  AssembledProblem p = buildProblem(list, Tpetra::getDefaultComm());
  Vector v(p.qp.Q->getDomainMap());
  EXPECT_GT(solveLinear(p.qp, p.multigrid, v, 1e-12), 0);
  const DistributedSpace& ds = distributedSpace(*p.space);
  Vector u(ds.overlapDofMap());
  u.doImport(v, Import(ds.ownedDofMap(), ds.overlapDofMap()), Tpetra::INSERT);
  auto ud = u.getData();
  std::vector<int> localIndex(ds.space().numNodes(), -1);
  for (std::size_t i = 0; i < ds.overlapSpaceNodes().size(); ++i) localIndex[ds.overlapSpaceNodes()[i]] = i;

  const QuadratureRule rule = simplexQuadrature(2, 2 * degree + 4);
  const LagrangeBasis& basis = ds.space().basis();
  std::vector<double> phi(basis.size());
  double coords[6], local = 0;
  for (long long cell = 0; cell < ds.mesh().numCells(); ++cell) {
    ds.mesh().cellVertexCoordinates(cell, coords);
    const double J[4] = {coords[2] - coords[0], coords[4] - coords[0], coords[3] - coords[1], coords[5] - coords[1]};
    const double det = std::abs(J[0] * J[3] - J[1] * J[2]);
    const long long* nodes = ds.space().cellNodes(cell);
    for (int q = 0; q < rule.size(); ++q) {
      const double* xi = &rule.points[2 * q];
      basis.values(xi, phi.data());
      const double x = coords[0] + J[0] * xi[0] + J[1] * xi[1], y = coords[1] + J[2] * xi[0] + J[3] * xi[1];
      double uh[2] = {0, 0};
      for (int i = 0; i < basis.size(); ++i)
        for (int c = 0; c < 2; ++c) uh[c] += phi[i] * ud[2 * localIndex[nodes[i]] + c];
      const double e0 = uh[0] - std::sin(pi * x) * std::sin(pi * y), e1 = uh[1];
      local += rule.weights[q] * det * (e0 * e0 + e1 * e1);
    }
  }
  double global = 0;
  Teuchos::reduceAll(*ds.comm(), Teuchos::REDUCE_SUM, 1, &local, &global);
  return std::sqrt(global);
}

TEST(ElasticityAssembler, ConvergesAtTheExpectedOrders) {
  for (int degree : {1, 2, 3}) {
    const int coarse = degree == 1 ? 16 : 8;
    const double e1 = manufacturedL2Error(coarse, degree), e2 = manufacturedL2Error(2 * coarse, degree);
    const double order = std::log2(e1 / e2);
    EXPECT_GT(order, degree + 1 - 0.15) << "P" << degree << ": errors " << e1 << ", " << e2;
    EXPECT_LT(order, degree + 1 + 0.5) << "P" << degree;
  }
}

TEST(ElasticityAssembler, ContactRowsAreMinusTheObstacleDirection) {
  AssembledProblem p = buildProblem(shippedProblem("paper/B"), Tpetra::getDefaultComm());
  // Each row of A is -n_o on one node: with n_o = e_z the row sums are -1 and A A^T = I.
  Vector ones(p.qp.A->getDomainMap()), rowSums(p.qp.A->getRangeMap());
  ones.putScalar(1.0);
  p.qp.A->apply(ones, rowSums);
  Vector minusOne(p.qp.A->getRangeMap());
  minusOne.putScalar(-1.0);
  rowSums.update(-1.0, minusOne, 1.0);
  EXPECT_EQ(rowSums.normInf(), 0.0);
  EXPECT_EQ(p.qp.d->normInf(), 0.0);
}

// Weighted gaps: row j is the integral of psi_j (-n_o . u) over the contact face, psi_j the
// multiplier function of contact node j, and d_j the integral of psi_j g. On the unit face
// of a box, for u = -n_o f with f linear (interpolated exactly by every degree), the rows
// sum to the integral of f, and for f = 1 each row is positive (its weight), P2 vertices of
// triangles included.
TEST(ElasticityAssembler, WeightedGapRowsIntegrateAgainstTheVertexHats) {
  for (const std::string formulation : {"weighted gap", "dual mortar"})
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      const std::string what = formulation + ", dim " + std::to_string(dim) + " P" + std::to_string(degree);
      const int cells = dim == 2 ? 5 : 3;
      Teuchos::ParameterList problem = signorini::testing::boxProblem(dim, cells, degree);
      problem.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");
      problem.sublist("Contact").set("gap: value", 0.25);
      problem.sublist("Contact").set("formulation", formulation);
      AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
      const ContactQP& qp = p.qp;
      const MultigridInput& mg = p.multigrid;
      EXPECT_EQ(qp.A->getGlobalNumRows(), static_cast<std::size_t>(std::pow(degree * cells + 1, dim - 1))) << what;

      // u = -n_o f: f = 1, then f = 1 + x (+ 2y), from the node coordinates.
      const int axis = dim - 1;  // n_o = e_axis
      Vector u(qp.A->getDomainMap()), rows(qp.A->getRangeMap());
      auto x = mg.coordinates;
      const auto setField = [&](bool linear) {
        auto data = u.getDataNonConst();
        for (std::size_t node = 0; node < x->getLocalLength(); ++node) {
          double f = 1.0;
          if (linear) f += x->getData(0)[node] + (dim == 3 ? 2.0 * x->getData(1)[node] : 0.0);
          for (int c = 0; c < dim; ++c) data[dim * node + c] = c == axis ? -f : 0.0;
        }
      };
      setField(false);
      qp.A->apply(u, rows);
      double localSmallest = std::numeric_limits<double>::infinity(), smallest = 0;
      for (double w : rows.getData()) localSmallest = std::min(localSmallest, w);
      Teuchos::reduceAll(*qp.A->getComm(), Teuchos::REDUCE_MIN, 1, &localSmallest, &smallest);
      EXPECT_GT(smallest, 0.0) << what;  // every constraint has a positive weight
      EXPECT_NEAR(rows.meanValue() * rows.getGlobalLength(), 1.0, 1e-12) << what;  // the face's measure
      Vector d(rows, Teuchos::Copy);  // d = 0.25 * the weights for a constant gap
      d.update(1.0, *qp.d, -0.25);
      EXPECT_LT(d.normInf(), 1e-14) << what;

      setField(true);
      qp.A->apply(u, rows);
      EXPECT_NEAR(rows.meanValue() * rows.getGlobalLength(), dim == 2 ? 1.5 : 2.5, 1e-12) << what;
    }
}

// The dual mortar basis is biorthogonal to the (transformed) displacement basis: row j holds
// contact node j's displacement alone (an edge node of a P2 triangle with the edge's two
// vertices: its transformed displacement), weighted by w_j, the integral of psi_j. For
// u = -n_o f with f linear, whose transformed coefficients are its nodal values, row j is
// w_j f(x_j): w_j times the nodal constraint's row, numbered alike.
TEST(ElasticityAssembler, DualMortarRowsAreWeightedNodalRows) {
  for (int dim : {2, 3})
    for (int degree : {1, 2, 3}) {
      const std::string what = "dim " + std::to_string(dim) + " P" + std::to_string(degree);
      Teuchos::ParameterList problem = signorini::testing::boxProblem(dim, dim == 2 ? 5 : 3, degree);
      problem.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");
      problem.sublist("Contact").set("formulation", "dual mortar");
      AssembledProblem dual = buildProblem(problem, Tpetra::getDefaultComm());
      problem.sublist("Contact").set("formulation", "nodal");
      AssembledProblem nodal = buildProblem(problem, Tpetra::getDefaultComm());
      const std::size_t nodesPerRow = dim == 3 && degree == 2 ? 3 : 1;
      EXPECT_EQ(dual.qp.A->getGlobalMaxNumRowEntries(), nodesPerRow) << what;

      const int axis = dim - 1;
      Vector u(dual.qp.A->getDomainMap()), weights(dual.qp.A->getRangeMap()), rows(weights.getMap()),
          nodalRows(weights.getMap());
      auto x = dual.multigrid.coordinates;
      const auto setField = [&](bool linear) {
        auto data = u.getDataNonConst();
        for (std::size_t node = 0; node < x->getLocalLength(); ++node) {
          const double f = linear ? 1.0 + x->getData(0)[node] + (dim == 3 ? 2.0 * x->getData(1)[node] : 0.0) : 1.0;
          for (int c = 0; c < dim; ++c) data[dim * node + c] = c == axis ? -f : 0.0;
        }
      };
      setField(false);
      dual.qp.A->apply(u, weights);
      EXPECT_GT(minOverRanks(*u.getMap()->getComm(), [&] {
                  double smallest = std::numeric_limits<double>::infinity();
                  for (double w : weights.getData()) smallest = std::min(smallest, w);
                  return smallest;
                }()), 0.0) << what;
      setField(true);
      dual.qp.A->apply(u, rows);
      nodal.qp.A->apply(u, nodalRows);
      rows.elementWiseMultiply(-1.0, weights, nodalRows, 1.0);
      EXPECT_LT(rows.normInf(), 1e-13) << what;
    }
}

// An expression that is not finite somewhere in the domain is an input error naming the
// parameter, the expression and a point, on every rank that meets it.
TEST(ElasticityAssembler, NonFiniteExpressionsAreInputErrors) {
  Teuchos::ParameterList problem = signorini::testing::boxProblem(2, 4, 1);
  problem.set("body force: y", "sqrt(-1-x)");
  try {
    buildProblem(problem, Tpetra::getDefaultComm());
    ADD_FAILURE() << "a NaN body force was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("body force: y"), std::string::npos) << message;
    EXPECT_NE(message.find("sqrt(-1-x)"), std::string::npos) << message;
    EXPECT_NE(message.find("not a number at ("), std::string::npos) << message;
  }
  // An expression whose singularity lies outside the domain is accepted.
  problem.set("body force: y", "1/(x+1)");
  EXPECT_NO_THROW(buildProblem(problem, Tpetra::getDefaultComm()));
}

// A contact node whose displacement towards the obstacle is prescribed: accepted while the
// prescribed displacement leaves its gap open, refused (every rank, both formulations) where
// it closes or crosses it.
TEST(ElasticityAssembler, PrescribedContactNodesMustLeaveTheGapOpen) {
  for (const char* formulation : {"nodal", "weighted gap"}) {
    Teuchos::ParameterList problem = contactBoxProblem(2, 3);
    problem.sublist("Contact").set("formulation", formulation);
    auto& bottom = problem.sublist("Dirichlet").sublist("ymin");
    bottom.set("displacement: y", "0.1");  // lifted off the plane: the gap opens
    EXPECT_NO_THROW(buildProblem(problem, Tpetra::getDefaultComm())) << formulation;
    for (const char* closing : {"0", "-0.1*(1+x)"}) {
      bottom.set("displacement: y", closing);
      try {
        buildProblem(problem, Tpetra::getDefaultComm());
        ADD_FAILURE() << formulation << ": prescribed u_y = " << closing << " on the contact boundary was accepted";
      } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("Problem/Contact: 4 node(s) of the contact boundary \"ymin\""), std::string::npos)
            << message;
        EXPECT_NE(message.find(closing[0] == '0' ? "g + n.u = 0" : "g + n.u = -0."), std::string::npos) << message;
      }
    }
  }
}

}  // namespace
