// A QP without constraints (m = 0) is the linear system Q v = b: one preconditioned Krylov
// solve, with the Newton systems' solver, to the stationarity the KKT tolerance asks for.
#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/ipm/InteriorPointMethods.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {

SolveResult solveUnconstrained(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& p,
                               const Vector* v0,
                               IterationObserver& observer) {
  Teuchos::Time timer("linear solve");
  timer.start(true);
  observer.onStart("linear solve (no constraints)", qp.Q->getDomainMap()->getGlobalNumElements(), 0);
  SolveResult result;
  NewtonSystemSolver newton(qp, multigrid, p);
  newton.setWeights(Vector(qp.A->getRangeMap()));
  RCP<Vector> v = initialDisplacement(qp, v0);
  Vector r(*qp.b, Teuchos::Copy), dv(qp.Q->getDomainMap());
  qp.Q->apply(*v, r, Teuchos::NO_TRANS, -1.0, 1.0);  // r = b - Q v
  const StoppingRule stop(p);
  // The relative stationarity is ||b - Q v|| / ||b||; half the tolerance leaves room for
  // the difference between the Krylov solver's residual and the true one.
  const double bnorm = qp.b->norm2();
  const KrylovResult kr = newton.solve(r, dv, 0.5 * stop.tolerance * (bnorm > 0 ? bnorm : 1.0));
  v->update(1.0, dv, 1.0);
  ++result.newtonSteps;
  countKrylovSolve(result, kr.iterations, kr.iterations);
  result.preconditionerSetups = newton.preconditionerSetups();
  result.multigridNonzeros = newton.multigridNonzeros();
  const Vector none(qp.A->getRangeMap());
  finishResult(qp, *v, none, none, result);

  NewtonStepRecord step;
  step.outer = 1;
  step.step = 1.0;
  step.objective = result.objective;
  step.kkt = result.kkt;
  step.krylovIterations = kr.iterations;
  step.seconds = timer.totalElapsedTime(true);
  observer.onNewtonStep(step);

  if (!stop.converged(result.kkt, result))
    stopWith(result, SolveStatus::KrylovFailure,
             "the linear solve of the unconstrained problem did not reach the KKT tolerance; raise "
             "Solver/Krylov/maximum iterations or choose a stronger Solver/Preconditioner");
  result.seconds = timer.totalElapsedTime(true);
  observer.onFinish(result);
  return result;
}

}  // namespace signorini::detail
