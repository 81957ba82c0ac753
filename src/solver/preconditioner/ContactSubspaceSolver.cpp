#include "solver/preconditioner/ContactSubspaceSolver.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include <Tpetra_ComputeGatherMap.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_RowMatrixTransposer.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "solver/preconditioner/LocalBlock.hpp"
#include "solver/preconditioner/LocalDirectSolver.hpp"

namespace signorini {

struct ContactSubspaceSolver::Impl {
  RCP<const Map> dofMap;
  // The contact DOFs of this rank's block, and the constraints on them: on rank 0 all of
  // them (gathered), or those this rank owns and the constraints that touch them (per rank).
  RCP<const Map> blockDofs, blockConstraints;
  RCP<const Import> toBlockDofs, toBlockConstraints;
  bool perRank = false;
  // Ranks with a nonempty block, on a one-rank communicator: P^T Q P and A P with
  // block-local column indices, and H_c = P^T Q P + (A P)^T D (A P) with its factorization.
  RCP<const Map> localDofs, localConstraints;
  RCP<BarrierHessianOperator> hessian;
  LocalDirectSolver solver;
  bool factored = false;
  // Scratch of apply(), which runs in every Krylov iteration; sized for `numVectors` columns.
  std::size_t numVectors = 0;
  RCP<MultiVector> blockX, blockY, localB, localX, correction;
};

namespace {

// The DOFs that appear with a nonzero entry in A's rows on this rank, sorted.
std::vector<GlobalOrdinal> contactDofsInRows(const CrsMatrix& A) {
  std::vector<GlobalOrdinal> touched;
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(A.getNodeNumRows()); ++i) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    A.getLocalRowView(i, cols, vals);
    for (std::size_t k = 0; k < cols.extent(0); ++k)
      if (vals(k) != 0.0) touched.push_back(A.getColMap()->getGlobalElement(cols(k)));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  return touched;
}

RCP<const Map> mapOf(const std::vector<GlobalOrdinal>& ids, const RCP<const Comm>& comm) {
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, comm));
}

// Per rank: the contact DOFs it owns in `dofMap`, and the constraints whose rows touch them.
void ownedBlock(const CrsMatrix& A, const RCP<const Map>& dofMap, const std::vector<GlobalOrdinal>& touched,
                RCP<const Map>& dofs, RCP<const Map>& constraints) {
  const RCP<const Comm> comm = dofMap->getComm();
  Vector seen(mapOf(touched, comm)), owned(dofMap);
  seen.putScalar(1.0);
  owned.doExport(seen, Export(seen.getMap(), dofMap), Tpetra::INSERT);
  std::vector<GlobalOrdinal> ownedDofs;
  auto o = owned.getData();
  for (std::size_t i = 0; i < owned.getLocalLength(); ++i)
    if (o[i] != 0.0) ownedDofs.push_back(dofMap->getGlobalElement(i));
  dofs = mapOf(ownedDofs, comm);
  // Constraint ids carried to the owners of the DOFs they touch, through A^T's rows there.
  const RCP<CrsMatrix> At =
      Tpetra::RowMatrixTransposer<Scalar, LocalOrdinal, GlobalOrdinal, Node>(Teuchos::rcpFromRef(A)).createTranspose();
  std::vector<GlobalOrdinal> ids;
  for (GlobalOrdinal dof : ownedDofs) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    At->getLocalRowView(At->getRowMap()->getLocalElement(dof), cols, vals);
    for (std::size_t k = 0; k < cols.extent(0); ++k)
      if (vals(k) != 0.0) ids.push_back(At->getColMap()->getGlobalElement(cols(k)));
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  constraints = mapOf(ids, comm);
}

// Whether every row of A has all its DOFs on one rank of `dofMap`, on every rank. Collective.
bool constraintsWithinRanks(const CrsMatrix& A, const Map& dofMap) {
  const auto columns = A.getColMap();
  Teuchos::Array<GlobalOrdinal> ids(columns->getNodeNumElements());
  for (long c = 0; c < ids.size(); ++c) ids[c] = columns->getGlobalElement(c);
  Teuchos::Array<int> owners(ids.size());
  dofMap.getRemoteIndexList(ids(), owners());
  bool within = true;
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(A.getNodeNumRows()); ++i) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    A.getLocalRowView(i, cols, vals);
    for (std::size_t k = 1; k < cols.extent(0); ++k)
      if (owners[cols(k)] != owners[cols(0)]) within = false;
  }
  return onEveryRank(*dofMap.getComm(), within);
}

}  // namespace

