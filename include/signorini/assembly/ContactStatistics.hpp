#pragma once
/// \file
/// Totals of one solution's contact forces and pressure, reported in the log and in
/// summary.json. The same on every rank.
#include <array>
#include <optional>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini {

struct ContactStatistics {
  int dim = 0;
  /// the obstacle's (or the master body's) force on the contact boundary: A^T lambda summed
  /// per component over its nodes' DOFs (with the mesh; over every DOF without)
  std::array<double, 3> force{{0, 0, 0}};
  /// between two bodies, the slave side's force on the master body: A^T lambda summed over
  /// the DOFs off the contact boundary, which balances `force`
  std::optional<std::array<double, 3>> masterForce;
  double normalForce = 0;  ///< force . obstacle direction (>= 0 when pressing)
  double area = 0;          ///< lumped boundary measure of the active nodes (a length in 2D); NaN without a mesh
  double peakPressure = 0;  ///< largest nodal value of p_h; NaN without a mesh
  long long activeNodes = 0;               ///< active constraints (one per contact node)
};

/// The statistics of several contact pairs together: forces, normal forces (each along its
/// pair's direction), areas and active nodes summed, the largest peak pressure.
ContactStatistics combinedStatistics(const std::vector<ContactStatistics>& pairs);

/// What a QP and its solution tell without the mesh (a QP handed over by another code): the
/// obstacle's force A^T lambda summed per component (multigrid.blockSize of them, DOF
/// blockSize * node + component), its length as the normal force (one obstacle direction), and
/// the active constraints (activeIndicator); area and peak pressure are NaN. Collective.
ContactStatistics contactStatistics(const ContactQP& qp, const MultigridInput& multigrid, const Vector& v,
                                    const Vector& lambda);

}  // namespace signorini
