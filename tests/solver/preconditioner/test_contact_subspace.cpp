// The contact-subspace correction: the exact solve on the DOFs of A and its additive and
// multiplicative combinations with the AMG, on every rank count; and every preconditioner
// configuration reaching the same solution.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "solver/preconditioner/ContactSubspaceSolver.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"
#include "solver/preconditioner/SubspaceCorrectedPreconditioner.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// 1 on the DOFs that appear in A, 0 elsewhere: the columns of A's nonzero entries (a
// weighted-gap column may sum to zero).
Vector contactIndicator(const ContactQP& qp) {
  Vector onColumns(qp.A->getColMap()), indicator(qp.A->getDomainMap());
  const auto a = qp.A->getLocalMatrixHost();
  auto c = onColumns.getDataNonConst();
  for (std::size_t e = 0; e < a.values.extent(0); ++e)
    if (a.values(e) != 0.0) c[a.graph.entries(e)] = 1.0;
  indicator.doExport(onColumns, Tpetra::Export<LocalOrdinal, GlobalOrdinal, Node>(qp.A->getColMap(), qp.A->getDomainMap()),
                     Tpetra::ADD);
  auto d = indicator.getDataNonConst();
  for (long i = 0; i < d.size(); ++i) d[i] = d[i] != 0.0 ? 1.0 : 0.0;
  return indicator;
}

struct WeightedProblem {
  AssembledProblem problem;
  RCP<BarrierHessianOperator> H;
  RCP<ContactSubspaceSolver> S;
};

// Problem `name` of the family, with its nodal constraints or with weighted gaps, whose
// rows couple the DOFs around a contact vertex.
struct Case {
  const char* name;
  const char* formulation;
};
const Case kCases[] = {{"M", "nodal"}, {"B", "nodal"}, {"H", "nodal"},
                       {"B", "weighted gap"}, {"H", "weighted gap"}, {"C", "weighted gap"}};

std::string describe(const Case& c) { return std::string(c.name) + " " + c.formulation; }

WeightedProblem weightedProblem(const Case& c, ContactSubspaceBlocks blocks = ContactSubspaceBlocks::Gathered) {
  Teuchos::ParameterList problem = shippedProblem(std::string("paper/") + c.name);
  problem.sublist("Contact").set("formulation", c.formulation);
  problem.set("stiffness: operator", "assembled");  // the pieces are compared with Q's
  WeightedProblem s{buildProblem(problem, Tpetra::getDefaultComm()), {}, {}};
  const ContactQP& qp = s.problem.qp;
  s.H = rcp(new BarrierHessianOperator(qp.Q, qp.A));
  s.S = rcp(new ContactSubspaceSolver(*assembledStiffness(qp, s.problem.multigrid), *qp.A, blocks));
  Vector D(qp.A->getRangeMap());
  D.randomize(1.0, 1e8);  // from free to firmly active constraints
  s.H->setWeights(D);
  s.S->setWeights(D);
  return s;
}

// y = S r solves the subspace equations P^T H y = P^T r exactly and vanishes off the subspace.
TEST(ContactSubspaceSolver, SolvesTheSubspaceEquations) {
  for (const Case& c : kCases) {
    WeightedProblem s = weightedProblem(c);
    const std::string name = describe(c);
    const ContactQP& qp = s.problem.qp;
    const Vector indicator = contactIndicator(qp);
    EXPECT_EQ(s.S->dimension(), std::llround(indicator.norm1())) << name;
    if (std::string(c.formulation) == "nodal") {
      EXPECT_EQ(s.S->dimension(), static_cast<long long>(qp.A->getGlobalNumRows())) << name;
    }
    Vector r(qp.Q->getDomainMap()), y(qp.Q->getDomainMap()), Hy(qp.Q->getDomainMap()), off(qp.Q->getDomainMap());
    r.randomize();
    s.S->apply(r, y);
    off.assign(y);
    off.elementWiseMultiply(-1.0, indicator, y, 1.0);  // y off the contact DOFs
    EXPECT_EQ(off.normInf(), 0.0) << name;
    s.H->apply(y, Hy);
    Hy.update(-1.0, r, 1.0);
    Hy.elementWiseMultiply(1.0, indicator, Hy, 0.0);  // P P^T (H y - r)
    Vector rc(r.getMap());
    rc.elementWiseMultiply(1.0, indicator, r, 0.0);
    EXPECT_LT(Hy.norm2(), 1e-10 * rc.norm2()) << name;
    EXPECT_GT(y.norm2(), 0.0) << name;
  }
}

