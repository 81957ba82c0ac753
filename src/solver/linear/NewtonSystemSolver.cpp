#include "solver/linear/NewtonSystemSolver.hpp"

#include <algorithm>
#include <limits>

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "core/CommunicationPhase.hpp"
#include "core/ParameterValidation.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/StiffnessParts.hpp"
#include "solver/preconditioner/GeometricMultigridPreconditioner.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"
#include "solver/preconditioner/SubspaceCorrectedPreconditioner.hpp"

namespace signorini {

RCP<Vector> constraintStiffness(const Vector& diagonalOfQ, const CrsMatrix& A) {
  Vector atColumns(A.getColMap());
  atColumns.doImport(diagonalOfQ, Import(diagonalOfQ.getMap(), A.getColMap()), Tpetra::INSERT);
  auto q = rcp(new Vector(A.getRowMap()));
  auto qd = q->getDataNonConst();
  auto cd = atColumns.getData();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(A.getNodeNumRows()); ++i) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    A.getLocalRowView(i, cols, vals);
    double rowNorm2 = 0;
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      qd[i] += vals(k) * vals(k) * cd[cols(k)];
      rowNorm2 += vals(k) * vals(k);
    }
    if (rowNorm2 > 0) qd[i] /= rowNorm2 * rowNorm2;
  }
  return q;
}

