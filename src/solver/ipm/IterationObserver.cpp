#include "signorini/solver/IterationObserver.hpp"

#include <cstdio>

namespace signorini {

const char* toString(SolveStatus status) {
  switch (status) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::IterationLimit: return "iteration limit";
    case SolveStatus::LineSearchFailure: return "line search failure";
    case SolveStatus::KrylovFailure: return "Krylov failure";
    case SolveStatus::NumericalBreakdown: return "numerical breakdown";
  }
  return "unknown";
}

void IterationLog::onStart(const std::string& method, long long n, long long m) {
  if (!print_) return;
  char line[256];
  std::snprintf(line, sizeof line, "Method: %s, n = %lld, m = %lld\n", method.c_str(), n, m);
  out_ << line;
  std::snprintf(line, sizeof line, "%5s %5s %10s %16s %9s %9s %9s %9s %7s %6s %9s\n", "it", "inner", "mu",
                "objective", "stat", "compl", "pfeas", "dfeas", "step", "krylov", "time[s]");
  out_ << line << std::flush;
}

void IterationLog::onNewtonStep(const NewtonStepRecord& s) {
  if (!print_) return;
  char line[256];
  std::snprintf(line, sizeof line, "%5d %5d %10.3e %16.9e %9.2e %9.2e %9.2e %9.2e %7.4f %6d %9.3f\n", s.outer,
                s.inner, s.mu, s.objective, s.kkt.stationarity, s.kkt.complementarity, s.kkt.primalFeasibility,
                s.kkt.dualFeasibility, s.step, s.krylovIterations, s.seconds);
  out_ << line << std::flush;
}

void IterationLog::onActiveSetFinish(const ActiveSetFinishRecord& attempt) {
  ++finishAttempts_;
  finishAccepted_ = attempt.accepted;
  finishKrylov_ += attempt.krylovIterations;
}

void IterationLog::onFinish(const SolveResult& r) {
  if (!print_) return;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s after %d main iterations, %d Newton steps, %lld Krylov iterations (max %d per step), "
                "%.3f s\n  objective %.12e, active constraints %lld, KKT: stat %.2e compl %.2e pfeas %.2e "
                "dfeas %.2e\n",
                toString(r.status), r.outerIterations, r.newtonSteps, r.krylovIterations, r.maxKrylovPerNewton,
                r.seconds, r.objective, r.activeConstraints, r.kkt.stationarity, r.kkt.complementarity,
                r.kkt.primalFeasibility, r.kkt.dualFeasibility);
  out_ << line;
  if (finishAttempts_ > 0)
    out_ << "  active-set finish: " << finishAttempts_ << " tried, "
         << (finishAccepted_ ? "the last step" : "none accepted") << ", " << finishKrylov_ << " Krylov iterations\n";
  if (!r.multigridNonzeros.empty()) {
    out_ << "  multigrid: matrix entries per level";
    for (std::size_t l = 0; l < r.multigridNonzeros.size(); ++l) out_ << (l ? ", " : " ") << r.multigridNonzeros[l];
    char complexity[64];
    std::snprintf(complexity, sizeof complexity, " (operator complexity %.2f)", r.operatorComplexity());
    out_ << (r.operatorComplexity() > 0 ? complexity : "") << "\n";
  }
  if (!r.converged()) out_ << "  " << r.message << "\n";
  out_ << std::flush;
}

void ObserverList::onStart(const std::string& method, long long n, long long m) {
  for (IterationObserver* o : observers_) o->onStart(method, n, m);
}
void ObserverList::onNewtonStep(const NewtonStepRecord& step) {
  for (IterationObserver* o : observers_) o->onNewtonStep(step);
}
void ObserverList::onMainIteration(int outer, int innerIterations) {
  for (IterationObserver* o : observers_) o->onMainIteration(outer, innerIterations);
}
void ObserverList::onActiveSetFinish(const ActiveSetFinishRecord& attempt) {
  for (IterationObserver* o : observers_) o->onActiveSetFinish(attempt);
}
void ObserverList::onFinish(const SolveResult& result) {
  for (IterationObserver* o : observers_) o->onFinish(result);
}

}  // namespace signorini
