// The geometric multigrid of box meshes: its levels, its interpolation (exact for linear
// fields that satisfy the Dirichlet conditions), and CG counts that do not grow with the
// mesh, on every rank count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <TpetraExt_MatrixMatrix.hpp>
#include <TpetraExt_TripleMatrixMultiply.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/ElasticityAssembler.hpp"
#include "fe/BoxGrid.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/linear/KrylovSolver.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"
#include "solver/preconditioner/JacobiEigenvalueEstimate.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// Linear elasticity on the unit box, clamped on its top face (or free), no contact.
AssembledProblem box(int dim, int cells, int degree, bool clamped = true) {
  Teuchos::ParameterList p = boxProblem(dim, cells, degree);
  if (clamped) {
    Teuchos::ParameterList& top = p.sublist("Dirichlet").sublist(dim == 2 ? "ymax" : "zmax");
    for (const char* c : {"x", "y", "z"})
      if (c[0] != 'z' || dim == 3) top.set(std::string("displacement: ") + c, "0");
  }
  return buildProblem(p, Tpetra::getDefaultComm());
}

// `directSolveSize` 0: MueLu below the coarsest grid; the levels end at the first grid with at
// most `directSolveSize` unknowns.
GeometricMultigridPreconditioner multigrid(const ContactQP& qp, const MultigridInput& mg, long long coarsestSize = 200,
                                           int eigenvalueUpdateSteps = 3, long long directSolveSize = 100) {
  return GeometricMultigridPreconditioner(*mg.grid, assembledStiffness(qp, mg)->getRowMap(),
                                          prescribedRows(*assembledStiffness(qp, mg)),
                                          *mg.coordinates, mg.blockSize, coarsestSize, directSolveSize,
                                          Teuchos::ParameterList(), Teuchos::ParameterList(), eigenvalueUpdateSteps);
}

// Every coarse matrix of `got` applies that of `expected` to 1e-12, on a random vector.
void expectSameCoarseMatrices(const GeometricMultigridPreconditioner& got,
                              const GeometricMultigridPreconditioner& expected, const std::string& label) {
  ASSERT_EQ(got.geometricLevels(), expected.geometricLevels()) << label;
  for (int l = 1; l <= expected.geometricLevels(); ++l) {
    Vector x(expected.levelMatrix(l)->getDomainMap()), a(x.getMap()), b(x.getMap());
    x.randomize();
    got.levelMatrix(l)->apply(x, a);
    expected.levelMatrix(l)->apply(x, b);
    a.update(-1.0, b, 1.0);
    EXPECT_LT(a.norm2(), 1e-12 * b.norm2()) << label << ", level " << l;
  }
}

// A box clamped on its top face with contact on its bottom one, and the Hessians
// H = Q + A^T D A of a barrier whose weights D, as mu falls, vanish on some constraints and
// grow by orders of magnitude on others.
Teuchos::ParameterList withConstraints(Teuchos::ParameterList problem, const std::string& constraints) {
  problem.sublist("Contact").set("formulation", constraints);
  return problem;
}

struct ContactBox {
  ContactBox(int dim, int cells, const std::string& constraints = "auto")
      : problem(buildProblem(withConstraints(contactBoxProblem(dim, cells), constraints), Tpetra::getDefaultComm())),
        H(problem.qp.Q, problem.qp.A) {}
  // Step k: weights 10^(2k - 6 + (g % 5) / 2) times Q's largest diagonal entry on the
  // constraints g (their ids) with g % 3 != 0, and on all from step 6 on; 10^-2k before that.
  RCP<CrsMatrix> hessian(int step) {
    H.setWeights(weights(step));
    return H.assemble();
  }
  Vector weights(int step) {
    Vector diagonal(problem.qp.Q->getRangeMap()), D(problem.qp.A->getRangeMap());
    assembledStiffness(problem.qp, problem.multigrid)->getLocalDiagCopy(diagonal);
    const double scale = diagonal.normInf();
    auto d = D.getDataNonConst();
    for (std::size_t i = 0; i < D.getLocalLength(); ++i) {
      const GlobalOrdinal g = D.getMap()->getGlobalElement(i);
      const bool active = g % 3 != 0 || step >= 6;
      d[i] = scale * std::pow(10.0, active ? 2.0 * step - 6 + 0.5 * static_cast<double>(g % 5) : -2.0 * step);
    }
    return D;
  }
  // What computeForSum() takes at a step: H's weights set, C = A^T D A and diag(Q) + diag(C).
  struct Sum {
    RCP<const CrsMatrix> C;
    Vector diagonal;
  };
  Sum sum(int step, const Vector& diagonalOfQ) {
    const Vector D = weights(step);
    H.setWeights(D);
    Sum s{H.contactTerm(D), Vector(diagonalOfQ.getMap())};
    s.C->getLocalDiagCopy(s.diagonal);
    s.diagonal.update(1.0, diagonalOfQ, 1.0);
    return s;
  }
  AssembledProblem problem;
  BarrierHessianOperator H;
};

