#pragma once
// The vector-valued P_k space of a mesh partitioned over the ranks of a communicator.
// Nodes are renumbered so that each rank owns a contiguous range (rank order); degrees of
// freedom are dof = dim * node + component. Each rank assembles only the cells of its
// METIS part; the nodes of those cells are its overlap (owned first, then ghosts).
#include <memory>
#include <vector>

#include "signorini/LagrangeSpace.hpp"
#include "signorini/SimplexMesh.hpp"
#include "signorini/TpetraTypes.hpp"

namespace signorini {

class DistributedSpace {
 public:
  // Every rank passes the same mesh (generated or read before partitioning).
  DistributedSpace(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> mesh, int degree);

  const RCP<const Comm>& comm() const { return comm_; }
  const SimplexMesh& mesh() const { return *mesh_; }
  const LagrangeSpace& space() const { return *space_; }
  int dim() const { return mesh_->dim; }
  long long numGlobalNodes() const { return space_->numNodes(); }

  // Renumbered (Tpetra) node id of a node of space().
  GlobalOrdinal globalNode(long long spaceNode) const { return newId_[spaceNode]; }
  int nodeOwner(long long spaceNode) const { return nodeOwner_[spaceNode]; }
  bool ownsNode(long long spaceNode) const { return nodeOwner_[spaceNode] == comm_->getRank(); }

  const std::vector<long long>& localCells() const { return localCells_; }
  bool isLocalCell(long long cell) const { return cellPart_[cell] == comm_->getRank(); }

  // Nodes: owned, and owned followed by the ghosts of the local cells.
  const RCP<const Map>& ownedNodeMap() const { return ownedNodeMap_; }
  const RCP<const Map>& overlapNodeMap() const { return overlapNodeMap_; }
  // The same for the degrees of freedom.
  const RCP<const Map>& ownedDofMap() const { return ownedDofMap_; }
  const RCP<const Map>& overlapDofMap() const { return overlapDofMap_; }

  // Space node ids of the overlap nodes, in overlapNodeMap() order.
  const std::vector<long long>& overlapSpaceNodes() const { return overlapSpaceNodes_; }

 private:
  RCP<const Comm> comm_;
  std::shared_ptr<const SimplexMesh> mesh_;
  std::unique_ptr<LagrangeSpace> space_;
  std::vector<int> cellPart_, nodeOwner_;
  std::vector<GlobalOrdinal> newId_;
  std::vector<long long> localCells_, overlapSpaceNodes_;
  RCP<const Map> ownedNodeMap_, overlapNodeMap_, ownedDofMap_, overlapDofMap_;
};

}  // namespace signorini
