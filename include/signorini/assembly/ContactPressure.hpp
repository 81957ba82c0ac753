#pragma once
/// \file
/// The contact pressure as a field on the contact boundary Gamma_c. The multipliers of the
/// node-wise constraints are nodal forces, f_i = -lambda_i; the pressure is their
/// boundary-L2 representative p_h = sum_j p_j phi_j, the solution of M p = f with the
/// consistent mass matrix M_ij = integral over Gamma_c of phi_i phi_j, restricted to the
/// loaded facets (those with an active node): p = 0 on the rest. On the whole of Gamma_c, the
/// projection of a pressure that drops to zero at the contact edge rings outside it
/// (alternating lobes of 10% of the peak on a P1 Hertz profile); restricted, p_h vanishes
/// where there is no contact. A uniform pressure is recovered exactly for every element
/// degree (unlike a division by lumped weights, which fails on P2 triangles, whose vertex
/// functions integrate to zero).
/// With weighted gaps (ContactFormulation::weightedGap) the multipliers already are the
/// pressure's coefficients, p = -sum lambda_a psi_a in the multiplier basis psi
/// (ContactMultiplierBasis: phi itself but for P2 tetrahedra), and need no solve. With the
/// dual mortar basis (ContactFormulation::dualMortar) -lambda_a is the pressure's local mean
/// at node a, shown as its nodal value.
#include <array>
#include <memory>
#include <vector>

#include "signorini/assembly/ContactStatistics.hpp"
#include "signorini/assembly/FiniteElementSpace.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

/// Pressure values at quadrature points of the contact boundary (exact for degree 2k + 2),
/// this rank's facets: points (dim coordinates each), weights (true measure), pressures.
struct ContactPressureSamples {
  int dim = 0;
  std::vector<double> points, weights, pressures;
};

/// How the pressure is recovered from nodal-constraint multipliers (weighted gaps need no
/// recovery, but for the patch average of the dual basis' nodal pressures): ContactPressure's
/// consistent pressure(), lumpedPressure() or patchPressure(); Auto is lumped for 2D P1, patch
/// for 3D P1 and consistent for P2/P3, chosen by the Hertz studies (doc/hertz-validation.md).
enum class PressureRecovery { Auto, Consistent, Lumped, Patch };

class ContactPressure {
 public:
  /// Collective. `constraintMap` is A's range map: one constraint per contact node, as the
  /// assembler numbers them. The recovery is that of the contact pair problem.contacts[pair]:
  /// its fields are 0 on the other pairs' constraints. Assembles M once.
  /// `space` is the one the problem was assembled on (AssembledProblem::space) and must
  /// outlive the recovery.
  ContactPressure(const FiniteElementSpace& space, const ProblemDefinition& problem,
                  const RCP<const Map>& constraintMap, std::size_t pair = 0);

  /// The pressure's nodal values on the constraint map, 0 off the nodes L of the facets that
  /// have a node with active != 0. Nodal constraints: M_LL p_L = -lambda_L (paper's sign,
  /// lambda <= 0), solved by CG on the symmetrically diagonal-scaled M to a relative residual
  /// of 1e-13; throws Error if CG does not get there (a mass matrix: it always should).
  /// Weighted gaps: the nodal values of -sum lambda_a psi_a. Collective.
  RCP<Vector> pressure(const Vector& lambda, const Vector& active) const;

  /// p_j = -lambda_j / w_j with the HRZ-lumped boundary weights w (row sums for P1) on the
  /// nodes of the loaded facets, 0 elsewhere. For P1 it is the multiplier of a dual mortar
  /// method with node-wise constraints. With weighted gaps, the same as pressure(). Collective.
  RCP<Vector> lumpedPressure(const Vector& lambda, const Vector& active) const;

  /// The lumped pressure averaged over each node's facet patch: p_i = sum_j f_j / sum_j w_j
  /// over the active nodes j that share a contact facet with node i (i included), f = -lambda,
  /// w the HRZ weights; p_i = 0 where i is not active. Exact for a uniform pressure; removes
  /// the node-to-node oscillation of P1 nodal forces on meshes whose boundary vertices
  /// alternate in valence (structured tetrahedral meshes). Dual mortar: the same average of the
  /// nodal pressures -lambda_j with the weights w_j = integral of psi_j (f_j = -lambda_j w_j);
  /// other weighted gaps: the same as pressure(). Collective.
  RCP<Vector> patchPressure(const Vector& lambda, const Vector& active) const;

  /// The pressure by the recovery `how`. Collective.
  RCP<Vector> recover(PressureRecovery how, const Vector& lambda, const Vector& active) const;

  /// The contact area: the lumped boundary measure (HRZ weights) of the active nodes, each
  /// node standing for its share of the boundary. Collective.
  double activeMeasure(const Vector& active) const;

  /// A field on the constraints (pressure, active indicator) at the overlap nodes of the
  /// space, in overlapSpaceNodes() order, 0 off Gamma_c. Collective.
  std::vector<double> overlapNodeValues(const Vector& values) const;

  /// p_h at the quadrature points of this rank's contact facets. Collective.
  ContactPressureSamples samples(const Vector& pressure) const;

  /// 1 on the owned DOFs of the contact boundary's nodes (the slave side of a pair of
  /// bodies), 0 elsewhere, on the space's owned DOF map.
  RCP<Vector> contactBoundaryDofs() const;

  /// 1 on the pair's constraints, 0 on the other pairs', on the constraint map.
  const Vector& pairConstraints() const { return *pairRows_; }

  const CrsMatrix& massMatrix() const { return *mass_; }
  int dim() const;
  /// True for contact between two bodies (ContactPair::masterBoundary given).
  bool betweenBodies() const { return betweenBodies_; }

 private:
  /// The nodal values of sum_a c_a psi_a (weighted gaps; c itself for the dual basis), on the
  /// constraint map.
  RCP<Vector> nodalValues(const Vector& coefficients) const;
  /// Pressure values at this rank's facet nodes: overlap constraint values, by local index.
  std::vector<double> overlapValues(const Vector& pressure) const;
  /// 1 on the owned constraints of facets with an active node, else 0.
  RCP<Vector> loadedNodes(const Vector& active) const;
  template <class Visit>
  void forEachQuadraturePoint(const Vector& pressure, Visit&& visit) const;

  struct MultiplierBasis;  ///< the basis psi of the multipliers on the contact facets

  const FiniteElementSpace& space_;
  std::shared_ptr<const MultiplierBasis> multipliers_;
  bool weightedGap_;
  bool betweenBodies_;
  RCP<const Map> constraintMap_, overlapMap_;
  RCP<CrsMatrix> mass_, scaledMass_;
  RCP<CrsMatrix> patchSum_;  ///< M's pattern with unit values: sums over a node's facet patch
  RCP<Vector> scaling_;  ///< D^-1/2, D = diag(M)
  RCP<Vector> lumpedWeights_;
  RCP<Vector> pairRows_;
  std::vector<std::pair<long long, int>> facets_;  ///< (cell, local facet) of this rank's contact facets
  std::vector<long long> overlapNodeConstraint_;  ///< per overlap space node, -1 for none
  std::vector<int> overlapIndex_;  ///< local index in overlapMap_ of each space node, -1 off Gamma_c
};

/// The statistics of the recovery's contact pair in a solution with recovered pressure p and
/// active constraints `active` (1 or 0 per constraint). Collective.
ContactStatistics contactStatistics(const ContactPressure& recovery, const Vector& pressure, const CrsMatrix& A,
                                    const Vector& lambda, const Vector& active,
                                    const std::array<double, 3>& obstacleDirection);

}  // namespace signorini