TEST(GeometricMultigrid, LevelsFollowTheGrids) {
  // 2D P1, 16 cells: grids of 16, 8, 4 cells; the 2-cell grid (18 unknowns) is below 50.
  EXPECT_EQ(multigrid(box(2, 16, 1).qp, box(2, 16, 1).multigrid, 50, 5, 0).levelSizes(), (std::vector<long long>{578, 162, 50}));
  // P2 goes to P1 on its own mesh first.
  EXPECT_EQ(multigrid(box(2, 4, 2).qp, box(2, 4, 2).multigrid, 20, 5, 0).levelSizes(), (std::vector<long long>{162, 50}));
  EXPECT_EQ(multigrid(box(3, 4, 1).qp, box(3, 4, 1).multigrid, 20, 5, 0).levelSizes(), (std::vector<long long>{375, 81, 24}));
  // An odd count coarsens too: 5 cells, then 3 (boxes of widths 2/5, 2/5 and 1/5), 2 and 1.
  EXPECT_EQ(multigrid(box(2, 5, 1).qp, box(2, 5, 1).multigrid, 1, 5, 0).levelSizes(), (std::vector<long long>{72, 32, 18, 8}));
  EXPECT_EQ(multigrid(box(3, 3, 1).qp, box(3, 3, 1).multigrid, 20, 5, 0).levelSizes(), (std::vector<long long>{192, 81, 24}));
  // The first grid the direct solver takes is the last.
  EXPECT_EQ(multigrid(box(2, 16, 1).qp, box(2, 16, 1).multigrid, 50, 5, 162).levelSizes(), (std::vector<long long>{578, 162}));
  EXPECT_EQ(multigrid(box(2, 16, 1).qp, box(2, 16, 1).multigrid, 50, 5, 161).levelSizes(), (std::vector<long long>{578, 162, 50}));
}

// P u_c = u at every fine DOF for a linear field u that vanishes on the clamped face (and
// for every linear field on a free box): the coarse spaces hold the fields they should.
TEST(GeometricMultigrid, InterpolationIsExactForLinearFields) {
  struct Case {
    int dim, cells, degree;
    bool clamped;
  };
  for (const Case& c : {Case{2, 8, 1, true}, Case{2, 4, 2, true}, Case{2, 4, 3, false}, Case{3, 4, 1, true},
                        Case{3, 4, 2, false}, Case{2, 7, 1, true}, Case{3, 3, 1, false}}) {
    const AssembledProblem problem = box(c.dim, c.cells, c.degree, c.clamped);
    const ContactQP& qp = problem.qp;
    const MultigridInput& mg = problem.multigrid;
    const GeometricMultigridPreconditioner gmg = multigrid(qp, mg, 1);
    ASSERT_GE(gmg.geometricLevels(), 1);
    // The field: u_a(x) = (1 - x_top) (a + 1 + x_0 - 2 x_1) when clamped, (a + 1 + x_0 - 2 x_1 + 3 x_top) when free.
    auto field = [&](const double* x, int a) {
      const double top = x[c.dim - 1], linear = a + 1 + x[0] - 2 * x[1];
      return c.clamped ? (1.0 - top) * (a + 1) : linear + 3 * top;
    };
    RCP<const CrsMatrix> P = gmg.prolongator(0);
    const auto coarse = c.degree == 1 ? mg.grid->coarser() : mg.grid;
    Vector uc(P->getDomainMap()), u(P->getRangeMap());
    {
      auto d = uc.getDataNonConst();
      for (std::size_t k = 0; k < uc.getLocalLength(); ++k) {
        const GlobalOrdinal dof = P->getDomainMap()->getGlobalElement(k);
        double x[3];
        coarse->vertexCoordinates(dof / mg.blockSize, x);
        d[k] = field(x, static_cast<int>(dof % mg.blockSize));
      }
    }
    P->apply(uc, u);
    auto ud = u.getData();
    double worst = 0.0;
    for (std::size_t i = 0; i < mg.coordinates->getLocalLength(); ++i) {
      double x[3];
      for (int a = 0; a < c.dim; ++a) x[a] = mg.coordinates->getData(a)[i];
      for (int a = 0; a < c.dim; ++a) worst = std::max(worst, std::abs(ud[c.dim * i + a] - field(x, a)));
    }
    EXPECT_LT(worst, 1e-12) << c.dim << "D P" << c.degree << " nx " << c.cells;
  }
}

// CG preconditioned by one V-cycle on a random right-hand side to 1e-8.
KrylovResult solve(const ContactQP& qp, const MultilevelPreconditioner& M) {
  auto b = rcp(new Vector(qp.Q->getRangeMap()));
  b->randomize();
  auto x = rcp(new Vector(qp.Q->getDomainMap()));
  const KrylovResult r = KrylovSolver().solve(qp.Q, M.getOperator(), b, x, 1e-8, 200);
  Vector residual(*b, Teuchos::Copy);
  qp.Q->apply(*x, residual, Teuchos::NO_TRANS, -1.0, 1.0);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(residual.norm2(), 1.0001e-8 * b->norm2()) << "the residual Belos reported is not the true one";
  return r;
}

