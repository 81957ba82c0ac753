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
//
// The master boundary may cover the slave boundary in part. A slave node has a constraint
// where it lies on a covered piece of one of its facets (coveredSlaveNodes); the others have
// none, and on a facet with nodes of both kinds the multiplier functions of the nodes without
// a constraint are shared out equally among the others (Wohlmuth's modification at the
// boundary of the contact zone): the functions still sum to one on the covered pieces, so a
// constant pressure still passes from one side to the other exactly. A covered piece that
// holds none of its facet's nodes is not constrained.
#include <vector>

#include "assembly/DistributedSpace.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

struct MortarRows {
  RCP<CrsMatrix> A;  // rows on constraintMap, columns the owned DOFs of both bodies
  RCP<Vector> d;
  RCP<Vector> weights;  // the integral of each row's multiplier function over the covered pieces
};

// Whether each overlap node (overlapSpaceNodes() order) is a node of the slave boundary that
// lies on a covered piece of one of its facets, on any rank. Throws InputError for the same
// boundary on both sides and a formulation it does not support. Collective.
std::vector<char> coveredSlaveNodes(const DistributedSpace& space, const ContactPair& pair);

// The rows of `pair` (the other rows of constraintMap empty). constraintOf: the pair's
// constraint of each overlap node (overlapNodeConstraints), -1 off the slave boundary and at
// the nodes that coveredSlaveNodes leaves out. Throws InputError for a pair it cannot pose (as
// coveredSlaveNodes, and both sides on one body), a constraint whose multiplier function has no positive integral over the
// covered pieces, bodies that overlap at the start (ContactPair::initialOverlapTolerance).
// Collective.
MortarRows mortarConstraints(const DistributedSpace& space, const ContactPair& pair,
                             const std::vector<long long>& constraintOf, const RCP<const Map>& constraintMap);

}  // namespace signorini
