#pragma once
// The vector-valued P_k space of a mesh partitioned over the ranks of a communicator.
// Nodes are renumbered so that each rank owns a contiguous range (rank order); degrees of
// freedom are dof = dim * node + component. Each rank holds only its cells, as a mesh of
// their own, and the P_k space on them; the nodes of those cells are its overlap (owned
// first, then ghosts). A general mesh is held once, by rank 0 alone: it builds the global
// space, partitions the cells with METIS and sends every rank its part. A box mesh is made
// by every rank for its own block of boxes, and a refined mesh by every rank refining its
// part of the coarse mesh, with no global fine mesh anywhere.
#include <cstddef>
#include <memory>
#include <vector>

#include "assembly/MeshPart.hpp"
#include "fe/SimplexRefinement.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/LagrangeSpace.hpp"
#include "fe/SimplexMesh.hpp"
#include "signorini/assembly/FiniteElementSpace.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini {
namespace detail {
class CoarseMeshLattice;
struct RefinedLevel;
}
struct MeshPieces;

class DistributedSpace final : public FiniteElementSpace {
 public:
  // Collective. Only rank 0's `globalMesh` is read; the other ranks may pass nullptr. Rank 0
  // lets go of the mesh once the parts are sent, so passing the only reference frees it.
  // Throws on every rank InputError for a missing or inconsistent mesh or a bad degree,
  // Error if the partition fails.
  DistributedSpace(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> globalMesh, int degree);

  // Collective. The space of makeBoxMesh(box.dim, box.cells, box.lengths), cut into one block
  // of boxes per rank (decomposeBox); when the box counts admit no such blocks, rank 0 makes
  // the global mesh and partitions it as above. Throws on every rank InputError for a bad
  // box or degree.
  DistributedSpace(const RCP<const Comm>& comm, const BoxGrid& box, int degree);

  // Collective. The space on `lattice`'s coarse mesh refined refinement.levels() times, each
  // rank refining its own coarse cells (RefinedMeshPart): no rank holds the fine mesh.
  // `finest` is this rank's finest level with its facets (refineLocally()): the space takes its
  // cells and facets.
  DistributedSpace(const detail::CoarseMeshLattice& lattice, const SimplexRefinement& refinement, int degree,
                   detail::RefinedLevel& finest);

  const RCP<const Comm>& comm() const override { return comm_; }
  // This rank's cells as a mesh (vertices and cells renumbered locally, in global order,
  // with the boundary facets of these cells) and the P_k space on it.
  const SimplexMesh& mesh() const { return *mesh_; }
  const LagrangeSpace& space() const { return *space_; }
  int dim() const override { return mesh_->dim; }
  int degree() const override { return space_->degree(); }
  long long numGlobalNodes() const override { return numGlobalNodes_; }
  long long numGlobalCells() const override { return numGlobalCells_; }
  std::size_t numOverlapNodes() const override { return overlapSpaceNodes_.size(); }
  void overlapNodeCoordinates(std::size_t i, double* x) const override;
  long long numLocalCells() const override { return mesh_->numCells(); }

  // Renumbered (Tpetra) node id of a node of space().
  GlobalOrdinal globalNode(long long spaceNode) const { return nodeId_[spaceNode]; }
  int nodeOwner(long long spaceNode) const { return nodeOwner_[spaceNode]; }
  bool ownsNode(long long spaceNode) const { return nodeOwner_[spaceNode] == comm_->getRank(); }

  // Id in the global mesh of a cell of mesh().
  long long globalCell(long long cell) const { return globalCells_[cell]; }

  // Sorted nodes of space() on the boundary with that tag of the global mesh (empty for an
  // unknown tag). Unlike space().boundaryNodes(tag) it includes nodes that lie on a facet of
  // another rank's cell. space().boundaryFacets(tag), in turn, lists each global facet on
  // exactly one rank: facet integrals summed over the ranks count every facet once.
  std::vector<long long> boundaryNodes(int tag) const;

  // Nodes: owned, and owned followed by the ghosts of the local cells.
  const RCP<const Map>& ownedNodeMap() const { return ownedNodeMap_; }
  const RCP<const Map>& overlapNodeMap() const { return overlapNodeMap_; }
  // The same for the degrees of freedom.
  const RCP<const Map>& ownedDofMap() const override { return ownedDofMap_; }
  const RCP<const Map>& overlapDofMap() const { return overlapDofMap_; }

  // Space node ids of the overlap nodes, in overlapNodeMap() order.
  const std::vector<long long>& overlapSpaceNodes() const { return overlapSpaceNodes_; }

  // What the serial phase cost rank 0: heap bytes of the global mesh, the global space and
  // the partition arrays (from their capacities; of a refined mesh, the coarse mesh and its
  // partition), the same on every rank; 0 without one.
  std::size_t serialPhaseBytes() const { return serialPhaseBytes_; }

 private:
  // Takes this rank's part: builds the space on it, the owned and overlap maps.
  void adopt(detail::MeshPart&& part, int degree);
  // The same for a part whose space was built on its mesh already (part.mesh is not read).
  void adopt(detail::MeshPart&& part, std::shared_ptr<const SimplexMesh> mesh, std::unique_ptr<LagrangeSpace> space);

  RCP<const Comm> comm_;
  std::shared_ptr<const SimplexMesh> mesh_;
  std::unique_ptr<LagrangeSpace> space_;
  long long numGlobalNodes_ = 0, numGlobalCells_ = 0;
  std::size_t serialPhaseBytes_ = 0;
  std::vector<int> nodeOwner_;
  std::vector<GlobalOrdinal> nodeId_;
  std::vector<long long> globalCells_, overlapSpaceNodes_;
  std::vector<int> boundaryTags_;  // boundary nodes per tag, CSR
  std::vector<long long> boundaryStart_, boundaryNodes_;
  RCP<const Map> ownedNodeMap_, overlapNodeMap_, ownedDofMap_, overlapDofMap_;
  // meshPieces(*this), found at its first call: the setup, the assembly and the grids ask.
  mutable std::shared_ptr<const MeshPieces> pieces_;
  friend const MeshPieces& meshPieces(const DistributedSpace& space);
};

// The DistributedSpace behind a space the library made (every FiniteElementSpace of
// buildProblem is one); throws Error for another.
const DistributedSpace& distributedSpace(const FiniteElementSpace& space);
std::shared_ptr<const DistributedSpace> distributedSpace(const std::shared_ptr<const FiniteElementSpace>& space);

}  // namespace signorini