// The counts stay put as the mesh is refined (14-15 in 2D, 10 in 3D on 1-3 ranks), where
// smoothed aggregation alone needs more on the finest mesh.
TEST(GeometricMultigrid, CgCountsDoNotGrowWithTheMesh) {
  struct Case {
    int dim, cells, degree, levels, maxIterations;
  };
  for (const Case& c : {Case{2, 32, 1, 1, 16}, Case{2, 64, 1, 2, 16}, Case{2, 16, 2, 1, 16}, Case{3, 8, 1, 1, 11},
                        Case{3, 16, 1, 2, 11}}) {
    const AssembledProblem problem = box(c.dim, c.cells, c.degree);
    GeometricMultigridPreconditioner gmg = multigrid(problem.qp, problem.multigrid, 200, 5, 1000);
    gmg.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid)));
    EXPECT_EQ(gmg.geometricLevels(), c.levels);
    EXPECT_TRUE(gmg.directCoarsestSolve());
    const KrylovResult r = solve(problem.qp, gmg);
    EXPECT_LE(r.iterations, c.maxIterations) << c.dim << "D P" << c.degree << " nx " << c.cells;
    if (c.dim == 2 && c.cells == 64) {
      MueLuPreconditioner amg(Teuchos::ParameterList(), problem.multigrid.blockSize, problem.multigrid.nearNullspace(problem.qp),
                              problem.multigrid.coordinates);
      amg.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid)));
      EXPECT_GT(solve(problem.qp, amg).iterations, r.iterations + 2) << "smoothed aggregation alone";
    }
  }
}

// x^T M y = y^T M x: CG needs a symmetric preconditioner, with either coarsest solve.
TEST(GeometricMultigrid, CycleIsSymmetric) {
  const AssembledProblem problem = box(3, 8, 1);
  for (long long directSolveSize : {0, 100}) {
    GeometricMultigridPreconditioner gmg = multigrid(problem.qp, problem.multigrid, 50, 5, directSolveSize);
    gmg.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid)));
    ASSERT_EQ(gmg.geometricLevels(), 2);
    EXPECT_EQ(gmg.directCoarsestSolve(), directSolveSize > 0);
    Vector x(problem.qp.Q->getDomainMap()), y(x.getMap()), Mx(x.getMap()), My(x.getMap());
    x.randomize();
    y.randomize();
    gmg.getOperator()->apply(x, Mx);
    gmg.getOperator()->apply(y, My);
    EXPECT_NEAR(y.dot(Mx), x.dot(My), 1e-11 * std::abs(y.dot(Mx))) << "direct solve size " << directSolveSize;
    EXPECT_GT(x.dot(Mx), 0.0);
  }
}

// The coarsest grid is factored when it has at most "direct solve size" unknowns: with no
// geometric level below the fine one, the cycle is then Q^-1 itself.
TEST(GeometricMultigrid, SmallCoarsestGridIsSolvedExactly) {
  const AssembledProblem problem = box(2, 5, 1);  // the 3-cell grid (32 unknowns) is below 40: one level
  const ContactQP& qp = problem.qp;
  const MultigridInput& mg = problem.multigrid;
  EXPECT_FALSE(multigrid(qp, mg, 40, 5, 71).directCoarsestSolve());  // 72 unknowns
  GeometricMultigridPreconditioner gmg = multigrid(qp, mg, 40, 5, 72);
  ASSERT_EQ(gmg.geometricLevels(), 0);
  ASSERT_TRUE(gmg.directCoarsestSolve());
  gmg.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(qp, mg)));
  Vector x(qp.Q->getDomainMap()), Qx(x.getMap()), MQx(x.getMap());
  x.randomize();
  qp.Q->apply(x, Qx);
  gmg.getOperator()->apply(Qx, MQx);
  MQx.update(-1.0, x, 1.0);
  EXPECT_LT(MQx.norm2(), 1e-10 * x.norm2());
}

// The level matrices of `a` and `b` act alike, and so do their cycles.
void expectTheSameLevels(const GeometricMultigridPreconditioner& a, const GeometricMultigridPreconditioner& b,
                         const std::string& label) {
  ASSERT_EQ(a.geometricLevels(), b.geometricLevels()) << label;
  for (int l = 1; l <= a.geometricLevels(); ++l) {
    const CrsMatrix &A = *a.levelMatrix(l), &B = *b.levelMatrix(l);
    ASSERT_EQ(A.getGlobalNumEntries(), B.getGlobalNumEntries()) << label << " level " << l;
    Vector x(A.getDomainMap()), ax(A.getRangeMap()), bx(A.getRangeMap());
    x.randomize();
    A.apply(x, ax);
    B.apply(x, bx);
    ax.update(-1.0, bx, 1.0);
    EXPECT_LT(ax.norm2(), 1e-12 * bx.norm2()) << label << " level " << l;
    EXPECT_GT(bx.norm2(), 0.0);
  }
  // The same smoothers and coarse solve.
  Vector x(a.levelMatrix(0)->getDomainMap()), Ax(x.getMap()), Bx(x.getMap());
  x.randomize();
  a.getOperator()->apply(x, Ax);
  b.getOperator()->apply(x, Bx);
  Ax.update(-1.0, Bx, 1.0);
  EXPECT_LT(Ax.norm2(), 1e-9 * Bx.norm2()) << label;
}

