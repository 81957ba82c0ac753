#pragma once
// Global node numbering of the scalar continuous P_k space on a simplex mesh. The vector
// valued space used everywhere numbers its degrees of freedom dof = dim * node + component.
#include <cstddef>
#include <utility>
#include <vector>

#include "fe/LagrangeBasis.hpp"
#include "fe/SimplexMesh.hpp"

namespace signorini {

class LagrangeSpace {
 public:
  // Vertices come first with node id == vertex id; the other nodes follow in order of first
  // appearance in a loop over the cells. A node is identified by its lattice point written
  // as the sorted (global vertex id, a_i > 0) pairs, so neighbouring cells agree on shared
  // edge and face nodes whatever their local vertex order.
  // The space keeps a reference to the mesh, which must outlive it. Throws InputError for a
  // bad degree or an inconsistent mesh (vertex ids out of range, a boundary facet listed
  // twice, shared by two cells or no face of any cell).
  LagrangeSpace(const SimplexMesh& mesh, int degree);
  LagrangeSpace(SimplexMesh&&, int) = delete;  // would keep a reference to a temporary

  // A node past the vertices sits at sum_i a_i x_i / degree, summed in increasing vertex id:
  // any part of a mesh whose vertices keep the global order computes the same bits.
  // The space of a part of a larger mesh, whose nodes past the vertices take the given
  // coordinates (dim each, in node order) instead of computing them. Throws InputError if
  // the count does not fit.
  LagrangeSpace(const SimplexMesh& mesh, int degree, const std::vector<double>& nonVertexCoordinates);
  LagrangeSpace(SimplexMesh&&, int, const std::vector<double>&) = delete;

  const SimplexMesh& mesh() const { return *mesh_; }
  int degree() const { return basis_.degree(); }
  int dim() const { return basis_.dim(); }
  const LagrangeBasis& basis() const { return basis_; }
  long long numNodes() const { return numNodes_; }
  int nodesPerCell() const { return basis_.size(); }

  // nodesPerCell() global node ids of a cell, in the basis' local order.
  const long long* cellNodes(long long cell) const {
    // P1 nodes are the vertices: share the mesh's array instead of copying it.
    return (basis_.degree() == 1 ? mesh_->cells.data() : cellNodes_.data()) + nodesPerCell() * cell;
  }

  // dim * numNodes(); P1 nodes are the vertices: the mesh's array, not a copy.
  const std::vector<double>& nodeCoordinates() const {
    return basis_.degree() == 1 ? mesh_->vertices : nodeCoordinates_;
  }

  // Sorted node ids of all lattice nodes of the boundary facets with that tag.
  std::vector<long long> boundaryNodes(int tag) const;

  // Boundary facets with that tag, in mesh facet order, each as (cell, local facet f), f
  // being the cell's local vertex opposite the facet.
  std::vector<std::pair<long long, int>> boundaryFacets(int tag) const;

  // (cell, local facet f) of mesh boundary facet `facet`: every facet is a face of exactly one cell.
  const std::pair<long long, int>& facetCell(long long facet) const { return facetCells_[facet]; }

  // Heap bytes held by the space's own arrays (their capacities; not the mesh's).
  std::size_t bytes() const;

 private:
  void build(const std::vector<double>* nonVertexCoordinates);

  const SimplexMesh* mesh_;
  LagrangeBasis basis_;
  long long numNodes_ = 0;
  std::vector<long long> cellNodes_;  // nodesPerCell() per cell; empty for P1
  std::vector<double> nodeCoordinates_;  // empty for P1
  std::vector<std::pair<long long, int>> facetCells_;  // (cell, local facet) of each mesh facet
};

}  // namespace signorini
