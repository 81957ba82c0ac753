#include "signorini/DistributedSpace.hpp"

#include <Tpetra_Map.hpp>

#include "signorini/MeshPartition.hpp"

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

}  // namespace

DistributedSpace::DistributedSpace(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> mesh,
                                   int degree)
    : comm_(comm), mesh_(std::move(mesh)), space_(std::make_unique<LagrangeSpace>(*mesh_, degree)) {
  const int rank = comm_->getRank(), size = comm_->getSize();
  cellPart_ = partitionCells(*mesh_, size);
  nodeOwner_ = nodeOwners(*space_, cellPart_);

  // Contiguous renumbering: rank r owns [offset_r, offset_{r+1}), nodes kept in space order.
  const long long numNodes = space_->numNodes();
  std::vector<long long> offset(size + 1, 0);
  for (long long n = 0; n < numNodes; ++n) ++offset[nodeOwner_[n] + 1];
  for (int r = 0; r < size; ++r) offset[r + 1] += offset[r];
  newId_.resize(numNodes);
  std::vector<long long> next(offset.begin(), offset.end() - 1);
  std::vector<GlobalOrdinal> owned;
  for (long long n = 0; n < numNodes; ++n) {
    newId_[n] = next[nodeOwner_[n]]++;
    if (nodeOwner_[n] == rank) {
      owned.push_back(newId_[n]);
      overlapSpaceNodes_.push_back(n);
    }
  }

  for (long long c = 0; c < mesh_->numCells(); ++c)
    if (cellPart_[c] == rank) localCells_.push_back(c);

  // Ghosts: nodes of local cells owned elsewhere, sorted by new id.
  std::vector<char> seen(numNodes, 0);
  std::vector<long long> ghosts;
  const int npc = space_->nodesPerCell();
  for (long long c : localCells_) {
    const long long* nodes = space_->cellNodes(c);
    for (int i = 0; i < npc; ++i)
      if (nodeOwner_[nodes[i]] != rank && !seen[nodes[i]]) {
        seen[nodes[i]] = 1;
        ghosts.push_back(nodes[i]);
      }
  }
  std::sort(ghosts.begin(), ghosts.end(),
            [&](long long a, long long b) { return newId_[a] < newId_[b]; });
  std::vector<GlobalOrdinal> overlap = owned;
  for (long long n : ghosts) {
    overlap.push_back(newId_[n]);
    overlapSpaceNodes_.push_back(n);
  }

  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  ownedNodeMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(owned), 0, comm_));
  overlapNodeMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(overlap), 0, comm_));
  ownedDofMap_ = dofMapOf(owned, dim(), comm_);
  overlapDofMap_ = dofMapOf(overlap, dim(), comm_);
}

}  // namespace signorini
