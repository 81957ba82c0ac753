#pragma once
// From a validated "Problem" parameter list to the distributed discrete problem: mesh
// (box generator or Gmsh file, made on rank 0 only), METIS partition, P_k space and the
// assembled ContactQP.
#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "signorini/ContactQP.hpp"
#include "signorini/DistributedSpace.hpp"
#include "signorini/ProblemDefinition.hpp"

namespace signorini {

struct AssembledProblem {
  ProblemDefinition definition;
  std::unique_ptr<DistributedSpace> space;  // this rank's mesh and space, global counts
  ContactQP qp;
  double setupSeconds = 0, assemblySeconds = 0;  // max over ranks
  // Rank 0's peak resident set during mesh and space, above its size before them (METIS'
  // and the hash tables' transient buffers included): the serial phase's real cost when it
  // is the process' largest allocation so far, as in the application.
  double serialMeshPeakMiB = 0;
};

// `baseDirectory` resolves a relative "mesh: file".
AssembledProblem buildProblem(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                              const std::string& baseDirectory = ".");

}  // namespace signorini
