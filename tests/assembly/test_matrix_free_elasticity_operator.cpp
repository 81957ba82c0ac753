// The matrix-free stiffness applies the assembled Q to round-off: P1-P3, 2D and 3D, with
// prescribed DOFs, several vectors at once, and the alpha/beta contract; its diagonal, its
// prescribed DOFs and its selected rows are the assembled ones; the paper's problems and P2/P3
// boxes (with no Q assembled at all) solved with it reach the assembled path's optimal values.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "assembly/ElasticityAssembler.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemParameters.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/ActiveSetReference.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// A box clamped on one face, with a nonzero displacement prescribed on the opposite one.
Teuchos::ParameterList clampedBox(int dim, int degree) {
  Teuchos::ParameterList p = boxProblem(dim, dim == 2 ? 5 : 3, degree);
  p.set("material: poisson ratio", 0.3);
  Teuchos::ParameterList& clamped = p.sublist("Dirichlet").sublist("xmin");
  Teuchos::ParameterList& pulled = p.sublist("Dirichlet").sublist("xmax");
  for (const char* c : {"x", "y", "z"})
    if (c[0] != 'z' || dim == 3) clamped.set(std::string("displacement: ") + c, "0");
  pulled.set("displacement: x", "0.01*y");
  return p;
}

struct Case {
  int dim, degree;
};

class MatrixFreeElasticityOperatorTest : public ::testing::TestWithParam<Case> {};

TEST_P(MatrixFreeElasticityOperatorTest, AppliesTheAssembledStiffness) {
  const Case k = GetParam();
  auto comm = Tpetra::getDefaultComm();
  AssembledProblem problem = buildProblem(clampedBox(k.dim, k.degree), comm);
  const RCP<MatrixFreeElasticityOperator> Q = matrixFreeStiffness(distributedSpace(problem.space), problem.definition);
  const CrsMatrix& K = *assembledStiffness(problem.qp, problem.multigrid);
  ASSERT_TRUE(Q->getDomainMap()->isSameAs(*K.getDomainMap()));
  ASSERT_TRUE(Q->getRangeMap()->isSameAs(*K.getRangeMap()));

  MultiVector X(K.getDomainMap(), 3), expected(K.getRangeMap(), 3), got(K.getRangeMap(), 3);
  X.randomize();
  K.apply(X, expected);
  Q->apply(X, got);
  std::vector<double> error(3), scale(3);
  got.update(-1.0, expected, 1.0);
  got.normInf(error);
  expected.normInf(scale);
  for (int j = 0; j < 3; ++j) EXPECT_LT(error[j], 1e-13 * scale[j]) << "vector " << j;

  // Y = beta Y + alpha Q X, with Y's old values kept.
  MultiVector Y(K.getRangeMap(), 3), reference(K.getRangeMap(), 3);
  Y.randomize();
  reference.assign(Y);
  K.apply(X, reference, Teuchos::NO_TRANS, -0.5, 2.0);
  Q->apply(X, Y, Teuchos::NO_TRANS, -0.5, 2.0);
  Y.update(-1.0, reference, 1.0);
  Y.normInf(error);
  reference.normInf(scale);
  for (int j = 0; j < 3; ++j) EXPECT_LT(error[j], 1e-13 * scale[j]) << "alpha/beta, vector " << j;
  EXPECT_GT(Q->bytes(), 0u);
}

TEST_P(MatrixFreeElasticityOperatorTest, DiagonalIsTheAssembledOne) {
  const Case k = GetParam();
  AssembledProblem problem = buildProblem(clampedBox(k.dim, k.degree), Tpetra::getDefaultComm());
  const RCP<MatrixFreeElasticityOperator> Q = matrixFreeStiffness(distributedSpace(problem.space), problem.definition);
  const CrsMatrix& K = *assembledStiffness(problem.qp, problem.multigrid);
  Vector expected(K.getRowMap()), got(K.getRowMap());
  K.getLocalDiagCopy(expected);
  Q->getLocalDiagCopy(got);
  const double scale = expected.normInf();
  got.update(-1.0, expected, 1.0);
  EXPECT_LT(got.normInf(), 1e-13 * scale);
}

TEST_P(MatrixFreeElasticityOperatorTest, SelectedRowsAndPrescribedDofsAreTheAssembledOnes) {
  const Case k = GetParam();
  AssembledProblem problem = buildProblem(clampedBox(k.dim, k.degree), Tpetra::getDefaultComm());
  const RCP<MatrixFreeElasticityOperator> Q = matrixFreeStiffness(distributedSpace(problem.space), problem.definition);
  const CrsMatrix& K = *assembledStiffness(problem.qp, problem.multigrid);
  EXPECT_EQ(Q->prescribedDofs(), prescribedRows(K));

  // Every third DOF: rows of free and prescribed DOFs, owned next to other ranks' DOFs.
  Vector selected(K.getRowMap());
  {
    auto s = selected.getDataNonConst();
    for (std::size_t i = 0; i < selected.getLocalLength(); ++i) s[i] = K.getRowMap()->getGlobalElement(i) % 3 == 0;
  }
  const RCP<const CrsMatrix> rows = Q->selectedRows(selected);
  ASSERT_TRUE(rows->getRowMap()->isSameAs(*K.getRowMap()));
  Vector x(K.getDomainMap()), expected(K.getRangeMap()), got(K.getRangeMap());
  x.randomize();
  K.apply(x, expected);
  expected.elementWiseMultiply(1.0, selected, expected, 0.0);
  rows->apply(x, got);
  got.update(-1.0, expected, 1.0);
  EXPECT_LT(got.normInf(), 1e-13 * expected.normInf());
  std::size_t entries = 0;  // the other rows are empty
  for (std::size_t i = 0; i < rows->getNodeNumRows(); ++i)
    if (selected.getData()[i] == 0.0) entries += rows->getNumEntriesInLocalRow(static_cast<LocalOrdinal>(i));
  EXPECT_EQ(entries, 0u);
}

