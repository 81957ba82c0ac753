#pragma once
// Geometric multigrid: below the fine space lies the sequence of grids a GeometricGrid gives
// (for a box mesh, grids with every other vertex line of the one above, and its last, so half
// the boxes per direction, one more for an odd count; a P_k space, k > 1, first goes to P1 on
// its own mesh's grid, or on that mesh refined at its nodes, where P is the identity), each a
// P1 space, joined by P1 interpolation P. The coarse matrices are Galerkin products P^T A P
// (the first one below a P_k space may be given as the grid's P1 stiffness instead, see
// setGridStiffness()), the smoother is Ifpack2's Chebyshev (on a fine level given as an
// operator, computeForSum(), a ChebyshevSmoother of it). The levels end at the first coarse
// grid with at most "direct solve size" unknowns, solved exactly (gathered to rank 0 and
// factored), or at a grid whose coarser one would have fewer than "coarsest size" unknowns
// or which has none; MueLu's algebraic multigrid, with the grid's
// rigid body modes, takes over below a coarsest grid too large to factor.
// The cycle is a V-cycle, symmetric positive definite for CG.
//
// Why: smoothed aggregation on these meshes needs more CG iterations as the mesh is refined
// (bench/results/amg-variants.md); interpolation between nested grids does not lose
// accuracy with the mesh size. In 2D each grid's triangles are unions of the finer grid's,
// so P is the exact embedding; the 3D pattern alternates with the box parity and the grids
// are not nested, which interpolation handles all the same.
//
// Dirichlet DOFs (prescribed: rows and columns of the identity, as symmetric elimination
// leaves them) stay out of the coarse spaces: a coarse DOF at a Dirichlet DOF
// is injected into it alone, and the interpolation to other DOFs skips it.
#include <memory>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_CrsMatrix_decl.hpp>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/core/GeometricGrid.hpp"
#include "solver/preconditioner/MultilevelPreconditioner.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"

namespace signorini {

class GeometricMultigridPreconditioner : public MultilevelPreconditioner {
 public:
  // The Ifpack2 Chebyshev parameters used where the user's "smoother" list is silent.
  static Teuchos::ParameterList defaultSmootherParameters();

  // `grid`: the P1 grid of the fine space's mesh; `dofMap`: the fine DOFs (the row map of
  // every matrix given to compute()), `prescribed` 1 for each owned one that is a Dirichlet
  // DOF (a unit row and column, see StiffnessParts); `coordinates`: the owned fine nodes,
  // on a node map with DOF = blockSize * node + component. Collective.
  // `eigenvalueUpdateSteps`: Lanczos steps of the smoothers' eigenvalue estimates after a
  // Galerkin update, started from the previous estimate's Ritz vector and the changed rows
  // (0: a fresh estimate of "chebyshev: eigenvalue max iterations" steps at every build; the
  // default, 3, is Preconditioner/geometric: eigenvalue update steps in NewtonSystemSolver).
  // `nodeBodies`: the body of each owned fine node where bodies meshed apart have nodes at one
  // place (MultigridInput::nodeBodies; empty: one body), for the grids' lookups.
  // Throws InputError when the nodes do not contain the coarse grid's vertices.
  GeometricMultigridPreconditioner(const GeometricGrid& grid, const RCP<const Map>& dofMap,
                                   const std::vector<char>& prescribed, const MultiVector& coordinates,
                                   int blockSize, long long coarsestSize, long long directSolveSize,
                                   const Teuchos::ParameterList& smoother,
                                   const Teuchos::ParameterList& muelu, int eigenvalueUpdateSteps,
                                   const std::vector<int>& nodeBodies = {});
  ~GeometricMultigridPreconditioner() override;

  void compute(const RCP<CrsMatrix>& A, bool reuse = false) override;
  // The coarse matrices are updated with the Galerkin products of `change` alone.
  void update(const RCP<CrsMatrix>& A, const CrsMatrix& change, bool reuse = false) override;

