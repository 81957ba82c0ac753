#pragma once
// What a solution shows in ParaView besides the pressure: the displacement, the normal
// contact force and the gap on this rank's overlap nodes (overlapSpaceNodes() order), and the
// von Mises stress on its cells (mesh() order). Mechanics computed here, written by io.
#include <vector>

#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class DistributedSpace;

struct SolutionFields {
  std::vector<double> displacement;        // dim values per node
  std::vector<double> normalContactForce;  // (A^T lambda) . n_o, n_o the obstacle direction
  std::vector<double> gap;  // g + n_o . u on the contact boundary (a pair of bodies: the weighted gap), 0 elsewhere
  std::vector<double> vonMisesStress;      // at each cell's centroid
};

// v on the owned DOF map, d and lambda on A's range map. The gap of a pair of bodies is its
// constraint's slack over the constraint's weight, (d - A v)_j / integral psi_j. Collective.
SolutionFields solutionFields(const DistributedSpace& space, const ProblemDefinition& problem, const CrsMatrix& A,
                              const Vector& d, const Vector& v, const Vector& lambda);

}  // namespace signorini