namespace {

// Whether some entry of `weights` differs from the one in `built` by more than `tolerance`. Collective.
bool movedMoreThan(const Vector& weights, const Vector& built, double tolerance) {
  Vector moved(weights.getMap());
  moved.update(1.0, weights, -1.0, built, 0.0);
  return moved.normInf() > tolerance;
}

void addGeometricParameters(Teuchos::ParameterList& prec) {
  prec.set("geometric: coarsest size", 200,
           "The geometric levels stop before a grid with fewer unknowns than this, or after one with a "
           "single box per direction",
           expert(range(1, std::numeric_limits<int>::max())));
  prec.set("geometric: direct solve size", 2500,
           "The geometric levels end at the first coarse grid with at most this many unknowns, which is solved "
           "exactly (gathered to rank 0 and factored by CHOLMOD's Cholesky); MueLu's algebraic multigrid takes over below a "
           "larger coarsest grid. 0: always MueLu",
           expert(range(0, std::numeric_limits<int>::max())));
  prec.set("geometric: algebraic levels rebuild tolerance", std::string("auto"),
           "Below a coarsest grid with more than \"geometric: direct solve size\" unknowns: 0, MueLu is the "
           "coarse solver, set up again at every build; above 0, MueLu's levels join the cycle, set up anew "
           "when the relative weight of some constraint (see \"amg of H: rebuild tolerance\") moved by more "
           "than this since they were, their coarse matrices updated with what changed in between; "
           "\"auto\": 0.9 where the coarsest grid is the P1 grid of a degree 2 or 3 mesh without coarser "
           "grids (a Gmsh mesh read as is, whose P1 grid MueLu coarsens), else 0",
           expert(autoOrRange(0.0, 1.0)));
  prec.set("geometric: eigenvalue update steps", 3,
           "Lanczos steps that update a smoother's largest-eigenvalue estimate when only the contact rows "
           "changed, from the previous Ritz vector; 0: a fresh estimate at every rebuild (1 and 2 steps are too "
           "inaccurate)",
           expert(zeroOrRange(3, 1000)));
}

void addPreconditionerParameters(Teuchos::ParameterList& prec) {
  prec.set("type", "amg of H",
           "\"none\", \"amg of Q\" (MueLu on Q, built once) or \"amg of H\" (a multigrid of "
           "Q + A^T D A, rebuilt as \"amg of H: rebuild tolerance\" says)",
           choices<PreconditionerType>({{"none", PreconditionerType::None},
                                        {"amg of Q", PreconditionerType::AmgOfQ},
                                        {"amg of H", PreconditionerType::AmgOfH}},
                                       "type"));
  prec.set("amg of H: rebuild tolerance", std::string("auto"),
           "Rebuild \"amg of H\" when the relative weight D_i / (D_i + q_i) of some constraint (q_i: its "
           "stiffness against the row, a_i^T diag(Q) a_i / |a_i|^4) moved by more than this since the last "
           "build; 0: at every Newton step, 1: never after the first; \"auto\": 0 with the geometric levels, "
           "0.9 with MueLu alone",
           expert(autoOrRange(0.0, 1.0)));
  prec.set("amg of H: weight cap", 10.0,
           "With a contact correction, \"amg of H\" is built for Q + A^T D' A, D'_i = min(D_i, cap q_i) "
           "(filtering): weights far above a constraint's stiffness stay out of the coarse levels and the "
           "contact correction solves for them exactly. 0: no cap",
           expert(range(0.0, 1e300)));
  prec.set("contact correction", "multiplicative",
           "Exact solve on the contact DOFs (those in A) combined with the AMG: \"none\", "
           "\"additive\" or \"multiplicative\" (symmetric: subspace, AMG, subspace); none where the "
           "\"amg of H\" is one grid factored exactly (a box mesh with at most \"geometric: direct solve "
           "size\" unknowns)",
           choices<ContactCorrection>({{"none", ContactCorrection::None},
                                       {"additive", ContactCorrection::Additive},
                                       {"multiplicative", ContactCorrection::Multiplicative}},
                                      "contact correction"));
  prec.set("contact correction: blocks", "auto",
           "How P^T H P is factored for the contact correction: \"per rank\", each rank the block of "
           "the contact DOFs it owns (block Jacobi, nothing gathered); \"gathered\", all of it on rank 0 "
           "(exact; its residual gathered in every Krylov iteration); \"auto\": per rank unless a constraint's "
           "DOFs lie on several ranks",
           expert(choices<ContactSubspaceBlocks>({{"auto", ContactSubspaceBlocks::Auto},
                                                  {"per rank", ContactSubspaceBlocks::PerRank},
                                                  {"gathered", ContactSubspaceBlocks::Gathered}},
                                                 "contact correction: blocks")));
  prec.set("free motions: coarse depth", 2,
           "Where only the contact holds a rigid body motion (force control), the preconditioner solves "
           "exactly on the free motions F and on (B H)^j F, j = 1 .. this, the preconditioned Krylov vectors that "
           "catch the body's soft motions around its contact patch; 0: on F alone",
           expert(range(0, 8)));
  prec.set("hierarchy", "auto",
           "Multigrid levels: \"geometric\" (P_k to P1 on the same mesh; on box meshes then grids with half the "
           "boxes per direction; Galerkin coarse matrices, Chebyshev smoothing, a direct solve or MueLu below); "
           "\"algebraic\": MueLu alone; \"auto\": geometric where the QP has a grid (box meshes, refined Gmsh "
           "meshes, degrees 2 and 3, a grid given by the caller)",
           choices<Hierarchy>({{"auto", Hierarchy::Auto},
                               {"algebraic", Hierarchy::Algebraic},
                               {"geometric", Hierarchy::Geometric}},
                              "hierarchy"));
  addGeometricParameters(prec);
  prec.sublist("Ifpack2", false,
               "Passed unchanged to Ifpack2's Chebyshev smoother of the coarse geometric levels, over "
               "Signorini's defaults (chebyshev: degree 2, chebyshev: ratio eigenvalue 7); the fine level's "
               "smoother, the same polynomial of H as an operator, reads its degree, ratio eigenvalue, boost "
               "factor and max eigenvalue");
  prec.sublist("MueLu", false,
               "Passed to MueLu unchanged, over Signorini's defaults; a reuse: type other than none refreshes "
               "the hierarchy of a matrix of the same pattern (tP and RP are refused: Trilinos 13.2 fails in "
               "them on contact problems; so is full, which keeps the first Hessian's hierarchy). Where MueLu "
               "is the whole hierarchy, aggregation: min agg size defaults to the 99th percentile of the nodal "
               "row sizes (a node and its neighbours) of the first matrix: aggregates grow from the "
               "best-connected nodes, fewer and larger than MueLu's own; and aggregation: drop tol to 0.01, "
               "which keeps the weakest couplings out of the aggregates");
}

}  // namespace

Teuchos::ParameterList NewtonSystemSolver::validParameters() {
  Teuchos::ParameterList p;
  Teuchos::ParameterList& krylov = p.sublist("Krylov", false, "Krylov solver of the Newton systems");
  krylov.setParameters(KrylovSolver::validParameters());
  krylov.set("maximum iterations", 1000, "Krylov iterations allowed per Newton system",
             range(1, 1000000));
  krylov.set("initial guess: previous solutions", 2,
             "Start each Newton system from the H-orthogonal projection of its solution on this many earlier "
             "solutions (and the predictor's step, for the corrector); a kept solution carries its product with "
             "Q, so the projection costs one application of Q per system; 0: start from zero",
             expert(range(0, 20)));
  krylov.set("initial guess: contact correction", true,
             "Then correct the start exactly on the contact DOFs, x += P (P^T H P)^-1 P^T (r - H x): one "
             "subspace solve per Newton system (and one application of H without the projection); needs "
             "Preconditioner/contact correction", expert());
  addPreconditionerParameters(p.sublist("Preconditioner", false, "Preconditioner of H"));
  return p;
}

