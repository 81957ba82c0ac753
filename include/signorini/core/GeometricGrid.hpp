#pragma once
/// \file
/// What the geometric multigrid needs of a mesh: a P1 simplex grid whose vertices are nodes
/// of the fine space, which simplex holds a point and its P1 weights there, and the next
/// coarser grid. The problem layer fills it in (a box mesh's nested grids, or the vertices of
/// a P_k space's own mesh, or of that mesh refined at the nodes, with no coarser grid); the
/// solver sees no mesh. Library users whose meshes are nested refinements can implement it.
#include <memory>
#include <string>

namespace signorini {

class GeometricGrid {
 public:
  virtual ~GeometricGrid() = default;

  virtual int dimension() const = 0;
  virtual long long numVertices() const = 0;
  /// The coordinates (dimension() values) of a vertex, 0 <= vertex < numVertices().
  virtual void vertexCoordinates(long long vertex, double* x) const = 0;
  /// The vertex at x (to a tolerance far below the grid's spacing), or -1.
  virtual long long vertexAt(const double* x) const = 0;
  /// The dimension() + 1 vertices of a simplex that holds x (a point outside the grid is first
  /// moved onto it) and their P1 basis functions at x: weights >= 0 that sum to 1.
  virtual void interpolation(const double* x, long long* vertices, double* weights) const = 0;
  /// The same for a point of body `body` (MultigridInput::nodeBodies; -1: any) where bodies
  /// meshed apart have nodes at one place: the vertex, simplex and weights of that body. A
  /// grid of one body (or whose bodies share no place) need not override them.
  virtual long long vertexOfBodyAt(const double* x, int body) const {
    (void)body;
    return vertexAt(x);
  }
  virtual void interpolationInBody(const double* x, int body, long long* vertices, double* weights) const {
    (void)body;
    interpolation(x, vertices, weights);
  }
  /// The next coarser grid, whose vertices are vertices of this one, or null.
  virtual std::shared_ptr<const GeometricGrid> coarser() const = 0;
  /// Whether the grid splits the cells of a P_k fine space (k > 1) at its nodes (a
  /// low-order-refined mesh): its vertices are then all the fine nodes, and its P1 space is a
  /// level of its own below the fine one rather than the fine space itself.
  virtual bool refinesFineCells() const { return false; }
  /// For messages, e.g. "32 x 32 box grid".
  virtual std::string description() const = 0;
};

}  // namespace signorini