// Between Newton steps only A^T D A changes; the coarse matrices are then updated in place
// with the Galerkin products of the change, and must equal the products of the new matrix.
TEST(GeometricMultigrid, UpdatedCoarseMatricesEqualFreshProducts) {
  for (int dim : {2, 3}) {
    ContactBox box(dim, dim == 2 ? 16 : 8);
    const ContactQP& qp = box.problem.qp;
    const MultigridInput& mg = box.problem.multigrid;
    // Fresh eigenvalue estimates at every build, so that the cycles can be compared below.
    GeometricMultigridPreconditioner updated = multigrid(qp, mg, 50, 0);
    ASSERT_GE(updated.geometricLevels(), 2);
    updated.compute(box.hessian(0));
    const RCP<const CrsMatrix> firstCoarse = updated.levelMatrix(1);
    const RCP<CrsMatrix> H2 = box.hessian(2);
    updated.compute(H2);
    EXPECT_EQ(updated.levelMatrix(1).get(), firstCoarse.get()) << dim << "D: not updated in place";
    GeometricMultigridPreconditioner fresh = multigrid(qp, mg, 50);
    fresh.compute(H2);
    expectTheSameLevels(updated, fresh, std::to_string(dim) + "D");

    // The same through update(): H changed in place, with the change that
    // BarrierHessianOperator reports, instead of a new matrix compared with the last one.
    GeometricMultigridPreconditioner inPlace = multigrid(qp, mg, 50, 0);
    const RCP<CrsMatrix> H = box.hessian(0);
    inPlace.compute(H);
    const RCP<const CrsMatrix> inPlaceCoarse = inPlace.levelMatrix(1);
    const RCP<CrsMatrix> change = box.H.updateAssembled(*H, box.weights(2));
    inPlace.update(H, *change);
    EXPECT_EQ(inPlace.levelMatrix(0).get(), H.get());
    EXPECT_EQ(inPlace.levelMatrix(1).get(), inPlaceCoarse.get()) << dim << "D: not updated in place";
    expectTheSameLevels(inPlace, fresh, std::to_string(dim) + "D, update()");

    // A fine matrix on another graph is not an update: the levels are computed afresh.
    updated.compute(Tpetra::MatrixMatrix::add(1.0, false, *H2, 0.0, false, *assembledStiffness(qp, mg)));
    EXPECT_NE(updated.levelMatrix(1).get(), firstCoarse.get()) << dim << "D";
  }
}

// Below a coarsest grid too large to factor, MueLu's levels kept in the cycle
// (keepAlgebraicLevels): set up at the first build, then updated in place with the
// Galerkin products of the changed rows, so that every level's matrix is P^T A P of the one
// above for the new H; the cycle stays symmetric and CG with it converges on H. After
// refreshAlgebraicLevels() the next build sets them up anew.
TEST(GeometricMultigrid, KeptAlgebraicLevelsFollowTheChangedRows) {
  for (int dim : {2, 3}) {
    const std::string label = std::to_string(dim) + "D";
    // Coarsest grids of 162 (2D) and 375 (3D) unknowns, which MueLu coarsens below its 100.
    ContactBox box(dim, dim == 2 ? 32 : 8);
    GeometricMultigridPreconditioner gmg = multigrid(box.problem.qp, box.problem.multigrid, dim == 2 ? 150 : 300, 3, 0);
    ASSERT_FALSE(gmg.directCoarsestSolve()) << label;
    gmg.keepAlgebraicLevels();
    ASSERT_TRUE(gmg.keepsAlgebraicLevels());
    gmg.compute(box.hessian(0));
    const int grids = gmg.geometricLevels(), algebraic = gmg.algebraicLevels();
    ASSERT_GE(algebraic, 1) << label;
    const RCP<const CrsMatrix> firstAlgebraic = gmg.levelMatrix(grids + 1);
    const RCP<CrsMatrix> H = box.hessian(4);
    gmg.compute(H);
    EXPECT_EQ(gmg.algebraicLevels(), algebraic) << label;
    EXPECT_EQ(gmg.levelMatrix(grids + 1).get(), firstAlgebraic.get()) << label << ": not updated in place";
    for (int l = grids; l < grids + algebraic; ++l) {
      CrsMatrix product(gmg.prolongator(l)->getDomainMap(), 0);
      Tpetra::TripleMatrixMultiply::MultiplyRAP(*gmg.prolongator(l), true, *gmg.levelMatrix(l), false,
                                                *gmg.prolongator(l), false, product);
      Vector x(product.getDomainMap()), a(x.getMap()), b(x.getMap());
      x.randomize();
      gmg.levelMatrix(l + 1)->apply(x, a);
      product.apply(x, b);
      a.update(-1.0, b, 1.0);
      EXPECT_LT(a.norm2(), 1e-12 * b.norm2()) << label << ", level " << l + 1;
    }
    Vector x(H->getDomainMap()), y(x.getMap()), Mx(x.getMap()), My(x.getMap());
    x.randomize();
    y.randomize();
    gmg.getOperator()->apply(x, Mx);
    gmg.getOperator()->apply(y, My);
    EXPECT_NEAR(y.dot(Mx), x.dot(My), 1e-11 * std::abs(y.dot(Mx))) << label;
    auto b = rcp(new Vector(H->getRangeMap())), v = rcp(new Vector(H->getDomainMap()));
    b->randomize();
    EXPECT_TRUE(KrylovSolver().solve(H, gmg.getOperator(), b, v, 1e-8, 200).converged) << label;

    gmg.refreshAlgebraicLevels();
    gmg.compute(box.hessian(6));
    EXPECT_GE(gmg.algebraicLevels(), 1) << label;
    EXPECT_NE(gmg.levelMatrix(grids + 1).get(), firstAlgebraic.get()) << label << ": not set up anew";
  }
}

