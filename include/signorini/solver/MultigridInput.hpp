#pragma once
/// \file
/// What the preconditioners of the Newton systems may use of a problem besides its QP. Every
/// member is optional: without any, MueLu builds an algebraic multigrid of Q alone. A box or
/// refined Gmsh mesh of buildProblem fills in its grids; a library user fills in what their
/// mesh gives (a signorini::SimplexGrid of their cells for the geometric P_k -> P1 step).
#include <memory>
#include <vector>

#include "signorini/core/GeometricGrid.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/ContactQP.hpp"

namespace signorini {

struct MultigridInput {
  int blockSize = 1;  ///< unknowns per node (dof = blockSize * node + component)
  RCP<const MultiVector> coordinates;  ///< node coordinates on a node map (MueLu, rigid body modes)
  /// rigid body modes on Q's domain map (MueLu, the rigid body check); without them,
  /// nearNullspace() makes them from `coordinates` where they are needed
  RCP<const MultiVector> nullspace;
  /// Of a problem of several bodies apart (no node in common): the body, 0 to count - 1, of
  /// each row of `coordinates`. The rigid body check then looks for the motions of each body
  /// (bodyMotions()); empty: one body.
  std::vector<int> nodeBodies;
  std::shared_ptr<const GeometricGrid> grid;  ///< a P1 grid of the mesh (geometric multigrid)
  /// the P1 stiffness of `grid`, DOF blockSize * vertex + component, any one-to-one row map,
  /// prescribed DOFs as unit rows: for a Lagrange P_k space, k > 1, that of its mesh (P^T Q P
  /// for P the P1 interpolation from the grid's vertices to Q's DOFs) or of its mesh refined
  /// at the nodes. The geometric multigrid's first coarse level starts from it; with a
  /// StiffnessOperator Q, Q is never assembled.
  RCP<const CrsMatrix> gridStiffness;
  /// Q assembled, when ContactQP::Q is an operator of its own (matrix-free): the
  /// preconditioners and scale estimates use it, every application of Q uses Q.
  RCP<const CrsMatrix> assembledQ;

  /// `nullspace`, or without it the rigid body modes made from `coordinates` when blockSize is
  /// their dimension and their rows are the nodes of qp.Q's DOFs on every rank (a new
  /// MultiVector, 3 or 6 columns), or null. Collective.
  RCP<const MultiVector> nearNullspace(const ContactQP& qp) const;

  /// The rigid body modes of each body: nearNullspace(qp) with its columns repeated per body
  /// of `nodeBodies`, each copy zero off its body's DOFs; nearNullspace(qp) itself for one
  /// body. Collective.
  RCP<const MultiVector> bodyMotions(const ContactQP& qp) const;
};

/// Q as an assembled matrix: multigrid.assembledQ if given, else qp.Q if it is a CrsMatrix,
/// else null.
RCP<const CrsMatrix> assembledStiffness(const ContactQP& qp, const MultigridInput& multigrid);

}  // namespace signorini
