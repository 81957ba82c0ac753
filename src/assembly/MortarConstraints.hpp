#pragma once
// Private to the library: the constraints of a contact pair between two bodies
// (ContactPair::masterBoundary). For every node j of the slave boundary Gamma_s, the weighted
// gap
//   integral over Gamma_s of psi_j (g0 + n . (u_s - u_m o pi)) >= 0,
// psi_j the multiplier function of the slave side (ContactMultiplierBasis; the dual basis for
// "dual mortar", so that the multiplier is the pressure's nodal value), n the outward normal
// of the slave facet, pi the projection along n onto the master boundary and g0 the initial
// distance along n to it. As a row of A v <= d: the slave terms integral psi_j phi_k n . u_k,
// the master terms -integral psi_j (N_l o pi) n . u_l, d_j = integral psi_j g0.
//
// Integration is segment based (Popp, Gitterle, Gee and Wall; Puso and Laursen): each master
// facet facing a slave facet is projected onto it along n and clipped to it (an interval in
// 2D, a convex polygon in 3D, cut into triangles), and each piece is integrated by a Gauss
// rule exact for the products of the pieces' polynomial functions, so that a pressure that
// is constant passes from one side to the other exactly (the contact patch test). Each rank
// integrates its own slave facets; the master facets it needs come from the ranks that hold
// them, chosen by the bounding box of its slave facets (no rank gathers a whole surface).
#include <vector>

#include "assembly/DistributedSpace.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

struct MortarRows {
  RCP<CrsMatrix> A;  // rows on constraintMap, columns the owned DOFs of both bodies
  RCP<Vector> d;
};

// The rows of `pair` (the other rows of constraintMap empty). constraintOf: the pair's
// constraint of each overlap node (overlapNodeConstraints), -1 off the slave boundary. Throws
// InputError for a pair it cannot pose: the same boundary on both sides or on one body, a
// formulation it does not support, slave facets that no master facet covers, bodies that
// overlap at the start (ContactPair::initialOverlapTolerance). Collective.
MortarRows mortarConstraints(const DistributedSpace& space, const ContactPair& pair,
                             const std::vector<long long>& constraintOf, const RCP<const Map>& constraintMap);

}  // namespace signorini