// The fine level left the operator Q + C (computeForSum, C = A^T D A) gives the hierarchy
// of the assembled Q + C: the same coarse matrices and the same cycle (its fine smoother is
// the same polynomial, applied through the operator), also after C changes, when the first
// coarse matrix is updated in place with the product of the change.
TEST(GeometricMultigrid, FineOperatorGivesTheHierarchyOfTheAssembledSum) {
  for (int dim : {2, 3}) {
    ContactBox box(dim, dim == 2 ? 16 : 8);
    const ContactQP& qp = box.problem.qp;
    const MultigridInput& mg = box.problem.multigrid;
    Vector diagonalOfQ(qp.Q->getRangeMap());
    assembledStiffness(qp, mg)->getLocalDiagCopy(diagonalOfQ);
    // Fresh eigenvalue estimates at every build, so that the cycles can be compared.
    GeometricMultigridPreconditioner sum = multigrid(qp, mg, 50, 0);
    ASSERT_GE(sum.geometricLevels(), 2);
    sum.setFineStiffness(assembledStiffness(qp, mg));
    RCP<const CrsMatrix> firstCoarse;
    for (int step : {0, 2, 7}) {
      const std::string label = std::to_string(dim) + "D step " + std::to_string(step);
      const ContactBox::Sum terms = box.sum(step, diagonalOfQ);
      sum.computeForSum(Teuchos::rcpFromRef(box.H), terms.diagonal, terms.C);
      if (firstCoarse.is_null()) firstCoarse = sum.levelMatrix(1);
      EXPECT_EQ(sum.levelMatrix(1).get(), firstCoarse.get()) << label << ": not updated in place";
      GeometricMultigridPreconditioner assembled = multigrid(qp, mg, 50, 0);
      assembled.compute(box.H.assemble());
      expectSameCoarseMatrices(sum, assembled, label);
      Vector x(qp.Q->getDomainMap()), a(x.getMap()), b(x.getMap());
      x.randomize();
      sum.getOperator()->apply(x, a);
      assembled.getOperator()->apply(x, b);
      a.update(-1.0, b, 1.0);
      EXPECT_LT(a.norm2(), 1e-9 * b.norm2()) << label;
    }
  }
}

// levelNonzeros counts each level's matrix: the fine one given to compute() (Q's, for a fine
// level given as the operator Q + C), the Galerkin products, and MueLu's coarser levels where
// MueLu is the coarse solver; nothing before a build.
TEST(GeometricMultigrid, LevelNonzerosCountEveryLevelsMatrix) {
  ContactBox box(2, 32);
  const ContactQP& qp = box.problem.qp;
  const MultigridInput& mg = box.problem.multigrid;
  const RCP<CrsMatrix> H = box.hessian(2);
  const auto entries = [](const CrsMatrix& A) { return static_cast<long long>(A.getGlobalNumEntries()); };
  for (long long directSolveSize : {1000LL, 0LL}) {  // a direct coarsest solve, MueLu below the grids
    const std::string label = "direct solve size " + std::to_string(directSolveSize);
    GeometricMultigridPreconditioner gmg = multigrid(qp, mg, 150, 3, directSolveSize);
    EXPECT_TRUE(gmg.levelNonzeros().empty()) << label;
    gmg.compute(H);
    const std::vector<long long> nonzeros = gmg.levelNonzeros();
    ASSERT_GE(nonzeros.size(), static_cast<std::size_t>(gmg.geometricLevels() + 1)) << label;
    EXPECT_EQ(nonzeros[0], entries(*H)) << label;
    for (int l = 1; l <= gmg.geometricLevels(); ++l) EXPECT_EQ(nonzeros[l], entries(*gmg.levelMatrix(l))) << label;
    const std::size_t below = nonzeros.size() - (gmg.geometricLevels() + 1);
    if (directSolveSize > 0) EXPECT_EQ(below, 0u) << label;
    else EXPECT_GE(below, 1u) << label << ": MueLu's levels below the coarsest grid";
    for (std::size_t l = 1; l < nonzeros.size(); ++l) EXPECT_LT(nonzeros[l], nonzeros[l - 1]) << label;
  }
  const RCP<const CrsMatrix> Q = assembledStiffness(qp, mg);
  Vector diagonalOfQ(qp.Q->getRangeMap());
  Q->getLocalDiagCopy(diagonalOfQ);
  GeometricMultigridPreconditioner sum = multigrid(qp, mg, 150, 3, 1000);
  sum.setFineStiffness(Q);
  const ContactBox::Sum terms = box.sum(2, diagonalOfQ);
  sum.computeForSum(Teuchos::rcpFromRef(box.H), terms.diagonal, terms.C);
  ASSERT_EQ(sum.levelNonzeros().size(), static_cast<std::size_t>(sum.geometricLevels() + 1));
  EXPECT_EQ(sum.levelNonzeros()[0], entries(*Q));
  EXPECT_EQ(sum.levelNonzeros()[1], entries(*sum.levelMatrix(1)));
}

