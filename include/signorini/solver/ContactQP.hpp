#pragma once
/// \file
/// The discrete frictionless contact problem, the interface between problem assembly and the
/// interior point solvers (and where library users hand over their own problem):
///     minimise J(v) = 1/2 v^T Q v - b^T v   subject to   A v <= d.
#include <memory>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/core/GeometricGrid.hpp"

namespace signorini {

/// The QP's data as distributed Tpetra objects, shared (reference-counted) with the caller:
/// the solver keeps them for the duration of a solve and never changes them. Units are the
/// caller's: Q and b in force per displacement and force, d in displacement; the multipliers
/// of the solution are then forces (nodal constraints) or pressures (weighted gaps).
struct ContactQP {
  /// symmetric positive definite: a CrsMatrix, or a StiffnessOperator (matrix-free), or any
  /// Operator (then Qassembled, or no preconditioner)
  RCP<const Operator> Q;
  RCP<const Vector> b;                 ///< on Q's domain map
  RCP<const CrsMatrix> A;              ///< m x n: range map = constraints, domain map = Q's domain map
  RCP<const Vector> d;                 ///< on A's range map
  /// optional: rigid body modes on Q's domain map (for MueLu and the rigid body check); without
  /// them, nearNullspace() makes them from `coordinates` where they are needed
  RCP<const MultiVector> nullspace;
  RCP<const MultiVector> coordinates;  ///< optional: node coordinates on a node map (for MueLu)
  int blockSize = 1;                   ///< unknowns per node (dof = blockSize * node + component)
  std::shared_ptr<const GeometricGrid> grid;  ///< optional: a P1 grid of the mesh (geometric multigrid)
  /// optional: Q assembled, when Q is an operator of its own (matrix-free): the
  /// preconditioners and scale estimates use it, every application of Q uses Q.
  RCP<const CrsMatrix> Qassembled;
  /// optional: the P1 stiffness of `grid`, DOF blockSize * vertex + component, any one-to-one
  /// row map, prescribed DOFs as unit rows: for a Lagrange P_k space, k > 1, that of its mesh
  /// (P^T Q P for P the P1 interpolation from the grid's vertices to Q's DOFs) or of its mesh
  /// refined at the nodes. The geometric multigrid's first coarse level starts from it; with
  /// a StiffnessOperator Q, Q is never assembled.
  RCP<const CrsMatrix> gridStiffness;

  /// Q as an assembled matrix: Qassembled if given, else Q if it is a CrsMatrix, else null.
  RCP<const CrsMatrix> Qmatrix() const;
  /// `nullspace`, or without it the rigid body modes made from `coordinates` when blockSize is
  /// their dimension and their rows are the nodes of Q's DOFs on every rank (a new
  /// MultiVector, 3 or 6 columns), or null. Collective.
  RCP<const MultiVector> nearNullspace() const;
};

}  // namespace signorini
