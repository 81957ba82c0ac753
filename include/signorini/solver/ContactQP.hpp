#pragma once
/// \file
/// The discrete frictionless contact problem, the interface between problem assembly and the
/// interior point solvers (and where library users hand over their own problem):
///     minimise J(v) = 1/2 v^T Q v - b^T v   subject to   A v <= d.
/// What the preconditioners may use besides it (coordinates, grids, an assembled Q) is a
/// MultigridInput of its own.
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

/// The QP's data as distributed Tpetra objects, shared (reference-counted) with the caller:
/// the solver keeps them for the duration of a solve and never changes them. Units are the
/// caller's: Q and b in force per displacement and force, d in displacement; the multipliers
/// of the solution are then forces (nodal constraints) or pressures (weighted gaps).
/// Prescribed displacements are eliminated symmetrically (doc/qp-format.md): a unit row and
/// column of Q, the prescribed value in b, and its column times the value moved into b.
struct ContactQP {
  /// symmetric positive definite (semidefinite along rigid motions the contact holds): a
  /// CrsMatrix, or a StiffnessOperator (matrix-free), or any Operator (then
  /// MultigridInput::assembledQ, or no preconditioner)
  RCP<const Operator> Q;
  RCP<const Vector> b;     ///< on Q's domain map
  RCP<const CrsMatrix> A;  ///< m x n: range map = constraints, domain map = Q's domain map
  RCP<const Vector> d;     ///< on A's range map
};

}  // namespace signorini
