#include "signorini/NewtonSystemSolver.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/Error.hpp"

namespace signorini {

Teuchos::ParameterList NewtonSystemSolver::validParameters() {
  Teuchos::ParameterList p;
  Teuchos::ParameterList& krylov = p.sublist("Krylov", false, "Krylov solver of the Newton systems");
  krylov.setParameters(KrylovSolver::validParameters());
  krylov.set("maximum iterations", 1000, "Krylov iterations allowed per Newton system",
             rcp(new Teuchos::EnhancedNumberValidator<int>(1, 1000000)));
  Teuchos::ParameterList& prec = p.sublist("Preconditioner", false, "Preconditioner of H");
  prec.set("type", "amg of H",
           "\"none\", \"amg of Q\" (MueLu on Q, built once) or \"amg of H\" (MueLu on the "
           "assembled Q + A^T D A, rebuilt each Newton step)",
           rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("none", "amg of Q", "amg of H"))));
  prec.sublist("MueLu", false, "Passed to MueLu unchanged, over Signorini's defaults");
  return p;
}

NewtonSystemSolver::NewtonSystemSolver(const ContactQP& qp, const Teuchos::ParameterList& params)
    : H_(rcp(new BarrierHessianOperator(qp.Q, qp.A))),
      krylov_(params.sublist("Krylov")),
      strategy_(params.sublist("Preconditioner").get<std::string>("type")),
      maxIterations_(params.sublist("Krylov").get<int>("maximum iterations")) {
  if (strategy_ == "none") return;
  if (qp.Qmatrix().is_null())
    throw InputError("Preconditioner/type \"" + strategy_ + "\" needs Q as an assembled CrsMatrix; "
                     "use \"none\" for a matrix-free Q");
  const Teuchos::ParameterList& muelu = params.sublist("Preconditioner").sublist("MueLu");
  amg_ = std::make_unique<MueLuPreconditioner>(muelu, qp.blockSize, qp.nullspace, qp.coordinates);
  reuseHierarchy_ = amg_->parameters().get<std::string>("reuse: type") != "none";
  if (strategy_ == "amg of Q") {
    amg_->compute(Teuchos::rcp_const_cast<CrsMatrix>(qp.Qmatrix()));
    amgReady_ = true;
  }
}

void NewtonSystemSolver::setWeights(const Vector& D) {
  H_->setWeights(D);
  if (strategy_ == "amg of H") {
    amg_->compute(H_->assemble(), reuseHierarchy_ && amgReady_);
    amgReady_ = true;
  }
}

KrylovResult NewtonSystemSolver::solve(const Vector& r, Vector& x, double absoluteTolerance) {
  x.putScalar(0.0);
  const double rnorm = r.norm2();
  if (rnorm == 0.0) return KrylovResult{0, true, 0.0};
  RCP<const Operator> M = amg_ ? amg_->getOperator() : Teuchos::null;
  auto rhs = Teuchos::rcpFromRef(r);
  auto sol = Teuchos::rcpFromRef(x);
  return krylov_.solve(H_, M, rhs, sol, std::min(0.5, absoluteTolerance / rnorm), maxIterations_);
}

}  // namespace signorini
