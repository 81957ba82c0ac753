#include "solver/preconditioner/GatheredDirectSolver.hpp"

#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/preconditioner/LocalBlock.hpp"
#include "solver/preconditioner/LocalDirectSolver.hpp"

namespace signorini {

struct GatheredDirectSolver::Factorization {
  RCP<const Map> rowMap;    // A's (distributed)
  RCP<const Map> rootRows;  // every row, on rank 0
  RCP<const Import> toRoot;
  RCP<const Map> localRows;  // rank 0 only: the same rows on the one-rank communicator
  RCP<CrsMatrix> rootA;
  std::shared_ptr<LocalDirectSolver> solver;  // rank 0 only

  void factor() {
    // A new solver, so that operators handed out for the last matrix stay valid.
    solver = solver ? std::make_shared<LocalDirectSolver>(*solver) : std::make_shared<LocalDirectSolver>();
    solver->factor(rootA);
  }
};

class GatheredDirectSolver::RootSolve : public Operator {
 public:
  explicit RootSolve(std::shared_ptr<const Factorization> f) : f_(std::move(f)) {}

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha, Scalar beta) const override {
    const std::size_t numVectors = X.getNumVectors();
    if (rootB_.is_null() || rootB_->getNumVectors() != numVectors) {
      rootB_ = rcp(new MultiVector(f_->rootRows, numVectors));
      rootX_ = rcp(new MultiVector(f_->rootRows, numVectors));
      solution_ = rcp(new MultiVector(f_->rowMap, numVectors));
      if (!f_->localRows.is_null()) {
        localB_ = rcp(new MultiVector(f_->localRows, numVectors));
        localX_ = rcp(new MultiVector(f_->localRows, numVectors));
      }
    }
    rootB_->doImport(X, *f_->toRoot, Tpetra::INSERT);
    if (!f_->rootA.is_null() && f_->localRows->getNodeNumElements() > 0) {
      copyLocalRows(*rootB_, *localB_);
      f_->solver->solve(*localB_, *localX_);
      copyLocalRows(*localX_, *rootX_);
    }
    solution_->doExport(*rootX_, *f_->toRoot, Tpetra::INSERT);
    Y.update(alpha, *solution_, beta);
  }
  RCP<const Map> getDomainMap() const override { return f_->rowMap; }
  RCP<const Map> getRangeMap() const override { return f_->rowMap; }

 private:
  std::shared_ptr<const Factorization> f_;
  mutable RCP<MultiVector> rootB_, rootX_, solution_, localB_, localX_;
};

GatheredDirectSolver::GatheredDirectSolver() = default;
GatheredDirectSolver::~GatheredDirectSolver() = default;

void GatheredDirectSolver::compute(const RCP<CrsMatrix>& A, bool) {
  if (!A->getRowMap()->isSameAs(*A->getRangeMap()) || !A->getDomainMap()->isSameAs(*A->getRangeMap()))
    throw Error("GatheredDirectSolver: the matrix's row, range and domain maps must be the same");
  auto f = std::make_shared<Factorization>();
  if (factorization_ && factorization_->rowMap->isSameAs(*A->getRowMap())) {
    *f = *factorization_;  // the maps and the import stay
  } else {
    f->rootRows = Tpetra::Details::computeGatherMap(A->getRowMap(), Teuchos::null);
    f->toRoot = rcp(new Import(A->getRowMap(), f->rootRows));
    if (A->getRowMap()->getComm()->getRank() == 0)
      f->localRows = rcp(new Map(f->rootRows->getNodeNumElements(), 0, selfComm()));
  }
  f->rowMap = A->getRowMap();
  const RCP<const Map> rootRows = f->rootRows;
  const auto rowIndex = [&rootRows](GlobalOrdinal gid) { return rootRows->getLocalElement(gid); };
  f->rootA = importedBlock(*A, f->rootRows, *f->toRoot, rowIndex, f->localRows, f->localRows);
  if (!f->localRows.is_null() && f->localRows->getNodeNumElements() > 0) f->factor();
  factorization_ = f;
  op_ = rcp(new RootSolve(f));
}

RCP<Operator> GatheredDirectSolver::getOperator() const {
  if (op_.is_null()) throw Error("GatheredDirectSolver::getOperator called before compute()");
  return op_;
}

}  // namespace signorini