// Per rank, y = S r solves each rank's block of the subspace equations, P_q^T H P_q y_q =
// P_q^T r with P_q the contact DOFs rank q owns, and S is symmetric positive definite. On one
// rank that is the whole subspace.
TEST(ContactSubspaceSolver, PerRankBlocksSolveTheirOwnSubspaceEquations) {
  for (const Case& c : kCases) {
    WeightedProblem s = weightedProblem(c, ContactSubspaceBlocks::PerRank);
    const std::string name = describe(c);
    const ContactQP& qp = s.problem.qp;
    const Vector indicator = contactIndicator(qp);
    EXPECT_EQ(s.S->dimension(), std::llround(indicator.norm1())) << name;
    const auto map = qp.Q->getDomainMap();
    Vector r(map), y(map), w(map), Sw(map);
    r.randomize();
    s.S->apply(r, y);
    const int ranks = map->getComm()->getSize(), rank = map->getComm()->getRank();
    double worst = 0.0;
    for (int q = 0; q < ranks; ++q) {
      Vector yq(map), Hyq(map);  // y on rank q's DOFs alone, and H of it
      if (rank == q) yq.assign(y);
      s.H->apply(yq, Hyq);
      if (rank != q) continue;
      Hyq.update(-1.0, r, 1.0);
      Hyq.elementWiseMultiply(1.0, indicator, Hyq, 0.0);
      for (double e : Hyq.getData()) worst = std::max(worst, std::abs(e));  // this rank's rows only
    }
    Vector rc(map);
    rc.elementWiseMultiply(1.0, indicator, r, 0.0);
    double worstOnAnyRank = 0.0;
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_MAX, worst, Teuchos::outArg(worstOnAnyRank));
    EXPECT_LT(worstOnAnyRank, 1e-10 * rc.normInf()) << name;
    w.randomize();
    s.S->apply(w, Sw);
    EXPECT_NEAR(w.dot(y), r.dot(Sw), 1e-10 * std::sqrt(w.dot(Sw) * r.dot(y))) << name;
    EXPECT_GT(r.dot(y), 0.0) << name;
  }
}

// Nodal constraints lie on one rank each: "auto" solves per rank. Whole solves with "auto"
// take the Krylov iterations of the exact, gathered solve to within 10%, with nodal
// constraints and with weighted gaps (which "auto" gathers where they are split).
TEST(ContactSubspaceSolver, AutoBlocksKeepTheKrylovCounts) {
  for (const Case& c : {Case{"H", "nodal"}, Case{"B", "weighted gap"}, Case{"J", "nodal"}}) {
    Teuchos::ParameterList problem = shippedProblem(std::string("paper/") + c.name);
    problem.sublist("Contact").set("formulation", c.formulation);
    const AssembledProblem assembled = buildProblem(problem, Tpetra::getDefaultComm());
    const ContactQP& qp = assembled.qp;
    if (std::string(c.formulation) == "nodal") {
      const StiffnessParts stiffness(qp, assembled.multigrid);
      EXPECT_TRUE(ContactSubspaceSolver(*stiffness.contactRows(*qp.A), *qp.A, ContactSubspaceBlocks::Auto).perRank());
    }
    SolveResult results[2];
    for (int k = 0; k < 2; ++k) {
      Teuchos::ParameterList params;
      params.sublist("Preconditioner").set("contact correction: blocks", k == 0 ? "gathered" : "auto");
      results[k] = InteriorPointSolver(params).solve(qp, assembled.multigrid);
      ASSERT_TRUE(results[k].converged()) << describe(c) << ": " << results[k].message;
    }
    EXPECT_LE(results[1].krylovIterations, 1.1 * results[0].krylovIterations + 1) << describe(c);
    EXPECT_LE(std::abs(results[1].outerIterations - results[0].outerIterations), 1) << describe(c);
    EXPECT_LT(std::abs(results[1].objective - results[0].objective), 1e-10 * std::abs(results[0].objective));
  }
}

