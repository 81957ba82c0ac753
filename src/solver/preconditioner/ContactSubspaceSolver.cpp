#include "solver/preconditioner/ContactSubspaceSolver.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"

namespace signorini {

using DirectSolver = Amesos2::Solver<CrsMatrix, MultiVector>;

struct ContactSubspaceSolver::Impl {
  RCP<const Map> dofMap;
  RCP<const Map> rootDofs;         // the contact DOFs, all on rank 0
  RCP<const Map> rootConstraints;  // the constraints, all on rank 0
  RCP<const Import> toRootDofs, toRootConstraints;
  bool onRoot = false;
  // Rank 0 only, on a one-rank communicator: P^T Q P and A P with contact-local column
  // indices, and H_c = P^T Q P + (A P)^T D (A P) with its factorization.
  RCP<const Map> localDofs, localConstraints;
  RCP<BarrierHessianOperator> hessian;
  RCP<DirectSolver> solver;
  // Scratch of apply(), which runs in every Krylov iteration; sized for `numVectors` columns.
  std::size_t numVectors = 0;
  RCP<MultiVector> rootX, rootY, localB, localX, correction;
};

namespace {

// Rows of M imported to `rootRows` (all on rank 0), kept on rank 0 with only the columns in
// `columnIndex` (global id -> contact index), as a matrix on the one-rank communicator.
RCP<CrsMatrix> rootRestriction(const CrsMatrix& M, const RCP<const Map>& rootRows, const Import& importer,
                               const std::unordered_map<GlobalOrdinal, LocalOrdinal>& columnIndex,
                               const RCP<const Map>& localRows, const RCP<const Map>& localColumns) {
  RCP<CrsMatrix> gathered = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(
      Teuchos::rcpFromRef(M), importer, M.getDomainMap(), rootRows);
  if (localRows.is_null()) return Teuchos::null;
  const LocalOrdinal numRows = static_cast<LocalOrdinal>(gathered->getNodeNumRows());
  const std::size_t maxEntries = gathered->getNodeMaxNumRowEntries();
  Teuchos::Array<GlobalOrdinal> cols(maxEntries);
  Teuchos::Array<Scalar> vals(maxEntries);
  std::vector<std::vector<GlobalOrdinal>> keptCols(numRows);
  std::vector<std::vector<Scalar>> keptVals(numRows);
  Teuchos::Array<std::size_t> rowLengths(numRows);
  for (LocalOrdinal i = 0; i < numRows; ++i) {
    std::size_t count = 0;
    gathered->getGlobalRowCopy(rootRows->getGlobalElement(i), cols(), vals(), count);
    for (std::size_t k = 0; k < count; ++k) {
      auto it = columnIndex.find(cols[k]);
      if (it == columnIndex.end()) continue;
      keptCols[i].push_back(it->second);
      keptVals[i].push_back(vals[k]);
    }
    rowLengths[i] = keptCols[i].size();
  }
  auto result = rcp(new CrsMatrix(localRows, rowLengths()));
  for (LocalOrdinal i = 0; i < numRows; ++i)
    result->insertGlobalValues(i, Teuchos::ArrayView<const GlobalOrdinal>(keptCols[i]),
                               Teuchos::ArrayView<const Scalar>(keptVals[i]));
  result->fillComplete(localColumns, localRows);
  return result;
}

// Copies the local rows of `from` into `to` (same local length and number of columns).
void copyLocalRows(const MultiVector& from, MultiVector& to) {
  for (std::size_t j = 0; j < from.getNumVectors(); ++j) {
    auto f = from.getData(j);
    auto t = to.getDataNonConst(j);
    for (std::size_t i = 0; i < from.getLocalLength(); ++i) t[i] = f[i];
  }
}

}  // namespace

ContactSubspaceSolver::ContactSubspaceSolver(const CrsMatrix& Q, const CrsMatrix& A)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.dofMap = Q.getDomainMap();
  if (!Q.getRowMap()->isSameAs(*s.dofMap))
    throw Error("ContactSubspaceSolver: Q's row map must be its domain map");
  if (!A.getDomainMap()->isSameAs(*s.dofMap)) throw Error("ContactSubspaceSolver: A's domain map differs from Q's");
  const RCP<const Comm> comm = s.dofMap->getComm();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();