  // What computeForSum() takes for Q: the fine matrix itself (its Galerkin product P^T Q P
  // is formed when needed; Q must stay valid), or, for a P_k fine space (k > 1), the grid's
  // P1 stiffness (MultigridInput::gridStiffness: DOF blockSize * vertex + component of the
  // constructor's grid, any one-to-one row map; copied) in place of P^T Q P, which it equals
  // on the mesh's own grid, so that Q need not be assembled.
  void setFineStiffness(const RCP<const CrsMatrix>& Q);
  void setGridStiffness(const CrsMatrix& gridStiffness);
  // Q as an operator with its diagonal (positive; copied), for the fine smoother of
  // computeForSum(): the largest eigenvalue lambda_Q of D_Q^-1 Q is estimated once, and
  // every H = Q + C then has max(lambda_Q, gamma_C) as a bound on its own, gamma_C =
  // jacobiGershgorinBound(C) (1 for a diagonal C). (The Rayleigh quotient of H over its
  // diagonal is a mediant of Q's and C's.) Where gamma_C is at most the boost factor times
  // lambda_Q, the interval the smoother damps with lambda_Q already reaches that bound, and
  // H needs no Lanczos steps of its own; above, H's own estimate is taken. Q must stay valid.
  void setFineStiffnessOperator(const RCP<const Operator>& Q, const Vector& diagonalOfQ);

  // The hierarchy for H = Q + C with the fine level left an operator: `H` applies it and
  // `diagonal` is its diagonal; Q is set as above and C, on the fine DOF map, is nonzero on
  // few rows (A^T D A on the contact DOFs). No fine matrix is assembled: the fine smoother is a
  // ChebyshevSmoother of H (reading the smoother list's degree, ratio, boost factor and max
  // eigenvalue), and the first coarse matrix is P^T Q P + P^T C P, which later calls with C on
  // the same graph update with the product of what changed in C. C is copied; H must stay
  // valid while the cycle is used. Needs a geometric level. Collective.
  void computeForSum(const RCP<const Operator>& H, const Vector& diagonal, const RCP<const CrsMatrix>& C,
                     bool reuse = false);
  RCP<Operator> getOperator() const override;
  // A fine level given as an operator counts Q's entries (those of C lie in Q's pattern), or 0
  // for a P_k space whose Q is not assembled; MueLu as the coarse solver adds its levels.
  std::vector<long long> levelNonzeros() const override;
  // Below a coarsest grid too large to factor, MueLu is by default the coarse solver, its
  // hierarchy set up again at every build. After keepAlgebraicLevels() (before the first
  // build) MueLu's levels join the cycle instead: its hierarchy of the coarsest grid's matrix
  // is set up at the first build, its prolongators are kept, their matrices updated with the
  // Galerkin products of what changed, as the grids' are, each with a Chebyshev smoother,
  // and its coarsest level is solved exactly. refreshAlgebraicLevels() makes the next build
  // set them up anew for its matrix. Why: on a P_k mesh's own P1 grid, MueLu's setup costs
  // as much as the rest of a build many times over, while few contact rows change.
  void keepAlgebraicLevels();
  void refreshAlgebraicLevels();
  bool keepsAlgebraicLevels() const { return static_cast<bool>(algebraicBelow_); }
  // Whether the fine space is P1 on the grid's vertices (else P_k goes to P1 first).
  bool fineIsP1() const { return isP1_; }

