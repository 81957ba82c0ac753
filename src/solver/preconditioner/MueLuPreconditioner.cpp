#include "solver/preconditioner/MueLuPreconditioner.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

using MueLuOperator = MueLu::TpetraOperator<Scalar, LocalOrdinal, GlobalOrdinal, Node>;

Teuchos::ParameterList MueLuPreconditioner::defaultParameters(int blockSize) {
  Teuchos::ParameterList p("MueLu");
  p.set("verbosity", "none");
  p.set("number of equations", blockSize);
  p.set("problem: symmetric", true);
  p.set("multigrid algorithm", "sa");
  p.set("aggregation: type", "uncoupled");
  p.set("smoother: type", "CHEBYSHEV");
  p.sublist("smoother: params").set("chebyshev: degree", 2);
  p.sublist("smoother: params").set("chebyshev: ratio eigenvalue", 7.0);
  // Amesos2 is wrong on more than one rank with Debian's Trilinos 13.2: the coarsest level
  // is smoothed by Chebyshev instead, and made small so that this is nearly exact.
  p.set("coarse: type", "CHEBYSHEV");
  p.sublist("coarse: params").set("chebyshev: degree", 8);
  p.set("coarse: max size", 100);
  p.set("max levels", 10);
  p.set("repartition: enable", false);  // Zoltan2 repartitioning aborts with 13.2
  p.set("reuse: type", "none");
  return p;
}

MueLuPreconditioner::MueLuPreconditioner(const Teuchos::ParameterList& params, int blockSize,
                                         RCP<const MultiVector> nullspace,
                                         RCP<const MultiVector> coordinates)
    : params_(defaultParameters(blockSize)),
      nullspace_(std::move(nullspace)),
      coordinates_(std::move(coordinates)) {
  // Our smoother parameters belong to our smoother choice: a user who picks another
  // smoother (or coarse solver) gets that package's defaults for it, plus whatever params
  // the user gives, never ours (Chebyshev's degree is an error for a relaxation).
  for (const char* level : {"smoother", "coarse"}) {
    const std::string type = std::string(level) + ": type", sub = std::string(level) + ": params";
    if (params.isType<std::string>(type) &&
        params.get<std::string>(type) != params_.get<std::string>(type))
      params_.remove(sub);
  }
  params_.setParameters(params);
}

void MueLuPreconditioner::compute(const RCP<CrsMatrix>& A, bool reuse) {
  if (reuse && !op_.is_null()) {
    auto mueluOp = Teuchos::rcp_dynamic_cast<MueLuOperator>(op_, true);
    MueLu::ReuseTpetraPreconditioner(A, *mueluOp);
    return;
  }
  Teuchos::ParameterList list = params_;
  auto& user = list.sublist("user data");
  if (!nullspace_.is_null())
    user.set("Nullspace", Teuchos::rcp_const_cast<MultiVector>(nullspace_));
  if (!coordinates_.is_null())
    user.set("Coordinates", Teuchos::rcp_const_cast<MultiVector>(coordinates_));
  try {
    op_ = MueLu::CreateTpetraPreconditioner<Scalar, LocalOrdinal, GlobalOrdinal, Node>(
        Teuchos::rcp_implicit_cast<Operator>(A), list);
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {
    throw InputError(std::string("MueLu rejected its parameter list: ") + e.what());
  }
}

RCP<Operator> MueLuPreconditioner::getOperator() const {
  if (op_.is_null()) throw Error("MueLuPreconditioner::getOperator called before compute()");
  return op_;
}

}  // namespace signorini
