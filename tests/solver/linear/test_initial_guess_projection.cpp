// Fischer's projection of a Krylov solve's starting vector on earlier solutions: exact when
// the solution lies in their span, the best guess of that span in H's energy norm otherwise,
// and what the Newton systems start from by default, with its correction on the contact
// DOFs.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "core/ParameterValidation.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/linear/InitialGuessProjection.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

struct Fixture {
  AssembledProblem problem = buildProblem(shippedProblem("paper/M"), Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  const MultigridInput& multigrid = problem.multigrid;
  BarrierHessianOperator H{qp.Q, qp.A};  // Q until weights are set: symmetric positive definite
  RCP<Vector> random() const {
    auto v = rcp(new Vector(qp.Q->getDomainMap()));
    v->randomize();
    return v;
  }
  double energyNorm(const Vector& v) const {
    Vector Hv(H.getRangeMap());
    H.apply(v, Hv);
    return std::sqrt(v.dot(Hv));
  }
};

TEST(InitialGuessProjection, ExactWhenTheSolutionIsInTheSpanOfTheKeptSolutions) {
  Fixture f;
  auto solution = f.random(), a = f.random(), b = f.random();
  Vector r(f.H.getRangeMap()), shifted(*solution, Teuchos::Copy), x(f.H.getDomainMap());
  f.H.apply(*solution, r);
  shifted.update(1.0, *a, 1.0);  // solution + a: with a, it spans the solution

  InitialGuessProjection projection(2);
  projection.remember(f.H, *b);  // dropped: the capacity is 2
  projection.remember(f.H, *a);
  projection.remember(f.H, shifted);
  EXPECT_EQ(projection.project(f.H, r, x, false), 2);
  x.update(-1.0, *solution, 1.0);
  EXPECT_LT(f.energyNorm(x), 1e-10 * f.energyNorm(*solution));
}

TEST(InitialGuessProjection, GivesTheGalerkinSolutionOnTheSpan) {
  Fixture f;
  auto solution = f.random();
  Vector r(f.H.getRangeMap()), x(f.H.getDomainMap()), residual(f.H.getRangeMap());
  f.H.apply(*solution, r);
  InitialGuessProjection projection(3);
  std::vector<RCP<Vector>> kept;
  for (int i = 0; i < 3; ++i) {
    kept.push_back(f.random());
    projection.remember(f.H, *kept.back());
  }
  ASSERT_EQ(projection.project(f.H, r, x, false), 3);
  // Galerkin: the residual is orthogonal to every kept solution (the error H-orthogonal).
  f.H.apply(x, residual);
  residual.update(1.0, r, -1.0);
  for (const auto& u : kept) EXPECT_LT(std::abs(u->dot(residual)), 1e-10 * u->norm2() * r.norm2());
  // Hence no multiple of one of them is closer to the solution in the energy norm.
  Vector error(x, Teuchos::Copy), Hu(f.H.getRangeMap());
  error.update(-1.0, *solution, 1.0);
  const double projected = f.energyNorm(error);
  EXPECT_LT(projected, f.energyNorm(*solution));
  for (const auto& u : kept) {
    f.H.apply(*u, Hu);
    Vector single(*u, Teuchos::Copy);
    single.scale(u->dot(r) / u->dot(Hu));
    single.update(-1.0, *solution, 1.0);
    EXPECT_LE(projected, f.energyNorm(single) * (1 + 1e-12));
  }
}

TEST(InitialGuessProjection, SkipsDependentVectorsAndUsesTheGivenStart) {
  Fixture f;
  auto a = f.random();
  Vector twice(*a, Teuchos::Copy), r(f.H.getRangeMap()), x(*a, Teuchos::Copy);
  twice.scale(2.0);
  f.H.apply(*a, r);
  InitialGuessProjection projection(4);
  EXPECT_EQ(projection.project(f.H, r, x, false), 0);  // nothing kept yet: x = 0
  EXPECT_EQ(x.norm2(), 0.0);
  x.assign(twice);
  EXPECT_EQ(projection.project(f.H, r, x, true), 1);  // the given start alone: scaled to a
  x.update(-1.0, *a, 1.0);
  EXPECT_LT(x.norm2(), 1e-12 * a->norm2());
  projection.remember(f.H, *a);
  projection.remember(f.H, twice);
  EXPECT_EQ(projection.project(f.H, r, x, false), 1);
  EXPECT_THROW(InitialGuessProjection(-1), InputError);
}

// H changes between the systems (D): the kept Q u give the same projection as H applied
// anew, x = U (U^T H U)^-1 U^T r, and H x with it; a start equal to the last kept solution
// adds nothing.
TEST(InitialGuessProjection, KeptProductsFollowNewWeights) {
  Fixture f;
  Vector D(f.qp.A->getRangeMap()), r(f.H.getRangeMap()), x(f.H.getDomainMap()), Hx(f.H.getRangeMap());
  D.randomize(1.0, 1e6);
  f.H.setWeights(D);
  auto u = f.random(), v = f.random();
  r.randomize();
  InitialGuessProjection projection(2);
  projection.remember(f.H, *u);
  projection.remember(f.H, *v);
  D.randomize(1.0, 1e8);
  f.H.setWeights(D);
  ASSERT_EQ(projection.project(f.H, r, x, false, &Hx), 2);

  // The 2 x 2 Galerkin system with H applied now.
  Vector Hu(f.H.getRangeMap()), Hv(f.H.getRangeMap());
  f.H.apply(*u, Hu);
  f.H.apply(*v, Hv);
  const double a = u->dot(Hu), b = u->dot(Hv), c = v->dot(Hv), ru = u->dot(r), rv = v->dot(r);
  const double det = a * c - b * b;
  Vector expected(*u, Teuchos::Copy);
  expected.update((a * rv - b * ru) / det, *v, (c * ru - b * rv) / det);
  expected.update(-1.0, x, 1.0);
  EXPECT_LT(expected.norm2(), 1e-8 * x.norm2());
  Vector applied(f.H.getRangeMap());
  f.H.apply(x, applied);
  applied.update(-1.0, Hx, 1.0);
  EXPECT_LT(applied.norm2(), 1e-10 * Hx.norm2());

  Vector start(*v, Teuchos::Copy);
  EXPECT_EQ(projection.project(f.H, r, start, true), 2);
  start.update(-1.0, x, 1.0);
  EXPECT_LT(start.norm2(), 1e-12 * x.norm2());
}

// A Newton system solved again needs no Krylov iteration with the projection, and some
// without it.
TEST(InitialGuessProjection, NewtonSystemSolverStartsFromEarlierSolutions) {
  Fixture f;
  Vector D(f.qp.A->getRangeMap()), r(f.H.getRangeMap()), x(f.H.getDomainMap());
  D.randomize(1.0, 1e6);
  r.randomize();
  for (int keep : {0, 2}) {
    Teuchos::ParameterList user;
    user.sublist("Krylov").set("initial guess: previous solutions", keep);
    NewtonSystemSolver newton(f.qp, f.multigrid,
                              validatedParameters(user, NewtonSystemSolver::validParameters(), "Solver"));
    newton.setWeights(D);
    const KrylovResult first = newton.solve(r, x, 1e-10 * r.norm2());
    ASSERT_TRUE(first.converged);
    EXPECT_GT(first.iterations, 0);
    const KrylovResult again = newton.solve(r, x, 1e-6 * r.norm2());
    ASSERT_TRUE(again.converged);
    if (keep == 0) {
      EXPECT_GT(again.iterations, 0);
    } else {
      EXPECT_EQ(again.iterations, 0);
    }
  }
}

// A system whose solution lies on the contact DOFs: the contact-corrected start is that
// solution (no Krylov iteration) with the exact, gathered subspace solve and with the
// per-rank one on one rank; the start from zero is not. On more ranks the per-rank start
// is a block Jacobi step, and CG takes it from there.
TEST(InitialGuessProjection, ContactCorrectedStartIsExactOnTheContactDofs) {
  Fixture f;
  Vector D(f.qp.A->getRangeMap()), ones(f.qp.A->getRangeMap()), solution(f.H.getDomainMap()),
      r(f.H.getRangeMap()), x(f.H.getDomainMap());
  D.randomize(1.0, 1e6);
  ones.putScalar(1.0);
  f.qp.A->apply(ones, solution, Teuchos::TRANS);  // nonzero exactly on the contact DOFs
  BarrierHessianOperator H(f.qp.Q, f.qp.A);
  H.setWeights(D);
  H.apply(solution, r);
  const bool oneRank = f.qp.Q->getDomainMap()->getComm()->getSize() == 1;
  int fromZero = 0;
  for (const char* start : {"zero", "gathered", "per rank"}) {
    const bool corrected = std::string(start) != "zero";
    Teuchos::ParameterList user;
    user.sublist("Krylov").set("initial guess: previous solutions", 0);
    user.sublist("Krylov").set("initial guess: contact correction", corrected);
    user.sublist("Preconditioner").set("contact correction: blocks", corrected ? start : "gathered");
    // paper/M is small enough to be factored whole, which needs no contact correction: MueLu
    // instead keeps one.
    user.sublist("Preconditioner").set("geometric: direct solve size", 0);
    NewtonSystemSolver newton(f.qp, f.multigrid,
                              validatedParameters(user, NewtonSystemSolver::validParameters(), "Solver"));
    newton.setWeights(D);
    const KrylovResult result = newton.solve(r, x, 1e-8 * r.norm2());
    ASSERT_TRUE(result.converged);
    const bool exact = std::string(start) == "gathered" || (corrected && oneRank);
    if (!corrected) {
      fromZero = result.iterations;
      EXPECT_GT(result.iterations, 0);
    } else if (exact) {
      EXPECT_EQ(result.iterations, 0) << start;
    } else {
      EXPECT_LE(result.iterations, fromZero) << start;
    }
    if (!exact && corrected) continue;  // a residual of 1e-8 bounds the error by H's condition only
    x.update(-1.0, solution, 1.0);
    EXPECT_LT(x.normInf(), 1e-6 * solution.normInf()) << start;
  }
}

}  // namespace
