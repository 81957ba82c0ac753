#pragma once
// Solves the Newton systems H dv = r of the interior point methods, H = Q + A^T D A applied
// matrix-free, by a preconditioned Belos Krylov method to an absolute residual tolerance
// (the truncated Newton step). The preconditioner is chosen by the "Preconditioner" list:
//   "none";
//   "amg of Q":  MueLu on Q, set up once and reused for every step;
//   "amg of H":  a multigrid of Q + A^T D A (assembled for MueLu's hierarchy, left an
//                operator on the fine level of the geometric one),
//                rebuilt when some constraint's relative weight D_i / (D_i + q_i) moved by
//                more than "amg of H: rebuild tolerance" since the last build (0: every
//                step, 1: never after the first; by default 0 with the geometric levels,
//                whose rebuild is an update, and 0.9 with MueLu's hierarchy alone, whose
//                rebuild is a whole setup), with MueLu's "reuse: type" if set; with a
//                contact correction, D_i is capped at "amg of H: weight cap" times q_i
//                (filtering: the correction solves the stiff contact part exactly);
// and its "contact correction": the AMG combined with an exact solve on the contact DOFs
// (see SubspaceCorrectedPreconditioner), "none", "additive" or "multiplicative". The
// multigrid's levels are MueLu's (MueLuPreconditioner) or, on a box mesh, geometric ones
// above MueLu's (GeometricMultigridPreconditioner): "hierarchy". A matrix-free Q (a
// StiffnessOperator, not assembled) takes "amg of H" on geometric levels, with the grid's P1
// stiffness (MultigridInput::gridStiffness) for a P_k space, and its contact rows for the contact
// correction.
#include <memory>

#include <Teuchos_ParameterList.hpp>

#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/linear/InitialGuessProjection.hpp"
#include "solver/linear/KrylovSolver.hpp"
#include "solver/preconditioner/ContactSubspaceSolver.hpp"
#include "solver/preconditioner/FreeMotionCorrection.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"
#include "solver/preconditioner/MultilevelPreconditioner.hpp"
#include "solver/preconditioner/SubspaceCorrectedPreconditioner.hpp"

namespace signorini {

class StiffnessParts;

// The choices of the "Preconditioner" list.
enum class PreconditionerType { None, AmgOfQ, AmgOfH };
enum class Hierarchy { Auto, Algebraic, Geometric };

class NewtonSystemSolver {
 public:
  // Sublists "Krylov" (see KrylovSolver) and "Preconditioner".
  static Teuchos::ParameterList validParameters();

  // Reads the "Krylov" and "Preconditioner" sublists of `params`, a list validated against
  // validParameters() (InteriorPointSolver's, or one that the caller validated); other
  // entries are the caller's. `freeMotions`: rigid body motions only the contact holds
  // (checkRigidBodyMotionsHeld), solved for exactly around the preconditioner
  // (FreeMotionCorrection); null if none. Throws InputError.
  NewtonSystemSolver(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& params,
                     RCP<const MultiVector> freeMotions = Teuchos::null);

  // Sets D and refreshes the preconditioner as its strategy says.
  void setWeights(const Vector& D);

  // Solves H x = r until ||r - H x|| <= absoluteTolerance, from x = 0 or, with Krylov/
  // "initial guess: previous solutions" > 0, from the projection on earlier solutions
  // (InitialGuessProjection). With `fromGuess`, the x given (e.g. the predictor's step for
  // the corrector, whose right-hand side differs by the centering terms only) is the start,
  // or joins the projection's basis. With Krylov/"initial guess: contact correction" and a
  // contact correction in the preconditioner, the start is then made exact on the contact
  // DOFs: x += P (P^T H P)^-1 P^T (r - H x), the starting vector of deflated CG.
  // With startReduction > 0 the solve stops earlier, once the residual of that start (or ||r||,
  // if smaller) has fallen by this factor, but not above absoluteTolerance nor before
  // absoluteFloor.
  KrylovResult solve(const Vector& r, Vector& x, double absoluteTolerance, bool fromGuess = false,
                     double startReduction = 0.0, double absoluteFloor = 0.0);

  const BarrierHessianOperator& hessian() const { return *H_; }
  int maxIterations() const { return maxIterations_; }
  // Number of AMG hierarchies built so far.
  int preconditionerSetups() const { return amgBuilds_ + (strategy_ == PreconditionerType::AmgOfQ ? 1 : 0); }
  // The entries of the multigrid levels' matrices in its last build, finest first (empty
  // without one). Collective.
  std::vector<long long> multigridNonzeros() const { return amg_ ? amg_->levelNonzeros() : std::vector<long long>(); }

 private:
  Teuchos::ParameterList params_;  // the validated "Krylov" and "Preconditioner" sublists
  RCP<BarrierHessianOperator> H_;
  RCP<BarrierHessianOperator> contactColumns_;  // H P P^T, for the multiplicative correction
  KrylovSolver krylov_;
  PreconditionerType strategy_;
  int maxIterations_;
  InitialGuessProjection initialGuess_;
  bool contactCorrectedStart_ = false;
  std::unique_ptr<MultilevelPreconditioner> amg_;
  ContactCorrection correction_ = ContactCorrection::None;
  RCP<ContactSubspaceSolver> subspace_;
  RCP<FreeMotionCorrection> freeMotionCorrection_;
  bool reuseHierarchy_ = false;
  double rebuildTolerance_ = 0.0;
  double weightCap_ = 0.0;  // "amg of H: weight cap" with a contact correction, else 0 (none)
  RCP<Vector> constraintStiffness_, builtWeights_;  // q_i, and w_i of the last AMG build
  RCP<Vector> algebraicWeights_;  // w_i when the algebraic levels below the grids were set up
  double algebraicRebuildTolerance_ = 0.0;
  RCP<CrsMatrix> assembledH_;                       // the matrix of the last AMG build
  // On the geometric levels H is not assembled: the hierarchy gets Q + A^T D' A as an
  // operator, its diagonal and A^T D' A (GeometricMultigridPreconditioner::computeForSum).
  GeometricMultigridPreconditioner* geometric_ = nullptr;  // amg_, when it takes that path
  RCP<BarrierHessianOperator> filteredH_;                  // Q + A^T D' A
  RCP<Vector> diagonalOfQ_;
  int amgBuilds_ = 0;
  bool amgReady_ = false;

  // The geometric hierarchy for Q + A^T D' A, D' = `filtered`, without assembling it.
  void buildGeometricForSum(const Vector& filtered);
  // Has the geometric hierarchy set up its algebraic levels anew at its next build when the
  // relative weights moved by more than algebraicRebuildTolerance_ since they were set up.
  void refreshAlgebraicLevelsIfMoved(const RCP<Vector>& weights);
  // amg_ on the geometric levels of multigrid.grid (Preconditioner/hierarchy geometric or auto).
  void makeGeometric(const ContactQP& qp, const MultigridInput& multigrid, const Teuchos::ParameterList& prec,
                     const StiffnessParts& stiffness);
};

// q_i = sum_j a_ij^2 Q_jj / |a_i|^4: the stiffness Q puts against constraint i in the units of
// its barrier weight D_i (row i adds D_i a_i a_i^T to H, whose eigenvalue D_i |a_i|^2 meets
// Q's stiffness along a_i, a_i^T diag(Q) a_i / |a_i|^2), so that D_i / q_i does not depend on
// how the row is scaled (weighted gaps scale theirs by their facets' measure); on A's row map,
// from diag(Q) on A's domain map.
RCP<Vector> constraintStiffness(const Vector& diagonalOfQ, const CrsMatrix& A);

}  // namespace signorini