  // The contact DOFs: every column of A with an entry, gathered to rank 0 without repeats.
  std::vector<GlobalOrdinal> touched;
  {
    const std::size_t maxEntries = A.getNodeMaxNumRowEntries();
    Teuchos::Array<GlobalOrdinal> cols(maxEntries);
    Teuchos::Array<Scalar> vals(maxEntries);
    for (std::size_t i = 0; i < A.getNodeNumRows(); ++i) {
      std::size_t count = 0;
      A.getGlobalRowCopy(A.getRowMap()->getGlobalElement(i), cols(), vals(), count);
      for (std::size_t k = 0; k < count; ++k)
        if (vals[k] != 0.0) touched.push_back(cols[k]);
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  }
  RCP<const Map> touchedMap = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(touched), 0, comm));
  s.rootDofs = Tpetra::Details::computeGatherMap(Tpetra::createOneToOne(touchedMap), Teuchos::null);
  s.rootConstraints = Tpetra::Details::computeGatherMap(A.getRangeMap(), Teuchos::null);
  s.toRootDofs = rcp(new Import(s.dofMap, s.rootDofs));
  s.toRootConstraints = rcp(new Import(A.getRowMap(), s.rootConstraints));
  s.onRoot = comm->getRank() == 0;

  std::unordered_map<GlobalOrdinal, LocalOrdinal> contactIndex;
  if (s.onRoot) {
    const RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    s.localDofs = rcp(new Map(s.rootDofs->getNodeNumElements(), 0, self));
    s.localConstraints = rcp(new Map(s.rootConstraints->getNodeNumElements(), 0, self));
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(s.rootDofs->getNodeNumElements()); ++i)
      contactIndex[s.rootDofs->getGlobalElement(i)] = i;
  }
  RCP<CrsMatrix> Qc = rootRestriction(Q, s.rootDofs, *s.toRootDofs, contactIndex, s.localDofs, s.localDofs);
  RCP<CrsMatrix> Ac =
      rootRestriction(A, s.rootConstraints, *s.toRootConstraints, contactIndex, s.localConstraints, s.localDofs);
  if (s.onRoot) s.hessian = rcp(new BarrierHessianOperator(Qc, Ac));
}

ContactSubspaceSolver::~ContactSubspaceSolver() = default;

void ContactSubspaceSolver::setWeights(const Vector& D) {
  Impl& s = *impl_;
  Vector rootD(s.rootConstraints);
  rootD.doImport(D, *s.toRootConstraints, Tpetra::INSERT);
  if (!s.onRoot || s.localDofs->getNodeNumElements() == 0) return;
  Vector localD(s.localConstraints);
  copyLocalRows(rootD, localD);
  s.hessian->setWeights(localD);
  RCP<CrsMatrix> Hc = s.hessian->assemble();
  s.solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", Hc);
  s.solver->symbolicFactorization().numericFactorization();
}

void ContactSubspaceSolver::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                  Scalar beta) const {
  Impl& s = *impl_;
  const std::size_t numVectors = X.getNumVectors();
  if (s.numVectors != numVectors) {
    s.numVectors = numVectors;
    s.rootX = rcp(new MultiVector(s.rootDofs, numVectors));
    s.rootY = rcp(new MultiVector(s.rootDofs, numVectors));
    s.correction = rcp(new MultiVector(s.dofMap, numVectors));
    if (s.onRoot) {
      s.localB = rcp(new MultiVector(s.localDofs, numVectors));
      s.localX = rcp(new MultiVector(s.localDofs, numVectors));
    }
  }
  s.rootX->doImport(X, *s.toRootDofs, Tpetra::INSERT);
  if (s.onRoot && s.localDofs->getNodeNumElements() > 0) {
    if (s.solver.is_null()) throw Error("ContactSubspaceSolver::apply called before setWeights()");
    copyLocalRows(*s.rootX, *s.localB);
    s.solver->solve(s.localX.ptr(), s.localB.ptr());
    copyLocalRows(*s.localX, *s.rootY);
  }
  s.correction->putScalar(0.0);  // the export writes the contact DOFs only
  s.correction->doExport(*s.rootY, *s.toRootDofs, Tpetra::INSERT);
  Y.update(alpha, *s.correction, beta);
}

RCP<const Map> ContactSubspaceSolver::getDomainMap() const { return impl_->dofMap; }
RCP<const Map> ContactSubspaceSolver::getRangeMap() const { return impl_->dofMap; }
long long ContactSubspaceSolver::dimension() const {
  return static_cast<long long>(impl_->rootDofs->getGlobalNumElements());
}

}  // namespace signorini
