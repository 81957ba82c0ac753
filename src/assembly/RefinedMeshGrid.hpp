#pragma once
// The geometric multigrid grids of a mesh refined uniformly on every rank (RefinedMeshPart):
// level l is the P1 grid of the coarse mesh refined l times, its vertices numbered by their
// coarse lattice points (CoarseMeshLattice::pointId). Its interpolation is the refinement's, not a search by coordinates:
// a point of the next finer level is a vertex of this one or the midpoint of one of its
// edges (weights 1/2), a node of the P_k space on the finest level has its cell's P1 weights.
// That is the exact embedding of the nested P1 spaces whatever the coordinates.
//
// A rank answers for the points of its own part: vertexAt() and interpolation() for the
// vertices of its next finer level (the finest grid: the nodes of its P_k space), given by
// their coordinates, vertexCoordinates() for its own vertices. The finest grid indexes the
// space's nodes at its first such question: a P1 space's multigrid starts at the grid below
// it and never asks, and the index would be the largest of all the levels'.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/CoarseMeshLattice.hpp"
#include "assembly/DistributedSpace.hpp"
#include "assembly/RefinedMeshPart.hpp"
#include "fe/SimplexRefinement.hpp"
#include "signorini/core/GeometricGrid.hpp"

namespace signorini {

class RefinedMeshGrid : public GeometricGrid {
 public:
  // Collective. The finest grid (level refinement.levels()) of `space`, which
  // makeRefinedMeshPart() made from `lattice` and `finest` (whose vertex data it reads), with
  // the coarser levels below it down to the coarse mesh; `delaunayBelow`: and below that the
  // Delaunay coarse grids of the coarse mesh's vertices (DelaunayCoarseGrid), so that a large
  // coarse mesh, which the direct solver does not take, need not be left to MueLu.
  // The finest grid keeps `space` for its answers and takes `finest`'s vertex ids and
  // coordinates.
  static std::shared_ptr<const RefinedMeshGrid> hierarchy(std::shared_ptr<const detail::CoarseMeshLattice> lattice,
                                                          const SimplexRefinement& refinement,
                                                          std::shared_ptr<const DistributedSpace> space,
                                                          detail::RefinedLevel finest, bool delaunayBelow);

  int dimension() const override { return dim_; }
  long long numVertices() const override { return numVertices_; }
  void vertexCoordinates(long long vertex, double* x) const override;
  long long vertexAt(const double* x) const override;
  // x must be a point this rank answers for (else Error).
  void interpolation(const double* x, long long* vertices, double* weights) const override;
  // Where bodies meshed apart have points at one place, the point of `body` (MeshPieces).
  long long vertexOfBodyAt(const double* x, int body) const override;
  void interpolationInBody(const double* x, int body, long long* vertices, double* weights) const override;
  std::shared_ptr<const GeometricGrid> coarser() const override { return coarser_; }
  std::string description() const override;

 private:
  struct Point;  // a point of the finer level: its cell's vertices here and their weights

  // Level `level` of `levels` with these vertices (ascending global ids) and coordinates.
  RefinedMeshGrid(const detail::CoarseMeshLattice& lattice, int level, int levels, std::vector<long long> vertexIds,
                  std::vector<double> coordinates);
  // The points to answer for: the vertices of the next finer level (`finerGrid`, refined as
  // `finer`), or the P_k space's nodes (the global id of each of its mesh's vertices given),
  // with their bodies (of each local coarse cell, or of each space node; empty: one body).
  void answerForLevel(const detail::CoarseMeshLattice& lattice, const SimplexRefinement& refinement,
                      const RefinedMeshGrid& finerGrid, const detail::RefinedLevel& finer,
                      const std::vector<int>& coarseCellBody);
  // Of the finest grid: the space's nodes are indexed by the first findPoint().
  void answerForSpaceWhenAsked(const SimplexRefinement& refinement, std::shared_ptr<const DistributedSpace> space,
                               std::vector<long long> vertexIds, std::vector<int> nodeBody);
  void answerForSpace() const;
  // Fills byPlace_ for points_.
  void indexPoints() const;
  // The point at x (of `body`, -1: any), or null.
  const Point* findPoint(const double* x, int body) const;
  const double* placeOf(std::size_t point) const { return pointCoordinates_->data() + dim_ * point; }
  // The vertex here at `point`, or -1.
  long long vertexOf(const Point& point) const;

  int dim_ = 0, level_ = 0, levels_ = 0;
  long long numVertices_ = 0;
  std::vector<long long> vertexIds_;  // this rank's vertices, ascending
  // dim_ per vertex; the next coarser grid's points are these vertices, and it shares them.
  std::shared_ptr<const std::vector<double>> coordinates_;
  mutable std::vector<Point> points_;
  // dim_ per point of points_: the finer grid's coordinates_, or the P_k space's nodes'.
  mutable std::shared_ptr<const std::vector<double>> pointCoordinates_;
  mutable int weightDenominator_ = 1;  // 2 between levels, k for the P_k space's nodes
  // (hash of a point's place, its index in points_), ascending: the table that finds a point
  // by its coordinates, radix-sorted by 8-byte keys rather than the points compared by theirs
  using PlaceEntry = std::pair<std::uint64_t, std::size_t>;
  mutable std::vector<PlaceEntry> byPlace_;
  // Of the finest grid until its first findPoint(): the refinement (a copy: a few hundred
  // template cells), the space whose nodes it answers for, the global id (here) of each vertex
  // of the space's mesh, and each node's body (empty: one body).
  struct SpaceToAnswerFor {
    SimplexRefinement refinement;
    std::shared_ptr<const DistributedSpace> space;
    std::vector<long long> vertexIds;
    std::vector<int> nodeBody;
  };
  mutable std::unique_ptr<SpaceToAnswerFor> spaceToAnswerFor_;
  std::shared_ptr<const GeometricGrid> coarser_;  // a RefinedMeshGrid but below the coarse mesh
};

}  // namespace signorini