namespace {

// The "Krylov" and "Preconditioner" sublists of a validated "Solver" list.
Teuchos::ParameterList newtonParameters(const Teuchos::ParameterList& solver) {
  Teuchos::ParameterList own;
  for (const char* name : {"Krylov", "Preconditioner"}) own.set(name, solver.sublist(name));
  return own;
}

}  // namespace

NewtonSystemSolver::NewtonSystemSolver(const ContactQP& qp, const MultigridInput& multigrid,
                                       const Teuchos::ParameterList& params,
                                       RCP<const MultiVector> freeMotions)
    : params_(newtonParameters(params)),
      H_(rcp(new BarrierHessianOperator(qp.Q, qp.A, assembledStiffness(qp, multigrid)))),
      krylov_(params_.sublist("Krylov")),
      strategy_(choice<PreconditionerType>(params_.sublist("Preconditioner"), "type")),
      maxIterations_(params_.sublist("Krylov").get<int>("maximum iterations")),
      initialGuess_(params_.sublist("Krylov").get<int>("initial guess: previous solutions")),
      contactCorrectedStart_(params_.sublist("Krylov").get<bool>("initial guess: contact correction")) {
  const Teuchos::ParameterList& prec = params_.sublist("Preconditioner");
  correction_ = choice<ContactCorrection>(prec, "contact correction");
  if (strategy_ == PreconditionerType::None) {
    if (correction_ != ContactCorrection::None)
      throw InputError("Preconditioner/contact correction needs an AMG: set Preconditioner/type to \"amg of Q\" "
                       "or \"amg of H\"");
    return;
  }
  const StiffnessParts stiffness(qp, multigrid);
  if (!stiffness.available())
    throw InputError("Preconditioner/type \"" + prec.get<std::string>("type") + "\" needs Q assembled or as a "
                     "StiffnessOperator; use \"none\" for another matrix-free Q");
  const bool assembled = !assembledStiffness(qp, multigrid).is_null();
  Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: preconditioner construction"));
  const Teuchos::ParameterList& muelu = prec.sublist("MueLu");
  const Hierarchy hierarchy = choice<Hierarchy>(prec, "hierarchy");
  const bool haveGrid = multigrid.grid && !multigrid.coordinates.is_null();
  if (hierarchy == Hierarchy::Geometric || (hierarchy == Hierarchy::Auto && haveGrid)) {
    makeGeometric(qp, multigrid, prec, stiffness);
  } else {
    amg_ = std::make_unique<MueLuPreconditioner>(muelu, multigrid.blockSize, multigrid.nearNullspace(qp),
                                                 multigrid.coordinates,
                                                 MueLuPreconditioner::Aggregation::WholeHierarchy);
    // A rebuild of MueLu's hierarchy is a whole setup: only when constraints switch.
    rebuildTolerance_ = autoOrNumber(prec, "amg of H: rebuild tolerance", 0.9);
  }
  if (!assembled && !geometric_)
    throw InputError("a matrix-free Q is preconditioned by Preconditioner/type \"amg of H\" on geometric levels "
                     "alone (degree 2 or 3; from a library, MultigridInput::grid and gridStiffness); set "
                     "Problem/stiffness: operator to \"assembled\"");
  if (correction_ != ContactCorrection::None) {
    const RCP<const CrsMatrix> contactRows = stiffness.contactRows(*qp.A);
    subspace_ = rcp(new ContactSubspaceSolver(*contactRows, *qp.A,
                                              choice<ContactSubspaceBlocks>(prec, "contact correction: blocks")));
    if (correction_ == ContactCorrection::Multiplicative) contactColumns_ = H_->onContactColumns(*contactRows);
  }
  // Without a contact correction, nothing else would see the weights above the cap.
  if (correction_ != ContactCorrection::None) weightCap_ = prec.get<double>("amg of H: weight cap");
  if (strategy_ == PreconditionerType::AmgOfH)
    constraintStiffness_ = constraintStiffness(diagonalOfQ_.is_null() ? *stiffness.diagonal() : *diagonalOfQ_, *qp.A);
  if (!freeMotions.is_null() && freeMotions->getNumVectors() > 0)
    freeMotionCorrection_ =
        rcp(new FreeMotionCorrection(H_, freeMotions, prec.get<int>("free motions: coarse depth")));
  reuseHierarchy_ = muelu.isType<std::string>("reuse: type") && muelu.get<std::string>("reuse: type") != "none";
  if (strategy_ == PreconditionerType::AmgOfQ) {
    amg_->compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(qp, multigrid)));
    amgReady_ = true;
  }
}

