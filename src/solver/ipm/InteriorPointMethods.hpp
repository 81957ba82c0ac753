#pragma once
// Private to src/solver: the two interior point methods and what they share.
#include <string>
#include <utility>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_Time.hpp>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"
#include "signorini/solver/IterationObserver.hpp"
#include "signorini/solver/SolveResult.hpp"
#include "solver/linear/NewtonSystemSolver.hpp"

namespace signorini::detail {

// The choices of the "Solver" list, parsed once when the solve starts.
enum class Method { PrimalDual, Primal };
enum class Centering { Mehrotra, Fixed };
enum class ForcingType { Reduction, Adaptive, Constant, EisenstatWalker, Relative };
enum class StartingPoint { Shift, Relaxed };

// `freeMotions`: the rigid body motions no prescribed displacement removes, along which Q is
// singular and only the contact holds the body (checkRigidBodyMotionsHeld); null if none.
SolveResult solvePrimalDual(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& params,
                            const Vector* v0,
                            IterationObserver& observer, const RCP<const MultiVector>& freeMotions);
SolveResult solvePrimalBarrier(const ContactQP& qp, const MultigridInput& multigrid,
                               const Teuchos::ParameterList& params, const Vector* v0,
                               IterationObserver& observer, const RCP<const MultiVector>& freeMotions);
// No constraints (m = 0): one Krylov solve of Q v = b to the KKT tolerance, whichever method.
SolveResult solveUnconstrained(const ContactQP& qp, const MultigridInput& multigrid,
                               const Teuchos::ParameterList& params, const Vector* v0,
                               IterationObserver& observer);

// The 2-norms of A's rows, on its range map (1 for an empty row): the scale of each
// constraint, a weighted gap's being its facets' measure. Collective if the maps differ.
Vector constraintRowNorms(const CrsMatrix& A);

// Largest alpha in (0, inf] with x + alpha dx >= 0, over all ranks (inf if dx >= 0).
double maxStepToBoundary(const Vector& x, const Vector& dx);

// Objective J(v) = 1/2 v^T Q v - b^T v, given Qv.
double objective(const ContactQP& qp, const Vector& v, const Vector& Qv);

// Scales of the problem from one rough unconstrained solve Q v_hat = b, used to build
// starting points: a displacement scale and an energy scale, both positive. A body that
// only its contact holds (Q singular) is solved with every constraint held by a spring.
struct ProblemScales {
  double displacement = 1.0;
  double energy = 1.0;
  int krylovIterations = 0;
};
// `newton` must have its weights set to zero (H = Q); they are zero again on return.
ProblemScales problemScales(const ContactQP& qp, const MultigridInput& multigrid, NewtonSystemSolver& newton, const Vector& v0,
                            bool freeWithoutContact);

// Adds the end-of-solve data (objective, multipliers, KKT measures, active set) to `result`.
void finishResult(const ContactQP& qp, const Vector& v, const Vector& lambda, const Vector& slack,
                  SolveResult& result);

// Ends a solve: sets the result's status and message. Returns false, for "continue?" tests.
bool stopWith(SolveResult& result, SolveStatus status, std::string message);

// The stopping tests both methods share, on the "Solver" list's kkt: tolerance and maximum
// iterations. Each sets the result's status when it stops the solve.
struct StoppingRule {
  double tolerance = 1e-8;
  int maxIterations = 200;

  explicit StoppingRule(const Teuchos::ParameterList& params);
  // Every relative KKT measure at most the tolerance.
  bool converged(const KKTMeasures& kkt, SolveResult& result) const;
  // `iterations` main iterations done and no more allowed.
  bool outOfIterations(int iterations, SolveResult& result) const;
};

// Counts one Krylov solve of `iterations` towards a Newton step whose solves took
// `stepIterations` in all (this one included).
void countKrylovSolve(SolveResult& result, int iterations, int stepIterations);

// Fills v with the initial guess or zero.
RCP<Vector> initialDisplacement(const ContactQP& qp, const Vector* v0);

// Absolute Krylov tolerance of a truncated Newton step, ||H dv - rhs|| <= tolerance, for a
// nonlinear residual of norm ||F|| (||grad psi|| for the primal method, the KKT residual
// for the primal-dual method, where the solve's error enters F's first block only):
//   "constant":          eta ||F|| (the inexact Newton condition of the paper's (27));
//   "adaptive":          min(eta ||rhs||, max(floor, safety * residualScale)), the residual
//                        scale following the barrier parameter; tailSafety instead of safety
//                        when stationarityOnly (the method's other KKT measures are met);
//   "eisenstat-walker":  eta_k ||F|| with Eisenstat and Walker's choice 2,
//                        eta_k = 0.9 (||F_k|| / ||F_k-1||)^2, safeguarded, at most eta;
//   "relative":          eta ||rhs||, a fixed residual reduction for every Newton system.
struct ForcingRule {
  ForcingType type = ForcingType::Reduction;
  double eta = 0.3;
  double safety = 0.3;
  double tailSafety = 0.01;
  double reductionSafeguard = 1.0;
  bool stationarityOnly = false;  // set by the method before each Newton step
  double floor = 0.0;
  // Eisenstat-Walker state: the previous nonlinear residual norm and forcing term.
  double previousNorm = -1.0, previousEta = 0.0;

  void restart() { previousNorm = -1.0; }
  // nonlinearNorm: the norm of the nonlinear residual the Newton step reduces (EW only).
  // An absolute tolerance; with "reduction" the loosest one allowed, startReduction() and
  // floor do the rest (NewtonSystemSolver::solve).
  double tolerance(double rhsNorm, double residualScale, double nonlinearNorm);
  // The factor by which a solve reduces its start's residual ("reduction"), else 0.
  double startReduction() const { return type == ForcingType::Reduction ? eta : 0.0; }
};
ForcingRule forcingRule(const Teuchos::ParameterList& params, double floor);

}  // namespace signorini::detail