// After a Galerkin update the smoothers' eigenvalue estimates take 3 Lanczos steps from the
// previous Ritz vectors instead of 15 from scratch, and must be as good: CG needs no more
// iterations than with a fresh build, at every step of a sequence whose weights grow by two
// orders of magnitude a step, where a third of the constraints jump from 1e-10 to 1e6 times
// Q's diagonal at step 6. Ritz vectors carried over without the D^1/2 scaling failed this
// from step 7 on (2D: 43 iterations against 15), as they did on the family (2D nx = 200:
// 315 CG iterations in the last Newton step against 7).
TEST(GeometricMultigrid, UpdatedEigenvalueEstimatesKeepTheCgCounts) {
  for (int dim : {2, 3}) {
    ContactBox box(dim, dim == 2 ? 32 : 8);
    GeometricMultigridPreconditioner updated = multigrid(box.problem.qp, box.problem.multigrid, 50);
    ASSERT_GE(updated.geometricLevels(), 2);
    for (int step = 0; step <= 12; ++step) {
      const RCP<CrsMatrix> H = box.hessian(step);
      updated.compute(H);
      GeometricMultigridPreconditioner fresh = multigrid(box.problem.qp, box.problem.multigrid, 50);
      fresh.compute(H);
      auto b = rcp(new Vector(H->getRangeMap()));
      b->randomize();
      int iterations[2];
      for (int k = 0; k < 2; ++k) {
        auto x = rcp(new Vector(H->getDomainMap()));
        const KrylovResult r =
            KrylovSolver().solve(H, (k == 0 ? updated : fresh).getOperator(), b, x, 1e-8, 200);
        ASSERT_TRUE(r.converged) << dim << "D step " << step;
        iterations[k] = r.iterations;
      }
      EXPECT_LE(iterations[0], iterations[1]) << dim << "D step " << step << ": updated estimates, fresh ones";
    }
  }
  // One or two steps from the previous Ritz vector are too few to trust (the parameter's
  // validator rejects them too).
  const AssembledProblem problem = box(2, 8, 1);
  EXPECT_THROW(multigrid(problem.qp, problem.multigrid, 50, 1), Error);
  EXPECT_THROW(multigrid(problem.qp, problem.multigrid, 50, 2), Error);
}

// Given Q as an operator, the fine smoother of every H = Q + C takes Q's eigenvalue bound,
// estimated once, instead of Lanczos steps on H where the bound on C allows: CG needs at most
// one iteration more than with H's own fresh estimate at each build, along the weights of
// UpdatedEigenvalueEstimatesKeepTheCgCounts.
void expectBoundedSmootherKeepsCgCounts(ContactBox& box, const std::string& name) {
  const ContactQP& qp = box.problem.qp;
  const MultigridInput& mg = box.problem.multigrid;
  Vector diagonalOfQ(qp.Q->getRangeMap());
  assembledStiffness(qp, mg)->getLocalDiagCopy(diagonalOfQ);
  GeometricMultigridPreconditioner bounded = multigrid(qp, mg, 50), fresh = multigrid(qp, mg, 50, 0);
  ASSERT_GE(bounded.geometricLevels(), 2);
  for (GeometricMultigridPreconditioner* m : {&bounded, &fresh}) m->setFineStiffness(assembledStiffness(qp, mg));
  bounded.setFineStiffnessOperator(qp.Q, diagonalOfQ);
  for (int step = 0; step <= 12; ++step) {
    const std::string label = name + " step " + std::to_string(step);
    const ContactBox::Sum terms = box.sum(step, diagonalOfQ);
    auto b = rcp(new Vector(terms.diagonal.getMap()));
    b->randomize();
    int iterations[2];
    for (int k = 0; k < 2; ++k) {
      GeometricMultigridPreconditioner& m = k == 0 ? bounded : fresh;
      m.computeForSum(Teuchos::rcpFromRef(box.H), terms.diagonal, terms.C);
      auto x = rcp(new Vector(terms.diagonal.getMap()));
      const KrylovResult r = KrylovSolver().solve(Teuchos::rcpFromRef(box.H), m.getOperator(), b, x, 1e-8, 200);
      ASSERT_TRUE(r.converged) << label;
      iterations[k] = r.iterations;
    }
    EXPECT_LE(iterations[0], iterations[1] + 1) << label << ": bounded, fresh";
  }
}

// Nodal constraints: C = A^T D A is diagonal. The bound is above H's largest eigenvalue, by
// 12% in 3D once the contact face (an eighth of this box's nodes) carries large weights, so
// the bounded smoother damps a slightly narrower range: 11 against 10 iterations at one or two
// of the 13 steps in 3D, depending on the right-hand side.
TEST(GeometricMultigrid, StiffnessEigenvalueBoundsEverySum) {
  for (int dim : {2, 3}) {
    ContactBox box(dim, dim == 2 ? 32 : 8);
    expectBoundedSmootherKeepsCgCounts(box, std::to_string(dim) + "D");
  }
}

// The same with weighted gaps, whose C couples the nodes of each contact facet. In 2D its
// bound gamma_C lies above lambda_Q = 3.10 at steps 2-5 (3.26) but within the boost factor
// 1.1 of it, where the smoother keeps lambda_Q; in 3D (6.5-8.7 against 2.50) H takes its
// own estimate.
TEST(GeometricMultigrid, StiffnessEigenvalueBoundsEverySumOfCoupledConstraints) {
  for (int dim : {2, 3}) {
    ContactBox box(dim, dim == 2 ? 32 : 8, "weighted gap");
    expectBoundedSmootherKeepsCgCounts(box, std::to_string(dim) + "D weighted gap");
  }
}

