#include "solver/preconditioner/MueLuPreconditioner.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_Hierarchy.hpp>
#include <MueLu_ParameterListInterpreter.hpp>
#include <MueLu_Utilities.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

using MueLuOperator = MueLu::TpetraOperator<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Hierarchy = MueLu::Hierarchy<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Interpreter = MueLu::ParameterListInterpreter<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using XpetraMatrix = Xpetra::Matrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;

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
  // R = P^T applied as P's transpose: the same operator without forming and storing R, whose
  // explicit transpose is a sizeable part of a smoothed-aggregation setup for 3D elasticity.
  p.set("transpose: use implicit", true);
  return p;
}

MueLuPreconditioner::MueLuPreconditioner(const Teuchos::ParameterList& params, int blockSize,
                                         RCP<const MultiVector> nullspace,
                                         RCP<const MultiVector> coordinates,
                                         Aggregation aggregation)
    : params_(defaultParameters(blockSize)),
      nullspace_(std::move(nullspace)),
      coordinates_(std::move(coordinates)),
      highValenceRoots_(aggregation == Aggregation::WholeHierarchy &&
                        !params.isParameter("aggregation: min agg size")) {
  if (aggregation == Aggregation::WholeHierarchy) params_.set("aggregation: drop tol", 0.01);
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
  // Both recompute products on the graphs of the first build, which Tpetra 13.2's reuse
  // kernels reject as new entries in a static graph on the Hessians of mortar and
  // force-controlled problems, although their pattern does not change.
  if (params_.isType<std::string>("reuse: type"))
    for (const char* broken : {"tP", "RP"})
      if (params_.get<std::string>("reuse: type") == broken)
        throw InputError(std::string("Solver/Preconditioner/MueLu/reuse: type: \"") + broken +
                         "\" fails inside Trilinos 13.2's matrix products on the Hessians of contact problems; use "
                         "\"none\" (the default), \"S\", \"RAP\" or \"emin\"");
  // "full" keeps the first hierarchy for every later Hessian, whose barrier weights grow by
  // orders of magnitude: three to four times the CG iterations on Gmsh cubes.
  if (params_.isType<std::string>("reuse: type") && params_.get<std::string>("reuse: type") == "full")
    throw InputError("Solver/Preconditioner/MueLu/reuse: type: \"full\" keeps the hierarchy of the first Hessian "
                     "for all later ones, whose contact weights grow by orders of magnitude; to rebuild less often, "
                     "raise Solver/Preconditioner/amg of H: rebuild tolerance, or use \"RAP\"");
}

namespace {

// True on every rank if A and B have the same rows, columns and entries in each row (their
// values aside). Collective.
bool samePattern(const CrsMatrix& A, const CrsMatrix& B) {
  bool same = A.getRowMap()->isSameAs(*B.getRowMap()) && A.getColMap()->isSameAs(*B.getColMap());
  if (same && A.getCrsGraph() != B.getCrsGraph()) {
    const auto a = A.getLocalMatrixHost().graph, b = B.getLocalMatrixHost().graph;
    same = a.row_map.extent(0) == b.row_map.extent(0) && a.entries.extent(0) == b.entries.extent(0);
    for (std::size_t i = 0; same && i < a.row_map.extent(0); ++i) same = a.row_map(i) == b.row_map(i);
    for (std::size_t k = 0; same && k < a.entries.extent(0); ++k) same = a.entries(k) == b.entries(k);
  }
  int local = same ? 1 : 0, all = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MIN, 1, &local, &all);
  return all == 1;
}

// The 99th percentile over all nodes of a node's row size in the nodal graph of A (the node
// and its neighbours): the entries of the node's first row over blockSize, rounded up. Collective.
int highValenceRowSize(const CrsMatrix& A, int blockSize) {
  constexpr int kLargest = 512;
  std::vector<long long> local(kLargest + 1, 0), global(kLargest + 1, 0);
  const auto rowMap = A.getRowMap();
  for (LocalOrdinal r = 0; r < static_cast<LocalOrdinal>(A.getNodeNumRows()); ++r) {
    if (rowMap->getGlobalElement(r) % blockSize != 0) continue;
    const std::size_t size = (A.getNumEntriesInLocalRow(r) + blockSize - 1) / blockSize;
    ++local[std::min<std::size_t>(size, kLargest)];
  }
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_SUM, kLargest + 1, local.data(), global.data());
  const long long nodes = std::accumulate(global.begin(), global.end(), 0LL);
  long long atMost = 0;
  for (int size = 0; size < kLargest; ++size)
    if ((atMost += global[size]) * 100 >= nodes * 99) return size;
  return kLargest;
}

