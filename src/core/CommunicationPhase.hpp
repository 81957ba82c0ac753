#pragma once
// Tells an MPI profiling library which phase of a run the messages belong to, through
// MPI_Pcontrol, the standard's hook for it (a no-op without such a library). The scaling
// benchmark's counters (bench/mpi_counters.cpp) count messages and bytes per phase.
#include <mpi.h>

namespace signorini::detail {

enum class CommunicationPhase : int {
  other = 0,
  meshAndSpace = 1,
  assembly = 2,
  solve = 3,                // the interior point iterations, but for the two below
  krylov = 4,               // Krylov iterations with their preconditioner applications
  preconditionerSetup = 5,  // multigrid, AMG and contact-subspace setups
  output = 6,
};

// The phase for the scope's lifetime; the enclosing one again afterwards.
class CommunicationPhaseScope {
 public:
  explicit CommunicationPhaseScope(CommunicationPhase phase) : previous_(current()) { enter(phase); }
  ~CommunicationPhaseScope() { enter(previous_); }
  CommunicationPhaseScope(const CommunicationPhaseScope&) = delete;
  CommunicationPhaseScope& operator=(const CommunicationPhaseScope&) = delete;

 private:
  static CommunicationPhase& current() {
    static CommunicationPhase phase = CommunicationPhase::other;
    return phase;
  }
  static void enter(CommunicationPhase phase) {
    current() = phase;
    MPI_Pcontrol(static_cast<int>(phase));
  }
  CommunicationPhase previous_;
};

}  // namespace signorini::detail