// The smoothers apply the boost factor once, as Ifpack2 does to a max eigenvalue it is given:
// smoothing with the Lanczos estimate lambda of D^-1 Q (15 steps, the default) is smoothing
// with "chebyshev: max eigenvalue" = lambda, on the interval [lambda / 7, 1.1 lambda]. Two grids
// (the coarse one factored), so that only the fine level is smoothed: assembled (Ifpack2's
// Chebyshev) and as the operator Q + C with C = 0 (ChebyshevSmoother, whose estimate is Q's).
TEST(GeometricMultigrid, SmoothersBoostTheEstimateOnce) {
  const AssembledProblem problem = box(2, 16, 1);
  const ContactQP& qp = problem.qp;
  const MultigridInput& mg = problem.multigrid;
  const RCP<CrsMatrix> Q = Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(qp, mg));
  Vector diagonalOfQ(Q->getRangeMap());
  Q->getLocalDiagCopy(diagonalOfQ);
  const Teuchos::ParameterList defaults = GeometricMultigridPreconditioner::defaultSmootherParameters();
  JacobiEigenvalueEstimate estimate;
  estimate.setMatrix(*Q);
  const double lambda = estimate.estimate(*Q, defaults.get<int>("chebyshev: eigenvalue max iterations"));
  const auto twoGrid = [&](const Teuchos::ParameterList& smoother) {
    return GeometricMultigridPreconditioner(*mg.grid, Q->getRowMap(), prescribedRows(*Q), *mg.coordinates,
                                            mg.blockSize, 50, 162, smoother, Teuchos::ParameterList(), 3);
  };
  Teuchos::ParameterList given, overBoosted;
  given.set("chebyshev: max eigenvalue", lambda);
  overBoosted.set("chebyshev: max eigenvalue", defaults.get<double>("chebyshev: boost factor") * lambda);
  auto C = rcp(new CrsMatrix(Q->getCrsGraph()));  // zero on Q's graph
  C->fillComplete(Q->getDomainMap(), Q->getRangeMap());
  Vector x(Q->getDomainMap());
  x.randomize();
  for (const bool asOperator : {false, true}) {
    const std::string label = asOperator ? "operator" : "assembled";
    // The cycle applied to x with each smoother list: the defaults, lambda given, boost x lambda given.
    std::vector<Vector> applied;
    for (const Teuchos::ParameterList& list : {defaults, given, overBoosted}) {
      GeometricMultigridPreconditioner m = twoGrid(list);
      ASSERT_EQ(m.levelSizes(), (std::vector<long long>{578, 162})) << label;
      if (asOperator) {
        m.setFineStiffness(Q);
        m.setFineStiffnessOperator(qp.Q, diagonalOfQ);
        m.computeForSum(qp.Q, diagonalOfQ, C);
      } else {
        m.compute(Q);
      }
      applied.emplace_back(x.getMap());
      m.getOperator()->apply(x, applied.back());
    }
    const auto distance = [](const Vector& a, const Vector& b) {
      Vector d(a, Teuchos::Copy);
      d.update(-1.0, b, 1.0);
      return d.norm2() / b.norm2();
    };
    EXPECT_LT(distance(applied[0], applied[1]), 1e-12) << label;
    EXPECT_GT(distance(applied[2], applied[1]), 1e-6) << label << ": the test cannot tell one boost from two";
  }
}

// For a P_k space (k > 1) the P1 stiffness of its mesh on the grid is P^T Q P: the hierarchy
// started from it, with no Q assembled, has the coarse matrices of the one started from Q.
TEST(GeometricMultigrid, GridStiffnessIsTheGalerkinProductOfQ) {
  for (const auto& [dim, degree] : {std::pair{2, 2}, std::pair{2, 3}, std::pair{3, 2}, std::pair{3, 3}}) {
    const std::string label = std::to_string(dim) + "D P" + std::to_string(degree);
    Teuchos::ParameterList definition = contactBoxProblem(dim, dim == 2 ? 8 : 4);
    definition.set("element: degree", degree);
    const AssembledProblem problem = buildProblem(definition, Tpetra::getDefaultComm());
    const ContactQP& qp = problem.qp;
    const MultigridInput& mg = problem.multigrid;
    BarrierHessianOperator H(qp.Q, qp.A);
    Vector D(qp.A->getRangeMap()), diagonal(qp.Q->getRangeMap());
    assembledStiffness(qp, mg)->getLocalDiagCopy(diagonal);
    D.putScalar(10.0 * diagonal.normInf());
    H.setWeights(D);
    const RCP<const CrsMatrix> C = H.contactTerm(D);
    const RCP<const CrsMatrix> grid = assembleGridStiffness(distributedSpace(*problem.space), problem.definition, *mg.grid);
    GeometricMultigridPreconditioner fromQ = multigrid(qp, mg, 20, 0), fromGrid = multigrid(qp, mg, 20, 0);
    ASSERT_GE(fromQ.geometricLevels(), 2) << label;
    fromQ.setFineStiffness(assembledStiffness(qp, mg));
    fromGrid.setGridStiffness(*grid);
    fromQ.computeForSum(Teuchos::rcpFromRef(H), diagonal, C);
    fromGrid.computeForSum(Teuchos::rcpFromRef(H), diagonal, C);
    expectSameCoarseMatrices(fromGrid, fromQ, label);
  }
}

