#pragma once
/// \file
/// Observers of an interior point solve, kept out of the algorithm (Ginkgo's loggers):
/// the solver reports each Newton step, each main iteration's end and each active-set finish;
/// what is printed or stored is the observer's choice (SolveRecorder keeps it all).
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

#include "signorini/solver/SolveResult.hpp"

namespace signorini {

/// Receives the solve's progress on every rank (the data are the same on all of them); the
/// default methods do nothing. Called synchronously from the solve: keep it cheap.
class IterationObserver {
 public:
  virtual ~IterationObserver() = default;
  virtual void onStart(const std::string& method, long long n, long long m) { (void)method, (void)n, (void)m; }
  virtual void onNewtonStep(const NewtonStepRecord& step) { (void)step; }
  /// Main iteration `outer` (from 1) ended after `innerIterations` Newton steps (the paper's
  /// Figure 2; 1 for the primal-dual method).
  virtual void onMainIteration(int outer, int innerIterations) { (void)outer, (void)innerIterations; }
  /// The primal-dual method tried an active-set finish (Solver/primal-dual: active-set finish).
  virtual void onActiveSetFinish(const ActiveSetFinishRecord& attempt) { (void)attempt; }
  virtual void onFinish(const SolveResult& result) { (void)result; }
};

/// Passes every report to each of its observers, in order.
class ObserverList : public IterationObserver {
 public:
  ObserverList(std::initializer_list<IterationObserver*> observers) : observers_(observers) {}
  void onStart(const std::string& method, long long n, long long m) override;
  void onNewtonStep(const NewtonStepRecord& step) override;
  void onMainIteration(int outer, int innerIterations) override;
  void onActiveSetFinish(const ActiveSetFinishRecord& attempt) override;
  void onFinish(const SolveResult& result) override;

 private:
  std::vector<IterationObserver*> observers_;
};

/// The iteration log: one fixed-column line per Newton step, on rank 0 only, flushed as it goes.
class IterationLog : public IterationObserver {
 public:
  IterationLog(std::ostream& out, bool isRankZero) : out_(out), print_(isRankZero) {}
  void onStart(const std::string& method, long long n, long long m) override;
  void onNewtonStep(const NewtonStepRecord& step) override;
  void onActiveSetFinish(const ActiveSetFinishRecord& attempt) override;
  void onFinish(const SolveResult& result) override;

 private:
  std::ostream& out_;
  bool print_;
  int finishAttempts_ = 0;
  bool finishAccepted_ = false;
  long long finishKrylov_ = 0;
};

}  // namespace signorini
