#pragma once
/// \file
/// Observers of an interior point solve, kept out of the algorithm (Ginkgo's loggers):
/// the solver reports each Newton step; what is printed or stored is the observer's choice.
#include <ostream>
#include <string>

#include "signorini/solver/SolveResult.hpp"

namespace signorini {

/// Receives the solve's progress on every rank (the data are the same on all of them); the
/// default methods do nothing. Called synchronously from the solve: keep it cheap.
class IterationObserver {
 public:
  virtual ~IterationObserver() = default;
  virtual void onStart(const std::string& method, long long n, long long m) { (void)method, (void)n, (void)m; }
  virtual void onNewtonStep(const NewtonStepRecord& step) { (void)step; }
  virtual void onFinish(const SolveResult& result) { (void)result; }
};

/// The iteration log: one fixed-column line per Newton step, on rank 0 only, flushed as it goes.
class IterationLog : public IterationObserver {
 public:
  IterationLog(std::ostream& out, bool isRankZero) : out_(out), print_(isRankZero) {}
  void onStart(const std::string& method, long long n, long long m) override;
  void onNewtonStep(const NewtonStepRecord& step) override;
  void onFinish(const SolveResult& result) override;

 private:
  std::ostream& out_;
  bool print_;
};

}  // namespace signorini