// A grid that the mesh does not refine is an input error, not a wrong preconditioner.
TEST(GeometricMultigrid, RejectsAGridTheMeshDoesNotRefine) {
  const AssembledProblem problem = box(2, 8, 1);
  BoxGrid wrong = dynamic_cast<const BoxGrid&>(*problem.multigrid.grid);
  wrong.cells = {6, 6, 1};  // halved: vertices at thirds, which the 8-cell mesh lacks
  const CrsMatrix& Q = *assembledStiffness(problem.qp, problem.multigrid);
  EXPECT_THROW(GeometricMultigridPreconditioner(wrong, Q.getRowMap(), prescribedRows(Q),
                                                *problem.multigrid.coordinates, 2, 1, 0, Teuchos::ParameterList(),
                                                Teuchos::ParameterList(), 5),
               InputError);
}

// A whole number given for a real smoother parameter (as --set "...ratio eigenvalue=20"
// gives) is that number; a word is an input error naming the parameter, not a failure
// inside Ifpack2.
TEST(GeometricMultigrid, SmootherParametersAreCheckedForTheirTypes) {
  const AssembledProblem problem = box(2, 8, 1);
  const CrsMatrix& Q = *assembledStiffness(problem.qp, problem.multigrid);
  const auto make = [&](const Teuchos::ParameterList& smoother) {
    GeometricMultigridPreconditioner p(*problem.multigrid.grid, Q.getRowMap(), prescribedRows(Q), *problem.multigrid.coordinates, 2,
                                       1, 0, smoother, Teuchos::ParameterList(), 3);
    p.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(problem.qp, problem.multigrid)));
  };
  Teuchos::ParameterList whole;
  whole.set("chebyshev: ratio eigenvalue", 20);
  EXPECT_NO_THROW(make(whole));
  Teuchos::ParameterList word;
  word.set("chebyshev: boost factor", "large");
  try {
    make(word);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("chebyshev: boost factor"), std::string::npos) << e.what();
  }
}

// The interior point solve reaches the same solution with either hierarchy. By default the geometric levels are rebuilt at
// every Newton step (one setup per main iteration and one for the start), MueLu's hierarchy
// alone only when constraints switch.
TEST(GeometricMultigrid, InteriorPointSolutionAgreesWithTheAlgebraicHierarchy) {
  const AssembledProblem problem = buildProblem(shippedProblem("paper/K"), Tpetra::getDefaultComm());
  double objective[2];
  int i = 0;
  for (const char* hierarchy : {"algebraic", "geometric"}) {
    Teuchos::ParameterList params;
    params.sublist("Preconditioner").set("hierarchy", hierarchy);
    const SolveResult r = InteriorPointSolver(params).solve(problem.qp, problem.multigrid);
    ASSERT_TRUE(r.converged()) << hierarchy << ": " << r.message;
    objective[i++] = r.objective;
    if (std::string(hierarchy) == "geometric") EXPECT_EQ(r.preconditionerSetups, r.outerIterations + 1);
    else EXPECT_LT(r.preconditionerSetups, r.outerIterations / 2) << r.preconditionerSetups << " setups";
  }
  EXPECT_LT(std::abs(objective[1] - objective[0]), 1e-8 * std::abs(objective[0]));
}

// MueLu's levels kept below the coarsest grid (the rebuild tolerance above 0) lead the
// interior point solve to the solution MueLu as coarse solver gives.
TEST(GeometricMultigrid, InteriorPointSolutionAgreesWithKeptAlgebraicLevels) {
  const AssembledProblem problem = buildProblem(shippedProblem("paper/K"), Tpetra::getDefaultComm());
  double objective[2];
  int i = 0;
  for (const char* tolerance : {"0", "0.9"}) {
    Teuchos::ParameterList params;
    params.sublist("Preconditioner").set("geometric: direct solve size", 0);
    params.sublist("Preconditioner").set("geometric: algebraic levels rebuild tolerance", std::string(tolerance));
    const SolveResult r = InteriorPointSolver(params).solve(problem.qp, problem.multigrid);
    ASSERT_TRUE(r.converged()) << "tolerance " << tolerance << ": " << r.message;
    objective[i++] = r.objective;
  }
  EXPECT_LT(std::abs(objective[1] - objective[0]), 1e-8 * std::abs(objective[0]));
}

TEST(GeometricMultigrid, NeedsABoxMesh) {
  AssembledProblem problem = buildProblem(shippedProblem("paper/M"), Tpetra::getDefaultComm());
  problem.multigrid.grid.reset();
  Teuchos::ParameterList params;
  params.sublist("Preconditioner").set("hierarchy", "geometric");
  EXPECT_THROW(InteriorPointSolver(params).solve(problem.qp, problem.multigrid), InputError);
  params.sublist("Preconditioner").set("hierarchy", "auto");  // falls back to MueLu alone
  EXPECT_TRUE(InteriorPointSolver(params).solve(problem.qp, problem.multigrid).converged());
}

}  // namespace
