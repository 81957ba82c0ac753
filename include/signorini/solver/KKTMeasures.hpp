#pragma once
/// \file
/// The optimality measures of min 1/2 v^T Q v - b^T v s.t. c = A v - d <= 0 with multipliers
/// lambda <= 0 (the paper's sign), absolute and relative:
///   stationarity       ||Q v - b - A^T lambda||          / max(||b||, ||A^T lambda||)
///   complementarity    max_i |lambda_i c_i|, relative: m max_i |lambda_i c_i| (a bound of the
///                      duality gap, so of the error in J) / max(|b^T v|, v^T Q v)
///   primal feasibility max(0, max_i c_i)                  / max(||v||_inf, ||d||_inf)
///   dual feasibility   max(0, max_i lambda_i)             / ||lambda||_inf
/// (a zero scale counts as 1).
#include <cmath>

#include <cmath>
#include <vector>

#include "signorini/solver/ContactQP.hpp"

namespace signorini {

struct KKTMeasures {
  double stationarity = 0, complementarity = 0, primalFeasibility = 0, dualFeasibility = 0;  ///< relative
  double stationarityAbs = 0, complementarityAbs = 0, primalFeasibilityAbs = 0, dualFeasibilityAbs = 0;

  double worst() const;  ///< largest relative measure
};

KKTMeasures kktMeasures(const ContactQP& qp, const Vector& v, const Vector& lambda);

/// Which constraints are active: the multiplier is large against a force scale
/// (max(||b||_inf, ||lambda||_inf)) compared with the slack against a displacement scale
/// (max(||v||_inf, ||d||_inf)). Each row i of A is first normalised by its 2-norm r_i (the
/// multiplier becomes lambda_i r_i, the slack s_i / r_i), so that rows in other units than a
/// displacement, such as weighted gaps, are judged alike; node-wise rows -n.u <= g have r_i = 1.
class ActiveSetCriterion {
 public:
  /// Collective.
  ActiveSetCriterion(const ContactQP& qp, const Vector& v, const Vector& lambda);
  /// Constraint i (local index on A's range map) with multiplier lambda and slack d_i - A_i v.
  bool isActive(LocalOrdinal i, double lambda, double slack) const {
    const double r = rowNorm_[i];
    return std::abs(lambda * r) * displacementScale_ > std::abs(slack / r) * forceScale_;
  }
  /// Whether constraint i is nearly degenerate: its multiplier and its slack both at most
  /// `fraction` of their scales, so that which side of isActive() it falls on hardly matters.
  bool isNearlyDegenerate(LocalOrdinal i, double lambda, double slack, double fraction) const {
    const double r = rowNorm_[i];
    return std::abs(lambda * r) <= fraction * forceScale_ && std::abs(slack / r) <= fraction * displacementScale_;
  }
  /// The weight (force per displacement, in constraint i's units) at which a force of the
  /// force scale makes a displacement of `fraction` times the displacement scale.
  double weight(LocalOrdinal i, double fraction) const {
    const double r = rowNorm_[i];
    return forceScale_ / (fraction * displacementScale_ * r * r);
  }

 private:
  std::vector<double> rowNorm_;  ///< per local constraint, 1 for an empty row
  double forceScale_ = 1, displacementScale_ = 1;
};

/// 1 on the constraints ActiveSetCriterion calls active at (v, lambda), 0 elsewhere, on A's range map.
RCP<Vector> activeIndicator(const ContactQP& qp, const Vector& v, const Vector& lambda);

}  // namespace signorini
