#include "assembly/MeshPieces.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"

namespace signorini {
namespace {

// Union-find over the space nodes of this rank's cells.
class LocalPieces {
 public:
  explicit LocalPieces(const LagrangeSpace& space) : parent_(space.numNodes()) {
    std::iota(parent_.begin(), parent_.end(), 0LL);
    for (long long cell = 0; cell < space.mesh().numCells(); ++cell) {
      const long long* nodes = space.cellNodes(cell);
      for (int a = 1; a < space.nodesPerCell(); ++a) unite(nodes[0], nodes[a]);
    }
  }
  long long root(long long n) {
    while (parent_[n] != n) n = parent_[n] = parent_[parent_[n]];
    return n;
  }

 private:
  void unite(long long a, long long b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  std::vector<long long> parent_;
};

MeshPieces findPieces(const DistributedSpace& ds) {
  LocalPieces local(ds.space());
  const auto& overlap = ds.overlapSpaceNodes();
  const long long numNodes = ds.space().numNodes();
  // Each local piece takes the smallest global id of its nodes, over every rank: labels pass
  // through the nodes that ranks share until none changes. Values numGlobal - label, so that
  // the owners' ABSMAX keeps the smallest label.
  std::vector<double> label(numNodes);
  for (long long n = 0; n < numNodes; ++n) label[n] = static_cast<double>(ds.globalNode(n));
  const double top = static_cast<double>(ds.numGlobalNodes());
  Vector owned(ds.ownedNodeMap()), shared(ds.overlapNodeMap());
  const Export toOwners(ds.overlapNodeMap(), ds.ownedNodeMap());
  const Import toSharers(ds.ownedNodeMap(), ds.overlapNodeMap());
  for (bool changed = true; changed;) {
    std::vector<double> smallest(numNodes, top);
    for (long long n = 0; n < numNodes; ++n) smallest[local.root(n)] = std::min(smallest[local.root(n)], label[n]);
    {
      auto s = shared.getDataNonConst();
      for (std::size_t i = 0; i < overlap.size(); ++i) s[i] = top - smallest[local.root(overlap[i])];
    }
    owned.putScalar(0.0);
    owned.doExport(shared, toOwners, Tpetra::ABSMAX);
    shared.doImport(owned, toSharers, Tpetra::INSERT);
    bool mine = false;
    auto s = shared.getData();
    for (std::size_t i = 0; i < overlap.size(); ++i) {
      const double updated = top - s[i];
      mine = mine || updated != label[overlap[i]];
      label[overlap[i]] = updated;
    }
    changed = !onEveryRank(*ds.comm(), !mine);
  }
  // Number the pieces by their labels, the same on every rank.
  std::vector<double> labels;
  for (std::size_t i = 0; i < ds.ownedNodeMap()->getNodeNumElements(); ++i) labels.push_back(label[overlap[i]]);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  std::vector<double> all = exchangeWithRanks(*ds.comm(), std::vector<std::vector<double>>(ds.comm()->getSize(), labels));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  MeshPieces pieces;
  pieces.count = static_cast<int>(all.size());
  const auto pieceOf = [&](double l) { return static_cast<int>(std::lower_bound(all.begin(), all.end(), l) - all.begin()); };
  for (std::size_t i = 0; i < ds.ownedNodeMap()->getNodeNumElements(); ++i)
    pieces.ofOwnedNode.push_back(pieceOf(label[overlap[i]]));
  pieces.ofSpaceNode.assign(numNodes, -1);
  for (long long n : overlap) pieces.ofSpaceNode[n] = pieceOf(label[n]);
  return pieces;
}

}  // namespace

const MeshPieces& meshPieces(const DistributedSpace& ds) {
  if (!ds.pieces_) ds.pieces_ = std::make_shared<const MeshPieces>(findPieces(ds));
  return *ds.pieces_;
}

}  // namespace signorini
