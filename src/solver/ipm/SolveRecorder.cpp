#include "signorini/solver/SolveRecorder.hpp"

namespace signorini {

void SolveRecorder::onStart(const std::string&, long long, long long) {
  history_.clear();
  innerIterations_.clear();
  finishes_.clear();
}

long long SolveRecorder::activeSetFinishKrylov() const {
  long long total = 0;
  for (const ActiveSetFinishRecord& attempt : finishes_) total += attempt.krylovIterations;
  return total;
}

}  // namespace signorini
