#pragma once
/// \file
/// A GeometricGrid made from any simplex mesh a caller has: the P1 grid of its triangles or
/// tetrahedra, for the geometric multigrid's P_k -> P1 step on a QP assembled by another
/// finite element code (MultigridInput::grid), or the finest grid of a P1 QP. Below it come
/// coarse grids made of its own vertices (CoarseGrids::delaunay), as below a Gmsh mesh read as
/// is, or MueLu's algebraic levels (CoarseGrids::none).
#include <memory>
#include <string>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/core/GeometricGrid.hpp"

namespace signorini {

class SimplexGrid : public GeometricGrid {
 public:
  /// Collective. Each rank gives the cells it holds: `cells` has dim + 1 vertex ids per cell
  /// (any global ids, the same on every rank for the same vertex), `vertexIds` the distinct
  /// vertices of these cells and `coordinates` theirs (dim per vertex, in vertexIds' order).
  /// The cells of a rank must hold the nodes of the QP's rows it owns (the cells it assembled).
  /// Throws InputError for a dimension other than 2 or 3, arrays of sizes that do not fit, a
  /// cell naming a vertex not in vertexIds, or a degenerate cell.
  /// With `outside` Outside::nearestCell, a point in none of the cells is first moved onto the
  /// nearest of them (GeometricGrid::interpolation) instead of being an error: for cells that
  /// cover the nodes only up to the boundary's curvature, a coarser grid of the mesh's.
  enum class Outside { error, nearestCell };
  /// With CoarseGrids::delaunay the coarse grids below this one are the Delaunay
  /// triangulations of maximal independent sets of its vertices that keep the domain's
  /// corners and take its edges and faces first (found from the cells of all ranks together,
  /// a cell held by several ranks counting once), level by level, down to a
  /// few hundred vertices: the same grids on any rank count, each a geometric multigrid level
  /// (doc/algorithms.md). Their first level is as coarse as the mesh's own when the ranks'
  /// cells together are all of its cells (the edges they leave out join vertices that may then
  /// both be kept). With CoarseGrids::none there are none, and MueLu coarsens below it.
  enum class CoarseGrids { none, delaunay };
  SimplexGrid(const RCP<const Comm>& comm, int dim, std::vector<long long> vertexIds, std::vector<double> coordinates,
              std::vector<long long> cells, Outside outside = Outside::error,
              CoarseGrids coarseGrids = CoarseGrids::delaunay);
  ~SimplexGrid() override;

  int dimension() const override { return dim_; }
  /// The number of distinct vertices over all ranks.
  long long numVertices() const override { return numVertices_; }
  /// For a vertex of this rank's cells.
  void vertexCoordinates(long long vertex, double* x) const override;
  /// The vertex within 1e-10 of the local cell size of x, among this rank's, or -1.
  long long vertexAt(const double* x) const override;
  /// x in one of this rank's cells (within 1e-10 of its size): that cell's vertices and P1
  /// weights. Throws Error for a point in none, unless the grid moves such points onto its
  /// nearest cell (Outside::nearestCell).
  void interpolation(const double* x, long long* vertices, double* weights) const override;
  std::shared_ptr<const GeometricGrid> coarser() const override { return coarser_; }
  std::string description() const override;

 private:
  struct Buckets;
  // The cell whose smallest barycentric coordinate at x is largest, among the cells whose
  // bounding box holds x (nearest = 0) or the `nearest` cells with the nearest boxes; -1 if
  // there are none. Its weights in `lambda`.
  long long bestCell(const double* x, std::size_t nearest, double* lambda) const;

  int dim_;
  Outside outside_;
  long long numVertices_ = 0;
  std::vector<long long> vertexIds_;  // sorted
  std::vector<double> coordinates_;   // dim_ per vertex, in vertexIds_ order
  std::vector<long long> cells_;      // dim_ + 1 local vertex indices per cell
  std::unique_ptr<Buckets> buckets_;  // cells and vertices by place (R-trees)
  std::shared_ptr<const GeometricGrid> coarser_;
};

}  // namespace signorini