  // Grids below the fine level (0: MueLu alone), and the global unknowns of every level,
  // finest first (kept algebraic levels included once built).
  int geometricLevels() const { return geometricLevels_; }
  // Levels below the coarsest grid made of MueLu's prolongators (after the first build).
  int algebraicLevels() const { return algebraicLevels_; }
  std::vector<long long> levelSizes() const;
  // Whether the coarsest grid is solved exactly (else MueLu is below it, as the coarse
  // solver or, kept, as levels whose last is factored).
  bool directCoarsestSolve() const { return directCoarsest_; }
  // The interpolation from level l + 1 to level l (l = 0: to the fine space), kept algebraic
  // levels included. On a grid level, coarse DOF blockSize * v + c is component c at vertex v
  // of that level's grid (GeometricGrid numbering).
  RCP<const CrsMatrix> prolongator(int level) const;
  // The matrix of level l (0: the fine one given to compute(), none after computeForSum();
  // then the Galerkin products).
  // After the first compute(), a fine matrix on the previous one's graph updates them in
  // place with the products of the entries that changed.
  RCP<const CrsMatrix> levelMatrix(int level) const;

 private:
  struct Level;
  std::vector<std::shared_ptr<Level>> levels_;  // levels_[0] is the fine space
  Teuchos::ParameterList smoother_;
  int eigenvalueUpdateSteps_;
  bool directCoarsest_ = false;
  std::unique_ptr<MultilevelPreconditioner> coarse_;
  // MueLu, once, for the levels below the coarsest grid (appendAlgebraicLevels()).
  std::unique_ptr<MueLuPreconditioner> algebraicBelow_;
  int geometricLevels_ = 0, algebraicLevels_ = 0;
  RCP<Operator> cycle_;
  bool isP1_ = false;  // the fine space is P1 on the grid's vertices
  RCP<const CrsMatrix> fineStiffness_, firstCoarseStiffness_;  // see setFineStiffness()
  RCP<const Operator> fineOperator_;  // see setFineStiffnessOperator()
  RCP<Vector> fineOperatorDiagonal_;
  double fineOperatorEigenvalue_ = 0.0;  // lambda_Q once estimated
  // The C of the last computeForSum(): its graph and values (null after a compute()).
  RCP<const CrsMatrix::crs_graph_type> lastTerm_;
  std::vector<double> lastTermValues_;

  // Builds the levels for A; with `change`, A's entries that changed since the last build,
  // by updating the coarse matrices with its Galerkin products. `reuse` goes to the coarsest
  // level's compute().
  void build(const RCP<CrsMatrix>& A, RCP<const CrsMatrix> change, bool reuse);
  // The same below level `top`, whose matrix is set (`change`: what changed in it), keeping
  // the smoothers and operators above it.
  void buildFrom(std::size_t top, RCP<const CrsMatrix> change, bool reuse);
  // Level l's smoother and level l + 1's matrix, from `change` in level l's matrix (null:
  // the whole product); returns the change in level l + 1's (null if it was rebuilt whole).
  RCP<const CrsMatrix> buildLevel(std::size_t l, RCP<const CrsMatrix> change);
  // Level l's smoother for its matrix, which had `levelChange` added (null: new).
  void buildSmoother(std::size_t l, const RCP<const CrsMatrix>& levelChange);
  // Below the coarsest grid, levels with the prolongators of MueLu's hierarchy of its matrix.
  void appendAlgebraicLevels();
  // The smoother's max eigenvalue for the level's operator: the smoother list's, or the
  // Lanczos estimate, updated from the last Ritz vector after a `change` (the smoother
  // applies the boost factor to it).
  double maxEigenvalue(Level& level, const RCP<const CrsMatrix>& change);
  // The fine smoother's max eigenvalue for H = Q + C (see setFineStiffnessOperator()).
  double maxEigenvalueOfSum(Level& fine, const CrsMatrix& C, const RCP<const CrsMatrix>& change);
  RCP<const CrsMatrix> changeOfTerm(const CrsMatrix& C) const;
  void rememberTerm(const RCP<const CrsMatrix>& C);
  // P^T Q P (a matrix of its own), and P^T (Q + C) P.
  RCP<CrsMatrix> firstCoarseStiffness() const;
  RCP<CrsMatrix> firstCoarseMatrix(const RCP<const CrsMatrix>& C) const;
};

}  // namespace signorini