// The hierarchy behind the operator compute() made.
RCP<Hierarchy> hierarchyOf(const RCP<Operator>& op) {
  return Teuchos::rcp_dynamic_cast<MueLuOperator>(op, true)->GetHierarchy();
}

}  // namespace

void MueLuPreconditioner::compute(const RCP<CrsMatrix>& A, bool reuse) {
  // MueLu's reuse keeps the coarse matrices' graphs: a matrix of another pattern (H of two
  // bodies, whose A^T D A is assembled by products) gets a new hierarchy.
  if (reuse && !op_.is_null() && !built_.is_null() && !samePattern(*A, *built_)) reuse = false;
  built_ = A;
  if (reuse && !op_.is_null()) {
    auto mueluOp = Teuchos::rcp_dynamic_cast<MueLuOperator>(op_, true);
    MueLu::ReuseTpetraPreconditioner(A, *mueluOp);
    return;
  }
  // The parameter list is interpreted once: building MueLu's factories from it costs more
  // than a whole setup of a small hierarchy, and every Newton step sets one up.
  try {
    if (factory_.is_null()) {
      if (highValenceRoots_)
        params_.set("aggregation: min agg size",
                    std::max(2, highValenceRowSize(*A, params_.get<int>("number of equations"))));
      factory_ = rcp(new Interpreter(params_, A->getDomainMap()->getComm()));
    }
    const RCP<Hierarchy> hierarchy = factory_->CreateHierarchy();
    hierarchy->setlib(Xpetra::UseTpetra);
    const RCP<MueLu::Level> fine = hierarchy->GetLevel(0);
    fine->Set("A", MueLu::TpetraCrs_To_XpetraMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>(A));
    if (!nullspace_.is_null())
      fine->Set("Nullspace", MueLu::TpetraMultiVector_To_XpetraMultiVector<Scalar, LocalOrdinal, GlobalOrdinal, Node>(
                                 Teuchos::rcp_const_cast<MultiVector>(nullspace_)));
    if (!coordinates_.is_null())
      fine->Set("Coordinates", MueLu::TpetraMultiVector_To_XpetraMultiVector<Scalar, LocalOrdinal, GlobalOrdinal, Node>(
                                   Teuchos::rcp_const_cast<MultiVector>(coordinates_)));
    hierarchy->SetProcRankVerbose(A->getDomainMap()->getComm()->getRank());
    factory_->SetupHierarchy(*hierarchy);
    op_ = rcp(new MueLuOperator(hierarchy));
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {
    throw InputError(std::string("MueLu rejected its parameter list: ") + e.what());
  }
}

std::vector<MueLuPreconditioner::CoarseLevel> MueLuPreconditioner::coarseLevels() const {
  using Utilities = MueLu::Utilities<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
  if (op_.is_null()) throw Error("MueLuPreconditioner::coarseLevels called before compute()");
  const RCP<Hierarchy> hierarchy = hierarchyOf(op_);
  std::vector<CoarseLevel> levels;
  for (int l = 1; l < hierarchy->GetNumLevels(); ++l) {
    const RCP<MueLu::Level> level = hierarchy->GetLevel(l);
    if (!level->IsAvailable("P") || !level->IsAvailable("A"))
      throw Error("MueLuPreconditioner::coarseLevels: MueLu kept no P or A on level " + std::to_string(l));
    levels.push_back({Utilities::Op2NonConstTpetraCrs(level->Get<RCP<XpetraMatrix>>("P")),
                      Utilities::Op2NonConstTpetraCrs(level->Get<RCP<XpetraMatrix>>("A"))});
  }
  return levels;
}

// Counting stops at a level whose matrix MueLu did not keep (as the user's list may ask for
// its coarsest): a count is no reason to fail a solve.
std::vector<long long> MueLuPreconditioner::levelNonzeros() const {
  if (op_.is_null() || built_.is_null()) return {};
  const RCP<Hierarchy> hierarchy = hierarchyOf(op_);
  std::vector<long long> nonzeros{static_cast<long long>(built_->getGlobalNumEntries())};
  for (int l = 1; l < hierarchy->GetNumLevels() && hierarchy->GetLevel(l)->IsAvailable("A"); ++l)
    nonzeros.push_back(static_cast<long long>(hierarchy->GetLevel(l)->Get<RCP<XpetraMatrix>>("A")->getGlobalNumEntries()));
  return nonzeros;
}

RCP<Operator> MueLuPreconditioner::getOperator() const {
  if (op_.is_null()) throw Error("MueLuPreconditioner::getOperator called before compute()");
  return op_;
}

}  // namespace signorini