ContactSubspaceSolver::ContactSubspaceSolver(const CrsMatrix& Q, const CrsMatrix& A, ContactSubspaceBlocks blocks)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.dofMap = Q.getDomainMap();
  if (!Q.getRowMap()->isSameAs(*s.dofMap))
    throw Error("ContactSubspaceSolver: Q's row map must be its domain map");
  if (!A.getDomainMap()->isSameAs(*s.dofMap)) throw Error("ContactSubspaceSolver: A's domain map differs from Q's");
  const RCP<const Comm> comm = s.dofMap->getComm();
  const std::vector<GlobalOrdinal> touched = contactDofsInRows(A);
  if (blocks == ContactSubspaceBlocks::Auto)
    blocks = constraintsWithinRanks(A, *s.dofMap) ? ContactSubspaceBlocks::PerRank : ContactSubspaceBlocks::Gathered;
  s.perRank = blocks == ContactSubspaceBlocks::PerRank;
  if (blocks == ContactSubspaceBlocks::Gathered) {
    s.blockDofs = Tpetra::Details::computeGatherMap(Tpetra::createOneToOne(mapOf(touched, comm)), Teuchos::null);
    s.blockConstraints = Tpetra::Details::computeGatherMap(A.getRangeMap(), Teuchos::null);
  } else {
    ownedBlock(A, s.dofMap, touched, s.blockDofs, s.blockConstraints);
  }
  s.toBlockDofs = rcp(new Import(s.dofMap, s.blockDofs));
  s.toBlockConstraints = rcp(new Import(A.getRowMap(), s.blockConstraints));

  std::unordered_map<GlobalOrdinal, LocalOrdinal> blockIndex;
  if (s.blockDofs->getNodeNumElements() > 0) {
    const RCP<const Comm> self = selfComm();
    s.localDofs = rcp(new Map(s.blockDofs->getNodeNumElements(), 0, self));
    s.localConstraints = rcp(new Map(s.blockConstraints->getNodeNumElements(), 0, self));
    for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(s.blockDofs->getNodeNumElements()); ++i)
      blockIndex[s.blockDofs->getGlobalElement(i)] = i;
  }
  const auto blockColumn = [&blockIndex](GlobalOrdinal gid) {
    const auto it = blockIndex.find(gid);
    return it == blockIndex.end() ? LocalOrdinal(-1) : it->second;
  };
  RCP<CrsMatrix> Qc = importedBlock(Q, s.blockDofs, *s.toBlockDofs, blockColumn, s.localDofs, s.localDofs);
  RCP<CrsMatrix> Ac =
      importedBlock(A, s.blockConstraints, *s.toBlockConstraints, blockColumn, s.localConstraints, s.localDofs);
  if (!s.localDofs.is_null()) s.hessian = rcp(new BarrierHessianOperator(Qc, Ac));
}

ContactSubspaceSolver::~ContactSubspaceSolver() = default;

void ContactSubspaceSolver::setWeights(const Vector& D) {
  Impl& s = *impl_;
  Vector blockD(s.blockConstraints);
  blockD.doImport(D, *s.toBlockConstraints, Tpetra::INSERT);
  if (s.localDofs.is_null()) return;
  Vector localD(s.localConstraints);
  copyLocalRows(blockD, localD);
  s.hessian->setWeights(localD);
  s.solver.factor(s.hessian->assemble());
  s.factored = true;
}

void ContactSubspaceSolver::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                  Scalar beta) const {
  Impl& s = *impl_;
  const std::size_t numVectors = X.getNumVectors();
  if (s.numVectors != numVectors) {
    s.numVectors = numVectors;
    s.blockX = rcp(new MultiVector(s.blockDofs, numVectors));
    s.blockY = rcp(new MultiVector(s.blockDofs, numVectors));
    s.correction = rcp(new MultiVector(s.dofMap, numVectors));
    if (!s.localDofs.is_null()) {
      s.localB = rcp(new MultiVector(s.localDofs, numVectors));
      s.localX = rcp(new MultiVector(s.localDofs, numVectors));
    }
  }
  s.blockX->doImport(X, *s.toBlockDofs, Tpetra::INSERT);
  if (!s.localDofs.is_null()) {
    if (!s.factored) throw Error("ContactSubspaceSolver::apply called before setWeights()");
    copyLocalRows(*s.blockX, *s.localB);
    s.solver.solve(*s.localB, *s.localX);
    copyLocalRows(*s.localX, *s.blockY);
  }
  s.correction->putScalar(0.0);  // the export writes the contact DOFs only, each from one block
  s.correction->doExport(*s.blockY, *s.toBlockDofs, Tpetra::INSERT);
  Y.update(alpha, *s.correction, beta);
}

bool ContactSubspaceSolver::perRank() const { return impl_->perRank; }

RCP<const Map> ContactSubspaceSolver::getDomainMap() const { return impl_->dofMap; }
RCP<const Map> ContactSubspaceSolver::getRangeMap() const { return impl_->dofMap; }
long long ContactSubspaceSolver::dimension() const {
  return static_cast<long long>(impl_->blockDofs->getGlobalNumElements());
}

}  // namespace signorini