void NewtonSystemSolver::makeGeometric(const ContactQP& qp, const MultigridInput& multigrid,
                                       const Teuchos::ParameterList& prec, const StiffnessParts& stiffness) {
  const bool assembled = !assembledStiffness(qp, multigrid).is_null();
  if (!multigrid.grid || multigrid.coordinates.is_null())
    throw InputError("Preconditioner/hierarchy \"geometric\" needs a grid: MultigridInput::grid (a GeometricGrid, "
                     "e.g. a signorini::SimplexGrid of the caller's mesh) and MultigridInput::coordinates; the problem "
                     "builder gives one for a box mesh, a refined Gmsh mesh (Problem/mesh: refinements) or "
                     "a degree of 2 or 3");
  // Without Q assembled the fine level cannot be factored: the P_k -> P1 level is taken
  // however few unknowns the P1 grid has.
  long long coarsestSize = prec.get<int>("geometric: coarsest size");
  if (!assembled) coarsestSize = std::min(coarsestSize, multigrid.blockSize * multigrid.grid->numVertices());
  auto geometric = std::make_unique<GeometricMultigridPreconditioner>(
      *multigrid.grid, qp.Q->getDomainMap(), stiffness.prescribedDofs(), *multigrid.coordinates, multigrid.blockSize,
      coarsestSize, prec.get<int>("geometric: direct solve size"),
      prec.sublist("Ifpack2"), prec.sublist("MueLu"), prec.get<int>("geometric: eigenvalue update steps"),
      multigrid.nodeBodies);
  if (strategy_ == PreconditionerType::AmgOfH && geometric->geometricLevels() > 0 &&
      (assembled || !multigrid.gridStiffness.is_null())) {
    geometric_ = geometric.get();
    filteredH_ = rcp(new BarrierHessianOperator(qp.Q, qp.A, assembledStiffness(qp, multigrid)));
    diagonalOfQ_ = stiffness.diagonal();
    if (!multigrid.gridStiffness.is_null())
      geometric_->setGridStiffness(*multigrid.gridStiffness);
    else
      geometric_->setFineStiffness(assembledStiffness(qp, multigrid));
    geometric_->setFineStiffnessOperator(qp.Q, *diagonalOfQ_);
  }
  // A single grid factored exactly is H's inverse: a contact correction would add nothing,
  // and the weights need no cap, which only serves such a correction.
  if (strategy_ == PreconditionerType::AmgOfH && geometric->geometricLevels() == 0 &&
      geometric->directCoarsestSolve())
    correction_ = ContactCorrection::None;
  // Below a P_k mesh's own P1 grid, MueLu's setup costs as much as the rest of a build many
  // times over (3D P2 .msh, 0.63 M unknowns: 0.5 s of 0.66 s); below a coarsened grid it is
  // small, and the levels it sets up for each matrix need fewer CG iterations.
  const bool onlyOwnP1Grid = !geometric->fineIsP1() && geometric->geometricLevels() == 1;
  algebraicRebuildTolerance_ = autoOrNumber(prec, "geometric: algebraic levels rebuild tolerance", onlyOwnP1Grid ? 0.9 : 0.0);
  if (geometric_ && algebraicRebuildTolerance_ > 0) geometric->keepAlgebraicLevels();
  amg_ = std::move(geometric);
  // A rebuild on the geometric levels updates the Galerkin products of the changed rows.
  rebuildTolerance_ = autoOrNumber(prec, "amg of H: rebuild tolerance", 0.0);
}

