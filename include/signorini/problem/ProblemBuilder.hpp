#pragma once
/// \file
/// From a validated "Problem" parameter list to the distributed discrete problem: mesh
/// (box generator or Gmsh file, made on rank 0 only), METIS partition, P_k space and the
/// assembled ContactQP.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "signorini/assembly/FiniteElementSpace.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

/// Receives what building a problem measured, on every rank (the same figures on all); the
/// default methods do nothing.
class BuildObserver {
 public:
  virtual ~BuildObserver() = default;
  /// A phase ("mesh and space", "assembly") took this long on the slowest rank.
  virtual void onPhase(const std::string& phase, double seconds) { (void)phase, (void)seconds; }
  /// Each rank's peak resident set grew by this much over mesh and space (rank order; MiB):
  /// rank 0's includes the serial phase's transient buffers (METIS, hash tables) where the
  /// mesh is read and partitioned there.
  virtual void onSetupMemory(const std::vector<double>& peakGrowthMiBPerRank) { (void)peakGrowthMiBPerRank; }
  /// A remark for the run log on how the problem was built where it is not what the parameters
  /// ask for, e.g. a mesh file read by rank 0 alone and why; on rank 0 at least.
  virtual void onNote(const std::string& note) { (void)note; }
};

/// A BuildObserver that keeps the figures.
class BuildRecorder : public BuildObserver {
 public:
  void onPhase(const std::string& phase, double seconds) override;
  void onSetupMemory(const std::vector<double>& peakGrowthMiBPerRank) override { setupPeakMiB = peakGrowthMiBPerRank; }
  void onNote(const std::string& note) override { notes.push_back(note); }
  double setupSeconds = 0, assemblySeconds = 0;  ///< max over ranks
  std::vector<double> setupPeakMiB;              ///< per rank
  std::vector<std::string> notes;                ///< in the order they came
};

/// A distributed problem ready to solve: the QP and what output needs (the definition and
/// the space). Move-only; shares the space with a matrix-free Q (which applies Q on it, so a
/// copy of the QP stays valid without the problem) and the QP's Tpetra objects.
struct AssembledProblem {
  AssembledProblem();
  AssembledProblem(AssembledProblem&&) noexcept;
  AssembledProblem& operator=(AssembledProblem&&) noexcept;
  ~AssembledProblem();

  ProblemDefinition definition;
  /// The distributed P_k space (for output and the pressure).
  std::shared_ptr<const FiniteElementSpace> space;
  ContactQP qp;
  MultigridInput multigrid;  ///< the mesh's coordinates and, where it has them, its grids
};

/// Whether the caller needs Q as a matrix: `Assembled` (to export it, say) resolves a
/// "stiffness: operator" of "auto" to "assembled"; a value the user chose stays.
enum class StiffnessNeed { AsConfigured, Assembled };

/// Builds the problem a "Problem" list describes; `baseDirectory` resolves a relative
/// "mesh: file"; the observer, if any, receives the phases' times and memory and notes for the
/// run log. Collective; throws InputError naming the parameter or file at fault.
AssembledProblem buildProblem(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                              const std::string& baseDirectory = ".",
                              StiffnessNeed stiffness = StiffnessNeed::AsConfigured, BuildObserver* observer = nullptr);

}  // namespace signorini
