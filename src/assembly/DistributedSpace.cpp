#include "assembly/DistributedSpace.hpp"

#include <algorithm>
#include <tuple>
#include <utility>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>

#include "assembly/BoxMeshPart.hpp"
#include "assembly/GlobalPartition.hpp"
#include "assembly/MeshPart.hpp"
#include "assembly/RefinedMeshPart.hpp"
#include "core/Collectives.hpp"
#include "core/RootTask.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

RCP<const Map> dofMapOf(const std::vector<GlobalOrdinal>& nodes, int dim, const RCP<const Comm>& comm) {
  std::vector<GlobalOrdinal> dofs;
  dofs.reserve(nodes.size() * dim);
  for (GlobalOrdinal n : nodes)
    for (int c = 0; c < dim; ++c) dofs.push_back(dim * n + c);
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                     Teuchos::ArrayView<const GlobalOrdinal>(dofs), 0, comm));
}

// The owned nodes' map, and its DOF map. Ranks own consecutive ranges of the renumbered nodes
// in rank order; told so, Tpetra finds the owner of an index by a search in the ranges,
// where a map given as a list of indices needs a distributed directory built with an
// all-to-all exchange of every index (the largest part of the imports' setup).
std::pair<RCP<const Map>, RCP<const Map>> ownedMapsOf(const std::vector<GlobalOrdinal>& owned, int dim,
                                                      const RCP<const Comm>& comm) {
  const long long count = static_cast<long long>(owned.size());
  long long upTo = 0;
  Teuchos::scan(*comm, Teuchos::REDUCE_SUM, 1, &count, &upTo);
  bool consecutive = true;
  for (std::size_t i = 0; i < owned.size(); ++i) consecutive = consecutive && owned[i] == upTo - count + static_cast<long long>(i);
  if (!onEveryRank(*comm, consecutive)) {
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    return {rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(owned), 0, comm)), dofMapOf(owned, dim, comm)};
  }
  const auto all = static_cast<Tpetra::global_size_t>(sumOverRanks(*comm, count));
  return {rcp(new Map(all, owned.size(), 0, comm)), rcp(new Map(dim * all, dim * owned.size(), 0, comm))};
}

}  // namespace

DistributedSpace::DistributedSpace(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> globalMesh,
                                   int degree)
    : comm_(comm) {
  const int rank = comm_->getRank(), size = comm_->getSize();

  // The serial phase: rank 0 partitions the global mesh and sends each rank its part.
  detail::MeshPart part;
  long long counts[3] = {0, 0, 0};  // global nodes, global cells, serial phase bytes
  std::unique_ptr<detail::GlobalPartition> global;
  detail::runOnRoot(*comm_, [&] {
    if (!globalMesh) throw InputError("distributed space: rank 0 has no mesh");
    global = std::make_unique<detail::GlobalPartition>(*globalMesh, degree, size);
    counts[0] = global->numNodes();
    counts[1] = global->numCells();
    counts[2] = static_cast<long long>(globalMesh->bytes() + global->bytes());
  });
  Teuchos::broadcast(*comm_, 0, 3, counts);
  numGlobalNodes_ = counts[0];
  numGlobalCells_ = counts[1];
  serialPhaseBytes_ = static_cast<std::size_t>(counts[2]);
  if (rank == 0) {
    for (int r = 1; r < size; ++r) detail::sendMeshPart(*comm_, global->part(r), r);
    part = global->part(0);
  } else {
    part = detail::receiveMeshPart(*comm_, 0);
  }
  // Rank 0 keeps no more of the global problem than any other rank (unless the caller holds
  // on to the mesh).
  global.reset();
  globalMesh.reset();
#if defined(__GLIBC__)
  if (rank == 0) malloc_trim(0);  // glibc keeps freed heap pages resident: hand them back
#endif

  adopt(std::move(part), degree);
}

DistributedSpace::DistributedSpace(const RCP<const Comm>& comm, const BoxGrid& box, int degree) : comm_(comm) {
  const BoxDecomposition blocks = decomposeBox(box.dim, box.cells, comm->getSize());
  if (blocks.numBlocks() != comm->getSize()) {  // more ranks than the boxes can be cut into
    std::shared_ptr<const SimplexMesh> global;
    detail::runOnRoot(*comm_, [&] {
      global = std::make_shared<const SimplexMesh>(makeBoxMesh(box.dim, box.cells, box.lengths));
    });
    *this = DistributedSpace(comm, std::move(global), degree);
    return;
  }
  detail::PartWithSpace part = detail::makeBoxMeshPart(comm_, box, blocks, degree);
  numGlobalNodes_ = part.numGlobalNodes;
  numGlobalCells_ = part.numGlobalCells;
  adopt(std::move(part.part), std::move(part.mesh), std::move(part.space));
}

