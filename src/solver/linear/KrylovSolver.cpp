#include "solver/linear/KrylovSolver.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosSolverFactory_Generic.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

using SolverFactory = Belos::SolverFactory<Scalar, MultiVector, Operator>;

// Belos' solver registry for these types, which libbelostpetra fills when it is loaded. Where
// this file sees another registry than the library's (compiled by another compiler than
// Trilinos: Clang does not share GCC's unique symbols), it is empty, and the header-only
// generic factory registers Belos' solvers in it.
SolverFactory& belosFactory() {
  static SolverFactory factory;
  static const bool filled = factory.isSupported("CG") || (Belos::GenericSolverFactory<Scalar, MultiVector, Operator>(), true);
  (void)filled;
  return factory;
}

// Belos' CG iterations precondition each new residual before they test it for convergence, so
// the last preconditioner application of every solve is wasted: a V-cycle in each Newton
// system, often a third of them. This wrapper hands back the residual itself once every
// column already meets its target ||r|| <= tol ||b||, the test CG is about to make; should CG
// go on regardless, that is one step with the identity preconditioner.
class SkippedAtConvergence : public Operator {
 public:
  SkippedAtConvergence(RCP<const Operator> M, std::vector<double> targets)
      : M_(std::move(M)), targets_(std::move(targets)) {}

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, Scalar alpha, Scalar beta) const override {
    std::vector<double> norms(X.getNumVectors());
    X.norm2(Teuchos::ArrayView<double>(norms));
    bool converged = norms.size() == targets_.size();
    for (std::size_t j = 0; converged && j < norms.size(); ++j) converged = norms[j] <= targets_[j];
    if (converged)
      Y.update(alpha, X, beta);
    else
      M_->apply(X, Y, mode, alpha, beta);
  }
  RCP<const Map> getDomainMap() const override { return M_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return M_->getRangeMap(); }

 private:
  RCP<const Operator> M_;
  std::vector<double> targets_;
};

// Whether `solver` is one of Belos' CG solvers measuring ||r|| / ||b|| (the residual scaling
// this class sets unless the Belos sublist says otherwise).
bool isCgRelativeToRhs(const Belos::SolverManager<Scalar, MultiVector, Operator>& solver,
                       const Teuchos::ParameterList& params) {
  const bool cg = dynamic_cast<const Belos::PseudoBlockCGSolMgr<Scalar, MultiVector, Operator>*>(&solver) ||
                  dynamic_cast<const Belos::BlockCGSolMgr<Scalar, MultiVector, Operator>*>(&solver);
  return cg && params.isType<std::string>("Implicit Residual Scaling") &&
         params.get<std::string>("Implicit Residual Scaling") == "Norm of RHS";
}

}  // namespace

Teuchos::ParameterList KrylovSolver::validParameters() {
  Teuchos::ParameterList p("Krylov");
  p.set("solver", "CG", "Belos solver name: CG, MINRES, GMRES, or any name Belos knows");
  p.sublist("Belos", false, "Passed to the Belos solver unchanged");
  return p;
}

KrylovSolver::KrylovSolver(const Teuchos::ParameterList& params)
    : solver_(params.isParameter("solver") ? params.get<std::string>("solver") : "CG"),
      belos_(params.isSublist("Belos") ? params.sublist("Belos") : Teuchos::ParameterList()) {
  if (!belosFactory().isSupported(solver_))
    throw InputError("Krylov solver \"" + solver_ + "\" is not a Belos solver");
}

KrylovResult KrylovSolver::solve(const RCP<const Operator>& A, const RCP<const Operator>& M,
                                 const RCP<const MultiVector>& b, const RCP<MultiVector>& x,
                                 double tol, int maxIterations, double startReduction, double floor) const {
  auto problem = rcp(new Belos::LinearProblem<Scalar, MultiVector, Operator>(A, x, b));
  problem->setProblem();
  if (startReduction > 0.0 && b->getNumVectors() == 1) {
    // Relative to ||b||, as the residual scaling below says; a start worse than zero counts as zero.
    const double bnorm = b->getVector(0)->norm2(), r0norm = problem->getInitResVec()->getVector(0)->norm2();
    if (bnorm > 0.0) tol = std::max(floor, std::min(tol, startReduction * std::min(r0norm, bnorm) / bnorm));
  }

  BelosSolver& solver = belosSolver(tol, maxIterations);
  if (!M.is_null()) {
    std::vector<double> targets(b->getNumVectors());
    b->norm2(Teuchos::ArrayView<double>(targets));
    for (double& target : targets) target = tol * (target > 0.0 ? target : 1.0);
    problem->setRightPrec(skipLastPreconditioning_ ? rcp<const Operator>(new SkippedAtConvergence(M, targets)) : M);
  }
  solver.setProblem(problem);
  KrylovResult result;
  try {
    const Belos::ReturnType status = solver.solve();
    result.converged = status == Belos::Converged;
    result.relativeResidual = solver.achievedTol();
  } catch (const std::exception&) {
    // Breakdown: report no convergence; the caller decides what to do with x.
    result.converged = false;
    result.relativeResidual = std::numeric_limits<double>::infinity();
  }
  result.iterations = solver.getNumIters();
  return result;
}

KrylovSolver::BelosSolver& KrylovSolver::belosSolver(double tol, int maxIterations) const {
  auto params = rcp(new Teuchos::ParameterList());
  if (belosSolver_.is_null()) {
    belosSolver_ = belosFactory().create(solver_, Teuchos::null);
    const auto valid = belosSolver_->getValidParameters();
    *params = belos_;
    // The forcing condition is on the true residual relative to the right-hand side, where
    // the solver lets us say so (MINRES always measures it that way).
    for (const char* scaling : {"Implicit Residual Scaling", "Explicit Residual Scaling"})
      if (valid->isParameter(scaling) && !params->isParameter(scaling)) params->set(scaling, "Norm of RHS");
    // CG's check p^T A p > 0 also fires on round-off once the residual is tiny; a truly
    // indefinite system shows up as non-convergence instead.
    if (valid->isParameter("Assert Positive Definiteness") && !params->isParameter("Assert Positive Definiteness"))
      params->set("Assert Positive Definiteness", false);
    skipLastPreconditioning_ = isCgRelativeToRhs(*belosSolver_, *params);
  }
  params->set("Convergence Tolerance", tol);
  params->set("Maximum Iterations", maxIterations);
  belosSolver_->setParameters(params);
  return *belosSolver_;
}

}  // namespace signorini
