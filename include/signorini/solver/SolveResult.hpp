#pragma once
/// \file
/// What an interior point solve returns: the solution, its KKT measures and the counters of
/// the paper's Table 2, which every method has. The history of the Newton steps and the
/// method-specific counters go to observers (IterationObserver, SolveRecorder).
#include <numeric>
#include <string>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/KKTMeasures.hpp"

namespace signorini {

enum class SolveStatus { Converged, IterationLimit, LineSearchFailure, KrylovFailure, NumericalBreakdown };

const char* toString(SolveStatus status);

/// One Newton step.
struct NewtonStepRecord {
  int outer = 0;             ///< main iteration
  int inner = 0;             ///< inner (Newton) iteration within it; 0 for primal-dual
  double mu = 0;             ///< barrier parameter of the step
  double objective = 0;      ///< J(v) after the step
  KKTMeasures kkt;           ///< after the step
  double step = 0;           ///< step length taken
  int krylovIterations = 0;  ///< of this step's solve(s)
  double seconds = 0;        ///< wall time since the start of the solve
};

/// One active-set finish attempt of the primal-dual method.
struct ActiveSetFinishRecord {
  int outer = 0;                  ///< the main iteration it followed
  bool accepted = false;          ///< it met every KKT tolerance and ended the solve
  long long krylovIterations = 0;  ///< of its solve (to the KKT tolerance)
};

/// The outcome of InteriorPointSolver::solve, the same on every rank but for the local
/// entries of v and lambda.
struct SolveResult {
  SolveStatus status = SolveStatus::IterationLimit;
  std::string message;           ///< what happened and, on failure, what to change
  RCP<Vector> v;                 ///< displacement
  RCP<Vector> lambda;            ///< multipliers, paper's sign: lambda <= 0
  double objective = 0;          ///< J(v)
  KKTMeasures kkt;
  long long activeConstraints = 0;

  int outerIterations = 0;       ///< the paper's "it"
  int newtonSteps = 0;           ///< Newton systems solved
  int gradientEvaluations = 0;   ///< the paper's "ngr"
  int functionEvaluations = 0;   ///< the paper's "nfc"
  long long krylovIterations = 0;  ///< CG iterations of the whole solve, the active-set finish's included
  int maxKrylovPerNewton = 0;      ///< largest CG count of one Newton system of the barrier steps
  int preconditionerSetups = 0;  ///< AMG hierarchies built
  /// Entries of each multigrid level's matrix in the last build, finest first (0 for a fine
  /// P2/P3 level applied without a matrix); empty without a multigrid preconditioner.
  std::vector<long long> multigridNonzeros;
  /// The sum of multigridNonzeros over its first: the cost of a cycle against the fine level's
  /// (MueLu's "operator complexity"); 0 where the fine level has no matrix.
  double operatorComplexity() const {
    if (multigridNonzeros.empty() || multigridNonzeros.front() == 0) return 0.0;
    return static_cast<double>(std::accumulate(multigridNonzeros.begin(), multigridNonzeros.end(), 0LL)) /
           static_cast<double>(multigridNonzeros.front());
  }
  double seconds = 0;

  bool converged() const { return status == SolveStatus::Converged; }
};

}  // namespace signorini
