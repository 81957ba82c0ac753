#pragma once
// The P1 grid of a distributed P_k space's own mesh (k > 1), or of that mesh refined at the
// nodes (each cell split into k^dim simplices on its nodes, every node a vertex): its
// vertices, numbered globally, and for each node of the space the cell that holds it and its
// P1 weights there. What the geometric multigrid needs for its P_k -> P1 step on a mesh with
// no coarser grids (a Gmsh mesh): below the P1 level it hands over to MueLu or a direct solve.
//
// A rank answers for the points of its own part: vertexAt() and interpolation() for the
// nodes of its cells (the multigrid asks about its owned nodes), vertexCoordinates() for the
// vertices among them. Bodies meshed apart (the mesh's connected pieces, numbered as
// MultigridInput::nodeBodies) may have nodes at one place: vertexOfBodyAt() and
// interpolationInBody() take the node of the body asked for.
#include <memory>
#include <string>
#include <vector>

#include "solver/DelaunayCoarseGrid.hpp"
#include "assembly/DistributedSpace.hpp"
#include "signorini/core/GeometricGrid.hpp"

namespace signorini {

class MeshVertexGrid : public GeometricGrid {
 public:
  enum class Refinement { none, atNodes };

  // Collective. Vertices are numbered in the order of their nodes' global ids, the owners'
  // ranges one after the other (refined at the nodes: a vertex's id is its node's). The grid
  // shares the space.
  explicit MeshVertexGrid(std::shared_ptr<const DistributedSpace> space, Refinement refinement = Refinement::none);

  int dimension() const override { return space_->dim(); }
  long long numVertices() const override { return numVertices_; }
  void vertexCoordinates(long long vertex, double* x) const override;
  long long vertexAt(const double* x) const override;
  // x must be a node of this rank's part (else Error): its cell's vertices and weights.
  void interpolation(const double* x, long long* vertices, double* weights) const override;
  long long vertexOfBodyAt(const double* x, int body) const override;
  void interpolationInBody(const double* x, int body, long long* vertices, double* weights) const override;
  std::shared_ptr<const GeometricGrid> coarser() const override { return coarser_; }
  bool refinesFineCells() const override { return refinement_ == Refinement::atNodes; }
  std::string description() const override;

  // The vertices of this rank's cells and the cells' edges between them (not refined at the
  // nodes): what DelaunayCoarseGrid coarsens.
  VertexGraph vertexGraph() const;
  // The next coarser grid, whose vertices are vertices of this one (DelaunayCoarseGrid).
  void setCoarser(std::shared_ptr<const GeometricGrid> coarser) { coarser_ = std::move(coarser); }

 private:
  // The local space node at x (of the body, if several have a node there), or -1.
  long long nodeAt(const double* x, int body = -1) const;

  // vertexId_ for the mesh's own vertices, and numVertices_.
  void numberMeshVertices();

  std::shared_ptr<const DistributedSpace> space_;
  Refinement refinement_;
  long long numVertices_ = 0;
  std::vector<long long> vertexId_;       // per local vertex: mesh vertex (= space node below
                                          // mesh().numVertices()), or space node when refined
  std::vector<long long> cellOfNode_;     // per local space node: a local cell that holds it (not refined)
  std::vector<long long> nodesByPlace_;   // local space nodes sorted by coordinates
  std::vector<long long> vertexById_;     // local vertices sorted by global id
  std::vector<int> bodyOfNode_;           // per local space node: its piece of the mesh
  std::shared_ptr<const GeometricGrid> coarser_;
};

}  // namespace signorini
