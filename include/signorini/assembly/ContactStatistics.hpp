#pragma once
/// \file
/// Totals of one solution's contact forces and pressure, reported in the log and in
/// summary.json. The same on every rank.
#include <array>

namespace signorini {

struct ContactStatistics {
  int dim = 0;
  std::array<double, 3> force{{0, 0, 0}};  ///< the obstacle's force on the body: A^T lambda summed per component
  double normalForce = 0;                  ///< force . obstacle direction (>= 0 when pressing)
  double area = 0;                         ///< lumped boundary measure of the active nodes (a length in 2D)
  double peakPressure = 0;                 ///< largest nodal value of p_h
  long long activeNodes = 0;               ///< active constraints (one per contact node)
};

}  // namespace signorini