DistributedSpace::DistributedSpace(const detail::CoarseMeshLattice& lattice, const SimplexRefinement& refinement,
                                   int degree, detail::RefinedLevel& finest)
    : comm_(lattice.comm()) {
  detail::PartWithSpace part = detail::makeRefinedMeshPart(lattice, refinement, degree, finest);
  numGlobalNodes_ = part.numGlobalNodes;
  numGlobalCells_ = part.numGlobalCells;
  serialPhaseBytes_ = lattice.serialPhaseBytes();
  adopt(std::move(part.part), std::move(part.mesh), std::move(part.space));
}

void DistributedSpace::adopt(detail::MeshPart&& part, int degree) {
  auto mesh = std::make_shared<const SimplexMesh>(std::move(part.mesh));
  std::unique_ptr<LagrangeSpace> space;
  bool consistent = true;
  try {
    space = std::make_unique<LagrangeSpace>(*mesh, degree, part.nodeCoordinates);
  } catch (const Error&) {
    consistent = false;
  }
  // adopt() below checks the space against the part on every rank.
  if (!onEveryRank(*comm_, consistent)) throw Error("distributed space: a rank's space does not match its part");
  adopt(std::move(part), std::move(mesh), std::move(space));
}

void DistributedSpace::adopt(detail::MeshPart&& part, std::shared_ptr<const SimplexMesh> mesh,
                             std::unique_ptr<LagrangeSpace> space) {
  const int rank = comm_->getRank();
  mesh_ = std::move(mesh);
  space_ = std::move(space);
  // The part's node data follows this space's numbering; a mismatch is a bug, not an input error.
  if (!onEveryRank(*comm_, space_->numNodes() == static_cast<long long>(part.nodeIds.size())))
    throw Error("distributed space: a rank's space does not match its part");
  nodeId_ = std::move(part.nodeIds);
  nodeOwner_ = std::move(part.nodeOwners);
  globalCells_ = std::move(part.globalCells);
  boundaryTags_ = std::move(part.boundaryTags);
  boundaryStart_ = std::move(part.boundaryStart);
  boundaryNodes_ = std::move(part.boundaryNodes);

  // Owned nodes, then the ghosts, each sorted by renumbered id: the order of the global space.
  const long long numNodes = space_->numNodes();
  overlapSpaceNodes_.resize(numNodes);
  for (long long n = 0; n < numNodes; ++n) overlapSpaceNodes_[n] = n;
  std::sort(overlapSpaceNodes_.begin(), overlapSpaceNodes_.end(), [&](long long a, long long b) {
    const bool ownsA = nodeOwner_[a] == rank, ownsB = nodeOwner_[b] == rank;
    return ownsA != ownsB ? ownsA : nodeId_[a] < nodeId_[b];
  });
  std::vector<GlobalOrdinal> overlap(numNodes);
  for (long long i = 0; i < numNodes; ++i) overlap[i] = nodeId_[overlapSpaceNodes_[i]];
  const std::size_t numOwned = std::count(nodeOwner_.begin(), nodeOwner_.end(), rank);
  const std::vector<GlobalOrdinal> owned(overlap.begin(), overlap.begin() + numOwned);

  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::tie(ownedNodeMap_, ownedDofMap_) = ownedMapsOf(owned, dim(), comm_);
  overlapNodeMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(overlap), 0, comm_));
  overlapDofMap_ = dofMapOf(overlap, dim(), comm_);
}

void DistributedSpace::overlapNodeCoordinates(std::size_t i, double* x) const {
  const int d = dim();
  std::copy_n(&space_->nodeCoordinates()[d * overlapSpaceNodes_[i]], d, x);
}

const DistributedSpace& distributedSpace(const FiniteElementSpace& space) {
  const auto* ds = dynamic_cast<const DistributedSpace*>(&space);
  if (!ds) throw Error("a FiniteElementSpace that the library did not make (buildProblem makes them)");
  return *ds;
}

std::shared_ptr<const DistributedSpace> distributedSpace(const std::shared_ptr<const FiniteElementSpace>& space) {
  distributedSpace(*space);
  return std::static_pointer_cast<const DistributedSpace>(space);
}

std::vector<long long> DistributedSpace::boundaryNodes(int tag) const {
  const auto it = std::lower_bound(boundaryTags_.begin(), boundaryTags_.end(), tag);
  if (it == boundaryTags_.end() || *it != tag) return {};
  const std::size_t i = it - boundaryTags_.begin();
  return std::vector<long long>(boundaryNodes_.begin() + boundaryStart_[i], boundaryNodes_.begin() + boundaryStart_[i + 1]);
}

}  // namespace signorini