// Both combinations are symmetric positive definite, and the multiplicative one is exact on
// the subspace (for x on the contact DOFs, M^-1 H x = x) and unchanged when its residuals
// come from H P P^T.
TEST(SubspaceCorrectedPreconditioner, SymmetricPositiveDefiniteAndExactOnTheSubspace) {
  for (const Case& c : {Case{"G", "nodal"}, Case{"B", "nodal"}, Case{"H", "weighted gap"}}) {
    WeightedProblem s = weightedProblem(c);
    const std::string name = describe(c);
    const ContactQP& qp = s.problem.qp;
    const MultigridInput& mg = s.problem.multigrid;
    MueLuPreconditioner amg(Teuchos::ParameterList(), mg.blockSize, mg.nearNullspace(qp), mg.coordinates);
    amg.compute(s.H->assemble());
    for (const ContactCorrection combination : {ContactCorrection::Additive, ContactCorrection::Multiplicative}) {
      const char* combinationName = combination == ContactCorrection::Additive ? "additive" : "multiplicative";
      SubspaceCorrectedPreconditioner M(s.H, amg.getOperator(), s.S, combination);
      Vector u(qp.Q->getDomainMap()), w(qp.Q->getDomainMap()), Mu(qp.Q->getDomainMap()), Mw(qp.Q->getDomainMap());
      u.randomize();
      w.randomize();
      M.apply(u, Mu);
      M.apply(w, Mw);
      const double uMw = u.dot(Mw), wMu = w.dot(Mu);
      EXPECT_LT(std::abs(uMw - wMu), 1e-8 * std::sqrt(u.dot(Mu) * w.dot(Mw))) << name << " " << combinationName;
      EXPECT_GT(u.dot(Mu), 0.0) << name << " " << combinationName;
      EXPECT_GT(w.dot(Mw), 0.0) << name << " " << combinationName;
      if (combination != ContactCorrection::Multiplicative) continue;
      Vector x(qp.Q->getDomainMap()), Hx(qp.Q->getDomainMap()), Mx(qp.Q->getDomainMap());
      x.randomize();
      x.elementWiseMultiply(1.0, contactIndicator(qp), x, 0.0);
      s.H->apply(x, Hx);
      M.apply(Hx, Mx);
      Mx.update(-1.0, x, 1.0);
      EXPECT_LT(Mx.norm2(), 1e-10 * x.norm2()) << name;
      // The same M^-1 with both residuals taken from H P P^T instead of H.
      SubspaceCorrectedPreconditioner sliced(s.H, amg.getOperator(), s.S, combination,
                                             s.H->onContactColumns(*assembledStiffness(s.problem.qp, s.problem.multigrid)));
      Vector slicedMu(qp.Q->getDomainMap());
      sliced.apply(u, slicedMu);
      slicedMu.update(-1.0, Mu, 1.0);
      EXPECT_LT(slicedMu.normInf(), 1e-12 * Mu.normInf()) << name;
    }
  }
}

