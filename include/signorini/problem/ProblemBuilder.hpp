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
  double setupSeconds = 0, assemblySeconds = 0;  ///< max over ranks
  /// Rank 0's peak resident set during mesh and space, above its size before them (METIS'
  /// and the hash tables' transient buffers included): the serial phase's real cost when it
  /// is the process' largest allocation so far, as in the application.
  double serialMeshPeakMiB = 0;
  /// The same growth of the peak resident set over mesh and space, on every rank (rank order).
  std::vector<double> setupPeakMiBPerRank;
};

/// Whether the caller needs Q as a matrix: `Assembled` (to export it, say) resolves a
/// "stiffness: operator" of "auto" to "assembled"; a value the user chose stays.
enum class StiffnessNeed { AsConfigured, Assembled };

/// Builds the problem a "Problem" list describes; `baseDirectory` resolves a relative
/// "mesh: file". Collective; throws InputError naming the parameter or file at fault.
AssembledProblem buildProblem(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                              const std::string& baseDirectory = ".",
                              StiffnessNeed stiffness = StiffnessNeed::AsConfigured);

}  // namespace signorini