void NewtonSystemSolver::setWeights(const Vector& D) {
  const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::preconditionerSetup);
  H_->setWeights(D);
  if (!freeMotionCorrection_.is_null()) freeMotionCorrection_->refresh();
  if (!contactColumns_.is_null()) contactColumns_->setWeights(D);
  if (!subspace_.is_null()) {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: contact subspace setup"));
    subspace_->setWeights(D);
  }
  if (strategy_ == PreconditionerType::AmgOfH) {
    // The AMG sees the weights filtered by the cap, and their relative values w_i = D_i / (D_i + q_i)
    // say how much A^T D A changes the matrix it was built for.
    auto weights = rcp(new Vector(D.getMap()));
    Vector filtered(D.getMap());
    {
      auto dd = D.getData();
      auto qd = constraintStiffness_->getData();
      auto wd = weights->getDataNonConst();
      auto fd = filtered.getDataNonConst();
      for (long i = 0; i < wd.size(); ++i) {
        fd[i] = weightCap_ > 0 ? std::min(dd[i], weightCap_ * qd[i]) : dd[i];
        wd[i] = fd[i] + qd[i] > 0 ? fd[i] / (fd[i] + qd[i]) : 0.0;
      }
    }
    if (amgReady_ && rebuildTolerance_ > 0 && !movedMoreThan(*weights, *builtWeights_, rebuildTolerance_)) return;
    builtWeights_ = weights;
    ++amgBuilds_;
    if (geometric_) {
      if (geometric_->keepsAlgebraicLevels()) refreshAlgebraicLevelsIfMoved(weights);
      buildGeometricForSum(filtered);
      amgReady_ = true;
      return;
    }
    // On Q's graph, H is updated in place and the hierarchy with what changed (A^T D A on the
    // contact DOFs); a copy of Q's values and a search for the changes were most of the cost.
    RCP<CrsMatrix> change;
    {
      Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: assemble H"));
      if (amgReady_ && !assembledH_.is_null() && H_->assemblesOnQGraph())
        change = H_->updateAssembled(*assembledH_, filtered);
      else
        assembledH_ = H_->assemble(filtered);
    }
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup"));
    if (change.is_null())
      amg_->compute(assembledH_, reuseHierarchy_ && amgReady_);
    else
      amg_->update(assembledH_, *change, reuseHierarchy_);
    amgReady_ = true;
  }
}

void NewtonSystemSolver::refreshAlgebraicLevelsIfMoved(const RCP<Vector>& weights) {
  if (!algebraicWeights_.is_null() && !movedMoreThan(*weights, *algebraicWeights_, algebraicRebuildTolerance_)) return;
  geometric_->refreshAlgebraicLevels();
  algebraicWeights_ = weights;
}

void NewtonSystemSolver::buildGeometricForSum(const Vector& filtered) {
  RCP<const CrsMatrix> C;
  Vector diagonal(diagonalOfQ_->getMap(), false);
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: assemble H"));
    filteredH_->setWeights(filtered);
    C = filteredH_->contactTerm(filtered);
    C->getLocalDiagCopy(diagonal);
    diagonal.update(1.0, *diagonalOfQ_, 1.0);
  }
  Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: AMG setup"));
  geometric_->computeForSum(filteredH_, diagonal, C, reuseHierarchy_ && amgReady_);
}

KrylovResult NewtonSystemSolver::solve(const Vector& r, Vector& x, double absoluteTolerance, bool fromGuess,
                                       double startReduction, double absoluteFloor) {
  const double rnorm = r.norm2();
  if (!fromGuess || rnorm == 0.0) x.putScalar(0.0);
  if (rnorm == 0.0) return KrylovResult{0, true, 0.0};
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: initial guesses"));
    // The contact correction needs H x, which the projection gives as a by-product.
    const bool correct = contactCorrectedStart_ && !subspace_.is_null();
    const RCP<Vector> Hx = correct ? rcp(new Vector(r.getMap(), false)) : Teuchos::null;
    if (initialGuess_.capacity() > 0)
      initialGuess_.project(*H_, r, x, fromGuess, Hx.get());
    else if (correct)
      H_->apply(x, *Hx);
    if (correct) {
      Hx->update(1.0, r, -1.0);  // the residual r - H x
      subspace_->apply(*Hx, x, Teuchos::NO_TRANS, 1.0, 1.0);
    }
  }
  RCP<const Operator> M = amg_ ? amg_->getOperator() : Teuchos::null;
  if (!subspace_.is_null()) M = rcp(new SubspaceCorrectedPreconditioner(H_, M, subspace_, correction_, contactColumns_));
  if (!freeMotionCorrection_.is_null()) {
    freeMotionCorrection_->setInner(M);
    M = freeMotionCorrection_;
  }
  auto rhs = Teuchos::rcpFromRef(r);
  auto sol = Teuchos::rcpFromRef(x);
  KrylovResult result;
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: Krylov"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::krylov);
    result = krylov_.solve(H_, M, rhs, sol, std::min(0.5, absoluteTolerance / rnorm), maxIterations_, startReduction,
                           absoluteFloor / rnorm);
  }
  {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: initial guesses"));
    initialGuess_.remember(*H_, x);
  }
  return result;
}

}  // namespace signorini
