#pragma once
// Coarse grids for a mesh that has none of its own (a Gmsh mesh read as is, the coarse mesh
// of a refined one, a caller's SimplexGrid), so that the geometric multigrid has levels below
// its P1 grid as on box meshes.
//
// Each coarse grid's vertices are a maximal independent set of the finer grid's vertices (no
// two joined by an edge of the finer grid; every other vertex next to one of them), chosen
// by Luby's rule with priorities that put the domain's corners first, then its edges, its
// faces and its inside (BoundaryFeatures), and within each the order of a hash of the
// vertices' coordinates, so that the set does not depend on the rank count and the coarse
// grids keep the domain's shape. Their Delaunay triangulation, one per body, is the grid; every rank
// holds it whole (it has about an eighth of the finer grid's vertices in 3D, a quarter in 2D).
// The vertices are nested, the cells are not: the interpolation to a finer vertex is P1 in
// the coarse cell that holds it. A Delaunay triangulation covers the convex hull of a body's
// vertices, less the flat slivers on it (delaunayCells): where the body is not convex, coarse
// cells span its concave parts (the coarse space is then coarser there, never wrong: the
// coarse operators are Galerkin products), and
// finer vertices outside the hull (on a curved boundary) take the nearest cell's weights,
// clamped to [0, 1].
#include <memory>
#include <string>
#include <vector>

#include "signorini/core/GeometricGrid.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/solver/SimplexGrid.hpp"

namespace signorini {

// One rank's view of a grid's vertices and edges: the vertices of its cells, with their
// global ids (0 .. count - 1 over all ranks), whether it owns them (each vertex has one
// owner), coordinates, bodies, the dimension of the boundary feature each lies on, and the
// edges of its cells between them (CSR, both ways).
struct VertexGraph {
  int dim = 0;
  std::vector<long long> ids;
  std::vector<char> owned;
  std::vector<double> coordinates;  // dim per vertex
  std::vector<int> bodies;          // per vertex; empty: one body
  std::vector<signed char> features;  // per vertex (BoundaryFeatures); empty: not known, none kept first
  std::vector<long long> start, neighbours;

  // start and neighbours from cells (dim + 1 local vertex indices each).
  void setEdgesOfCells(const std::vector<long long>& cells);
  // The edges as above and the features of the mesh these cells are this rank's part of
  // (boundaryFeatureDimensions). Collective.
  void setEdgesAndFeaturesOfCells(const Comm& comm, const std::vector<long long>& cells);
};

class DelaunayCoarseGrid final : public GeometricGrid {
 public:
  // Collective. The coarse grids below the grid of `graph`, each the coarsening of the one
  // above, until one has at most `fewestVertices` vertices (a few hundred: the direct solver
  // takes them) or a coarsening keeps more than `keptAtMost` of the vertices; null if the
  // first would.
  static std::shared_ptr<const DelaunayCoarseGrid> hierarchyBelow(const RCP<const Comm>& comm,
                                                                  const VertexGraph& graph,
                                                                  long long fewestVertices = 300,
                                                                  double keptAtMost = 0.6);

  int dimension() const override { return dim_; }
  long long numVertices() const override { return static_cast<long long>(bodies_.size()); }
  void vertexCoordinates(long long vertex, double* x) const override;
  long long vertexAt(const double* x) const override { return vertexOfBodyAt(x, -1); }
  void interpolation(const double* x, long long* vertices, double* weights) const override {
    interpolationInBody(x, -1, vertices, weights);
  }
  long long vertexOfBodyAt(const double* x, int body) const override;
  void interpolationInBody(const double* x, int body, long long* vertices, double* weights) const override;
  std::shared_ptr<const GeometricGrid> coarser() const override { return coarser_; }
  std::string description() const override;

 private:
  // Every body's cells (dim + 1 vertex indices each): each body's vertices are a grid.
  DelaunayCoarseGrid(int dim, std::vector<double> coordinates, std::vector<int> bodies,
                     const std::vector<std::vector<long long>>& cellsOfBodies);
  // The coarsening of `graph`, whose vertices and edges are spread over `graphComm` (comm, or
  // one rank's own where every rank holds the whole grid), and the coarser grids below it.
  // Collective over comm.
  static std::shared_ptr<const DelaunayCoarseGrid> coarsen(const RCP<const Comm>& comm,
                                                           const RCP<const Comm>& graphComm, const VertexGraph& graph,
                                                           long long fewestVertices, double keptAtMost);

  int dim_;
  std::vector<double> coordinates_;  // dim_ per vertex
  std::vector<int> bodies_;          // per vertex
  std::vector<std::unique_ptr<SimplexGrid>> byBody_;  // null for a body with no cells
  std::shared_ptr<const DelaunayCoarseGrid> coarser_;
};

}  // namespace signorini