INSTANTIATE_TEST_SUITE_P(Degrees, MatrixFreeElasticityOperatorTest,
                         ::testing::Values(Case{2, 1}, Case{2, 2}, Case{2, 3}, Case{3, 1}, Case{3, 2}, Case{3, 3}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::to_string(info.param.dim) + "D_P" + std::to_string(info.param.degree);
                         });

TEST(MatrixFreeElasticityOperator, SolvesThePaperProblemsToTheAssembledOptimalValues) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* name : {"A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M"}) {
    Teuchos::ParameterList definition = shippedProblem(std::string("paper/") + name);
    definition.set("stiffness: operator", "assembled");
    const AssembledProblem assembled = buildProblem(definition, comm);
    definition.set("stiffness: operator", "matrix-free");
    const AssembledProblem matrixFree = buildProblem(definition, comm);
    ASSERT_TRUE(Teuchos::rcp_dynamic_cast<const MatrixFreeElasticityOperator>(matrixFree.qp.Q) != Teuchos::null);
    const SolveResult a = InteriorPointSolver(Teuchos::ParameterList()).solve(assembled.qp, assembled.multigrid);
    const SolveResult f = InteriorPointSolver(Teuchos::ParameterList()).solve(matrixFree.qp, matrixFree.multigrid);
    ASSERT_TRUE(a.converged() && f.converged()) << name;
    EXPECT_NEAR(f.objective, a.objective, 1e-9 * std::fabs(a.objective)) << name;
    EXPECT_LE(std::abs(f.outerIterations - a.outerIterations), 1) << name;
  }
}

// A P2 or P3 box, matrix-free: no Q is assembled (the geometric multigrid starts from the
// mesh's P1 stiffness, the contact correction from Q's contact rows), and the solve reaches
// the assembled path's optimal value with about as many CG iterations.
TEST(MatrixFreeElasticityOperator, SolvesP2AndP3BoxesWithoutAssemblingQ) {
  auto comm = Tpetra::getDefaultComm();
  for (const Case k : {Case{2, 2}, Case{2, 3}, Case{3, 2}, Case{3, 3}}) {
    const std::string name = std::to_string(k.dim) + "D P" + std::to_string(k.degree);
    Teuchos::ParameterList definition = contactBoxProblem(k.dim, k.dim == 2 ? 12 : 4);
    definition.set("element: degree", k.degree);
    definition.set("body force: " + std::string(k.dim == 2 ? "y" : "z"), "-0.05");
    const AssembledProblem assembled = buildProblem(definition, comm);
    definition.set("stiffness: operator", "matrix-free");
    const AssembledProblem matrixFree = buildProblem(definition, comm);
    EXPECT_TRUE(assembledStiffness(matrixFree.qp, matrixFree.multigrid).is_null()) << name;
    ASSERT_FALSE(matrixFree.multigrid.gridStiffness.is_null()) << name;
    const SolveResult a = InteriorPointSolver(Teuchos::ParameterList()).solve(assembled.qp, assembled.multigrid);
    const SolveResult f = InteriorPointSolver(Teuchos::ParameterList()).solve(matrixFree.qp, matrixFree.multigrid);
    ASSERT_TRUE(a.converged() && f.converged()) << name;
    EXPECT_NEAR(f.objective, a.objective, 1e-9 * std::fabs(a.objective)) << name;
    EXPECT_LE(f.krylovIterations, 1.5 * a.krylovIterations) << name;
  }
}

// The QP of a matrix-free problem stays valid once the problem is gone: Q shares the space.
// Its solution is that of the active-set reference on the assembled stiffness.
TEST(MatrixFreeElasticityOperator, OutlivesTheProblem) {
  Teuchos::ParameterList definition = contactBoxProblem(2, 6);
  definition.set("element: degree", 2);
  definition.set("body force: y", "-0.05");
  definition.set("stiffness: operator", "matrix-free");
  const AssembledProblem problem = buildProblem(definition, Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  const SolveResult r = InteriorPointSolver(Teuchos::ParameterList()).solve(qp, problem.multigrid);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_LT(differenceToReference(definition, problem.multigrid, *r.v), 1e-7);
}

// Preconditioners that would need Q assembled are refused with a message, not run.
TEST(MatrixFreeElasticityOperator, RefusesAnAlgebraicHierarchyWithoutQ) {
  Teuchos::ParameterList definition = contactBoxProblem(2, 6);
  definition.set("element: degree", 2);
  definition.set("stiffness: operator", "matrix-free");
  const AssembledProblem problem = buildProblem(definition, Tpetra::getDefaultComm());
  Teuchos::ParameterList solver;
  solver.sublist("Preconditioner").set("hierarchy", "algebraic");
  EXPECT_THROW(InteriorPointSolver(solver).solve(problem.qp, problem.multigrid), InputError);
}

}  // namespace
