#pragma once
// Private to the library: one rank's cells of a coarse mesh that every rank refines on its
// own, and the global numbering of the coarse mesh's barycentric lattice points that makes
// the refined levels one distributed mesh without any rank holding it.
//
// The lattice points of resolution n are the points sum a_i v_i / n of the cells (a_i >= 0
// integers summing to n): the vertices of the mesh refined l times are those of resolution
// 2^l, and the nodes of its P_k space those of resolution k 2^l. A point lies in the inside
// of one coarse entity (its carrier: a vertex, edge, face or cell, the vertices with
// a_i > 0), and is numbered by it: vertices first, then each edge's n - 1 inner points, each
// face's, each cell's, in the entity's global order and, inside an entity, in an order fixed
// by its vertices' global ids, so that every rank holding the entity numbers it alike. Its
// owner is the entity's: the lowest rank among the cells around it, as for any node.
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/MeshPart.hpp"
#include "fe/GmshMesh.hpp"
#include "fe/SimplexRefinement.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

class CoarseMeshLattice {
 public:
  // Collective. Rank 0 renumbers its `mesh` along a Morton curve (orderAlongCurve), partitions
  // it (METIS; the other ranks pass nullptr) and sends each rank its cells with the numbers
  // and owners of their entities. Only points of resolution up to `resolution` can be asked
  // for: the entities that hold none are not numbered. Throws on every rank InputError for a
  // missing or inconsistent mesh, Error if the partition fails.
  CoarseMeshLattice(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> mesh, long long resolution);
  // Collective. Every rank passes its own part of a mesh read in parts (rank r part r); the
  // ranks number the entities together (latticePartOfSplitMesh), and none holds the mesh.
  // Each part's cells are put along a Morton curve (orderCellsAlongCurve). Resolution as above.
  CoarseMeshLattice(const RCP<const Comm>& comm, GmshMeshPart&& part, long long resolution);

  const RCP<const Comm>& comm() const { return comm_; }
  int dim() const { return part_.mesh.dim; }
  // This rank's coarse cells (vertices in global order, its boundary facets), and their ids.
  const SimplexMesh& mesh() const { return part_.mesh; }
  long long globalCell(long long cell) const { return part_.globalCells[cell]; }
  long long numGlobalCells() const { return counts_[3]; }
  // What the serial phase cost rank 0: heap bytes of the coarse mesh and its partition, the
  // same on every rank (0 for a mesh read in parts).
  std::size_t serialPhaseBytes() const { return serialPhaseBytes_; }

  // Global number of lattice points of resolution n.
  long long numPoints(long long n) const;
  // Global id (0 .. numPoints(n) - 1) of the point a (sum n) of local cell `cell`.
  long long pointId(long long cell, const LatticePoint& a, long long n) const;
  // The rank that owns it.
  int pointOwner(long long cell, const LatticePoint& a) const;
  // Whether it lies on the global boundary with that tag (on one of its facets).
  bool onBoundary(long long cell, const LatticePoint& a, int tag) const;
  // The tags of all boundaries of the global mesh, ascending.
  const std::vector<int>& boundaryTags() const { return part_.boundaryTags; }
  // Its coordinates, sum a_i x_i / n summed in increasing vertex id: the same bits in every
  // cell that holds it, and for the same point at every resolution; for a point placed on
  // the geometry (placeOnGeometry()), that place.
  void pointCoordinates(long long cell, const LatticePoint& a, long long n, double* x) const;

  // Places the points of resolution 2^refinement.levels() (and so those of every coarser
  // one) that lie inside a coarse facet or edge on the boundary of the .geo geometry at
  // `path` onto it: the closest point of its surface, or of its curve for an edge on one
  // (Gmsh's projection; the mesh read must carry SimplexMesh::geometryFacets, which leave
  // out planes and straight lines: points there stay where they are, as do those on an edge
  // between two surfaces that is no geometry curve). Rank 0 loads the geometry and places
  // every rank's points, if any rank has some. Collective.
  void placeOnGeometry(const std::string& path, const SimplexRefinement& refinement);

 private:
  // Indexes part_'s boundary and geometry entities and orders each cell's vertices by global
  // id (both constructors end here).
  void indexNearEntities();
  // The carrier's local vertices (cell vertex positions), sorted by global vertex id.
  int carrier(long long cell, const LatticePoint& a, int* positions) const;
  // The geometry entity (dimension, tag) a point inside a coarse boundary facet or edge goes
  // onto; false for any other point.
  bool geometryTarget(long long cell, const LatticePoint& a, int& entityDim, int& entity) const;
  using EntityKey = std::array<GlobalOrdinal, 3>;  // sorted vertex ids, padded with the largest id
  EntityKey entityKey(long long cell, const int* positions, int count) const;

  GlobalOrdinal vertexId(long long cell, int position) const {
    return part_.nodeIds[part_.mesh.cells[(dim() + 1) * cell + position]];
  }

  RCP<const Comm> comm_;
  MeshPart part_;
  long long counts_[4] = {0, 0, 0, 0};  // vertices, edges, faces (3D), cells
  std::size_t serialPhaseBytes_ = 0;
  // Of each cell, its vertex positions in increasing global id: carrier() is asked for every
  // lattice point of every cell, so the cell's order is found once.
  std::vector<std::array<unsigned char, 4>> positionsById_;
  // Sorted global vertex ids of every boundary facet near this part, and of each of their
  // edges, with the facet's tag.
  std::map<EntityKey, std::vector<int>> boundaryEntities_;
  // Geometry entities: of each boundary facet near this part, of each edge on a geometry
  // curve (3D), and the surfaces of the facets around each edge (3D).
  std::map<EntityKey, int> facetEntity_, edgeCurve_;
  std::map<EntityKey, std::vector<int>> edgeSurfaces_;
  // The placed points (placeOnGeometry()): ids at resolution placedResolution_, ascending,
  // and their coordinates.
  long long placedResolution_ = 0;
  std::vector<long long> placedIds_;
  std::vector<double> placedCoordinates_;
};

}  // namespace signorini::detail
