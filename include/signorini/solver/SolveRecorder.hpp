#pragma once
/// \file
/// An observer that keeps what a solve reports: the Newton steps (history.csv), the inner
/// iterations of each main iteration (the paper's Figure 2) and the active-set finish
/// attempts. Pass it to InteriorPointSolver::solve, alone or in an ObserverList.
#include <vector>

#include "signorini/solver/IterationObserver.hpp"

namespace signorini {

class SolveRecorder : public IterationObserver {
 public:
  void onStart(const std::string& method, long long n, long long m) override;
  void onNewtonStep(const NewtonStepRecord& step) override { history_.push_back(step); }
  void onMainIteration(int, int innerIterations) override { innerIterations_.push_back(innerIterations); }
  void onActiveSetFinish(const ActiveSetFinishRecord& attempt) override { finishes_.push_back(attempt); }

  /// Every Newton step, in order.
  const std::vector<NewtonStepRecord>& history() const { return history_; }
  /// Newton steps per main iteration.
  const std::vector<int>& innerIterations() const { return innerIterations_; }
  /// Every active-set finish tried, in order.
  const std::vector<ActiveSetFinishRecord>& activeSetFinishes() const { return finishes_; }
  /// Whether the last finish tried was accepted (the solve ended on it).
  bool finishedOnActiveSet() const { return !finishes_.empty() && finishes_.back().accepted; }
  /// CG iterations of all finish attempts.
  long long activeSetFinishKrylov() const;

 private:
  std::vector<NewtonStepRecord> history_;
  std::vector<int> innerIterations_;
  std::vector<ActiveSetFinishRecord> finishes_;
};

}  // namespace signorini
