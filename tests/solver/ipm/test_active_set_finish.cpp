// The primal-dual method's active-set finish: where the active set settles, the finish ends
// the solve at a point that meets every KKT tolerance and is the optimum the barrier
// iterations reach without it, in no more main iterations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/SolveRecorder.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

// The result, and what the recorder observed of the solve.
struct Recorded {
  SolveResult result;
  SolveRecorder record;
};

Recorded solve(const AssembledProblem& problem, bool finish) {
  Teuchos::ParameterList params;
  params.set("primal-dual: active-set finish", finish);
  Recorded r;
  r.result = InteriorPointSolver(params).solve(problem.qp, problem.multigrid, nullptr, &r.record);
  return r;
}

// A 2D and a 3D problem whose last iterations are the barrier's linear tail (K, L), and two
// where nearly degenerate constraints still cross the estimate then (F, I): the finish must
// not wait for them.
TEST(ActiveSetFinish, EndsTheSolveAtTheOptimumOfTheBarrierIterations) {
  for (const char* name : {"K", "L", "F", "I"}) {
    const AssembledProblem problem = buildProblem(shippedProblem(std::string("paper/") + name), Tpetra::getDefaultComm());
    const Recorded withFinish = solve(problem, true), withoutFinish = solve(problem, false);
    const SolveResult &with = withFinish.result, &without = withoutFinish.result;
    const std::vector<NewtonStepRecord>& history = withFinish.record.history();
    ASSERT_TRUE(with.converged() && without.converged()) << name << ": " << with.message << " / " << without.message;
    EXPECT_TRUE(withFinish.record.finishedOnActiveSet()) << name;
    EXPECT_GE(withFinish.record.activeSetFinishes().size(), 1u) << name;
    EXPECT_EQ(withoutFinish.record.activeSetFinishes().size(), 0u) << name;
    ASSERT_FALSE(history.empty());
    EXPECT_EQ(history.back().mu, 0.0) << name;
    EXPECT_EQ(history.back().step, 1.0) << name;
    EXPECT_EQ(static_cast<int>(withFinish.record.innerIterations().size()), with.outerIterations) << name;
    // The finish's CG iterations are counted in the total, not in the barrier systems' maximum.
    EXPECT_GE(withFinish.record.activeSetFinishKrylov(), history.back().krylovIterations) << name;
    EXPECT_GT(history.back().krylovIterations, 0) << name;
    EXPECT_LT(withFinish.record.activeSetFinishKrylov(), with.krylovIterations) << name;
    int largestBarrierStep = 0;
    for (std::size_t k = 0; k + 1 < history.size(); ++k)
      largestBarrierStep = std::max(largestBarrierStep, history[k].krylovIterations);
    EXPECT_LE(with.maxKrylovPerNewton, largestBarrierStep) << name;
    EXPECT_LE(with.kkt.worst(), 1e-8) << name;
    EXPECT_LE(with.outerIterations, without.outerIterations) << name;
    EXPECT_EQ(with.activeConstraints, without.activeConstraints) << name;
    // Both objectives are within the duality gap the tolerance allows, 1e-8 of the energy.
    EXPECT_LT(std::abs(with.objective - without.objective), 2e-8 * std::abs(without.objective)) << name;
    Vector dv(*with.v, Teuchos::Copy);
    dv.update(-1.0, *without.v, 1.0);
    EXPECT_LT(dv.normInf(), 1e-4 * without.v->normInf()) << name;
  }
}

// The finished point's multipliers are the contact forces: none of the wrong sign, none on a
// constraint with a gap.
TEST(ActiveSetFinish, MultipliersAreCompressiveAndComplementary) {
  const AssembledProblem problem = buildProblem(shippedProblem("paper/K"), Tpetra::getDefaultComm());
  const ContactQP& qp = problem.qp;
  const Recorded recorded = solve(problem, true);
  const SolveResult& r = recorded.result;
  ASSERT_TRUE(recorded.record.finishedOnActiveSet());
  Vector c(qp.A->getRangeMap());
  qp.A->apply(*r.v, c);
  c.update(-1.0, *qp.d, 1.0);
  const double lambdaMax = r.lambda->normInf();  // collective: not inside the loop over local entries
  const double scale = lambdaMax * std::max(r.v->normInf(), qp.d->normInf());
  auto l = r.lambda->getData();
  auto cd = c.getData();
  for (std::size_t i = 0; i < c.getLocalLength(); ++i) {
    EXPECT_LE(l[i], 1e-8 * lambdaMax) << i;
    EXPECT_LE(std::abs(l[i] * cd[i]), 1e-10 * scale) << i;
  }
}

}  // namespace
