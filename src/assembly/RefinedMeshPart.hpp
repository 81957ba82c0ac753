#pragma once
// Private to the library: the levels of a mesh refined uniformly on every rank, each rank
// refining its own coarse cells (CoarseMeshLattice) with no rank holding a fine mesh. The
// vertices of level l are the coarse lattice points of resolution 2^l, the nodes of the P_k
// space on the finest level those of resolution k 2^levels: their ids and owners come from
// the coarse entities, and the fine nodes are renumbered owner by owner as for any mesh.
#include <array>
#include <vector>

#include "assembly/CoarseMeshLattice.hpp"
#include "assembly/MeshPart.hpp"
#include "fe/LagrangeSpace.hpp"
#include "fe/SimplexRefinement.hpp"

namespace signorini::detail {

// This rank's coarse cells refined `level` times.
struct RefinedLevel {
  // Vertices in increasing global id, cells coarse cell by coarse cell in the order of
  // refinement.cells(level), positively oriented.
  SimplexMesh mesh;
  std::vector<long long> vertexIds;  // global id (CoarseMeshLattice::pointId, resolution 2^level) per vertex
  std::vector<LatticePoint> vertexPoints;  // a lattice point of each vertex ...
  std::vector<long long> vertexCells;      // ... in this coarse cell
  // Once makeRefinedMeshPart() made the part of this level: the global id of each of the
  // part's vertices, which come in another order.
  std::vector<long long> partVertexIds;
};

// `withFacets`: refine this rank's boundary facets of the coarse mesh too, with their tags.
RefinedLevel refineLocally(const CoarseMeshLattice& lattice, const SimplexRefinement& refinement, int level,
                           bool withFacets);

// The part of the P_k space on level refinement.levels(), whose refinement `finest` is (made
// with its facets): the part's mesh takes its cells and facets, its vertices in order of first
// appearance over the cells, `finest` keeps its vertex data for the multigrid's grids and
// learns the part's vertex ids. Collective.
PartWithSpace makeRefinedMeshPart(const CoarseMeshLattice& lattice, const SimplexRefinement& refinement, int degree,
                                  RefinedLevel& finest);

// The coarse cells in the order of their centroids along a Morton (Z-order) curve: a Gmsh
// mesh's cells come in the mesher's order, which scatters neighbours in memory.
std::vector<long long> coarseCellsAlongCurve(const SimplexMesh& mesh);

// Puts `mesh`'s cells (and their tags) in coarseCellsAlongCurve() order, in place: the loops
// over cells then visit neighbours one after another.
void orderCellsAlongCurve(SimplexMesh& mesh);

// orderCellsAlongCurve() and the vertices in order of first appearance in the cells, the
// facets and geometry entities renumbered to match. The global numbers of a partitioned mesh,
// and so each part's arrays and matrix rows, inherit this order: a mesher's would scatter a
// cell's neighbours in memory.
void orderAlongCurve(SimplexMesh& mesh);

// The vertices in order of first appearance in the cells (those in none last), the cells,
// facets and geometry entities renumbered to match, in place. Returns the new number of
// each old vertex.
std::vector<long long> numberVerticesByCells(SimplexMesh& mesh);

// The space's nodes in order of first appearance over its cells, coarse cell by coarse cell
// in `coarseOrder` (each coarse cell's `perCoarse` fine cells are consecutive): a global
// numbering in this order keeps a cell's nodes near in memory.
std::vector<long long> nodesByLocality(const LagrangeSpace& space, const std::vector<long long>& coarseOrder,
                                       long long perCoarse);

// The lattice point, resolution k 2^levels, of the P_k node with lattice index `index`
// (LagrangeBasis) in the finest cell with those corners.
LatticePoint nodePoint(const LatticeSimplex& corners, const std::array<int, 4>& index, int dim);

// Calls visit(node, cell, coarse cell, corners, index) for every (cell, local node) of a P_k
// space on the finest level built from makeRefinedMeshPart()'s part: a node once per cell,
// the cell's corners (lattice points of the finest level) and the node's lattice index in it.
template <class Space, class Visit>
void forEachCellNode(const Space& space, const SimplexRefinement& refinement, Visit&& visit) {
  const auto& templateCells = refinement.cells(refinement.levels());
  const long long perCoarse = static_cast<long long>(templateCells.size());
  const auto& lattice = space.basis().latticeIndices();
  for (long long cell = 0; cell < space.mesh().numCells(); ++cell) {
    const long long* nodes = space.cellNodes(cell);
    for (int local = 0; local < space.nodesPerCell(); ++local)
      visit(nodes[local], cell, cell / perCoarse, templateCells[cell % perCoarse], lattice[local]);
  }
}

}  // namespace signorini::detail