// H P P^T applies H to vectors on the contact DOFs, and its transpose gives H's contact rows.
TEST(BarrierHessianOperator, ContactColumnsGiveHOnTheSubspace) {
  for (const Case& c : kCases) {
    WeightedProblem s = weightedProblem(c);
    const std::string name = describe(c);
    const ContactQP& qp = s.problem.qp;
    const RCP<BarrierHessianOperator> HP = s.H->onContactColumns(*assembledStiffness(s.problem.qp, s.problem.multigrid));
    const Vector indicator = contactIndicator(qp);
    Vector x(qp.Q->getDomainMap()), Hx(qp.Q->getDomainMap()), HPx(qp.Q->getDomainMap());
    x.randomize();
    x.elementWiseMultiply(1.0, indicator, x, 0.0);
    s.H->apply(x, Hx);
    HP->apply(x, HPx);
    HPx.update(-1.0, Hx, 1.0);
    EXPECT_LT(HPx.normInf(), 1e-13 * Hx.normInf()) << name;

    Vector z(qp.Q->getDomainMap()), Hz(qp.Q->getDomainMap()), HPtz(qp.Q->getDomainMap());
    z.randomize();
    s.H->apply(z, Hz);
    HP->apply(z, HPtz, Teuchos::TRANS);
    Vector off(HPtz.getMap());
    off.elementWiseMultiply(1.0, indicator, HPtz, 0.0);
    off.update(1.0, HPtz, -1.0);  // what P P^T H z has off the subspace: nothing
    EXPECT_EQ(off.normInf(), 0.0) << name;
    Hz.elementWiseMultiply(1.0, indicator, Hz, 0.0);
    HPtz.update(-1.0, Hz, 1.0);
    EXPECT_LT(HPtz.normInf(), 1e-13 * Hz.normInf()) << name;
  }
}

// Every preconditioner configuration converges to the same solution, in no more Krylov
// iterations per Newton system with the contact correction than without.
TEST(SubspaceCorrectedPreconditioner, EveryConfigurationReachesTheSameSolution) {
  const AssembledProblem problem = buildProblem(shippedProblem("paper/K"), Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  double reference = 0;
  int withoutCorrection = 0;
  for (const char* type : {"amg of H", "amg of Q"})
    for (const char* correction : {"none", "additive", "multiplicative"})
      for (double rebuild : {0.0, 0.9}) {
        if (std::string(type) == "amg of Q" && rebuild > 0) continue;
        Teuchos::ParameterList params;
        params.sublist("Preconditioner").set("type", type);
        params.sublist("Preconditioner").set("contact correction", correction);
        params.sublist("Preconditioner").set("amg of H: rebuild tolerance", rebuild);
        const SolveResult r = InteriorPointSolver(params).solve(qp, problem.multigrid);
        const std::string what = std::string(type) + " / " + correction + " / " + std::to_string(rebuild);
        ASSERT_TRUE(r.converged()) << what << ": " << r.message;
        if (reference == 0) reference = r.objective;
        EXPECT_LT(std::abs(r.objective - reference), 1e-8 * std::abs(reference)) << what;
        if (std::string(type) == "amg of H" && rebuild == 0.0) {
          EXPECT_EQ(r.preconditionerSetups, r.outerIterations + 1) << what;  // one per main iteration and the start
          if (std::string(correction) == "none") withoutCorrection = r.maxKrylovPerNewton;
          if (std::string(correction) == "multiplicative") {
            EXPECT_LE(r.maxKrylovPerNewton, withoutCorrection) << what;
          }
        }
        if (rebuild > 0) {
          EXPECT_LT(r.preconditionerSetups, r.outerIterations) << what;
        }
      }
}

TEST(SubspaceCorrectedPreconditioner, NeedsAnAmg) {
  const AssembledProblem problem = buildProblem(shippedProblem("paper/M"), Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  Teuchos::ParameterList params;
  params.sublist("Preconditioner").set("type", "none");
  params.sublist("Preconditioner").set("contact correction", "multiplicative");
  EXPECT_THROW(InteriorPointSolver(params).solve(qp, problem.multigrid), InputError);
}

}  // namespace
