#include "assembly/RefinedMeshPart.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "assembly/SortByKey.hpp"
#include "fe/LagrangeSpace.hpp"
#include "fe/MortonCode.hpp"

namespace signorini::detail {

std::vector<long long> coarseCellsAlongCurve(const SimplexMesh& mesh) {
  const int d = mesh.dim;
  double lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
  for (int c = 0; c < d; ++c) {
    lower[c] = upper[c] = mesh.numVertices() > 0 ? mesh.vertices[c] : 0.0;
    for (long long v = 0; v < mesh.numVertices(); ++v) {
      lower[c] = std::min(lower[c], mesh.vertices[d * v + c]);
      upper[c] = std::max(upper[c], mesh.vertices[d * v + c]);
    }
  }
  std::vector<std::pair<std::uint64_t, long long>> code(mesh.numCells());
  double x[3];
  for (long long cell = 0; cell < mesh.numCells(); ++cell) {
    std::fill(x, x + 3, 0.0);
    for (int v = 0; v <= d; ++v)
      for (int c = 0; c < d; ++c) x[c] += mesh.vertices[d * mesh.cells[(d + 1) * cell + v] + c] / (d + 1);
    code[cell] = {mortonCode(x, lower, upper, d), cell};
  }
  sortPairs(code);
  std::vector<long long> order(code.size());
  for (std::size_t i = 0; i < code.size(); ++i) order[i] = code[i].second;
  return order;
}

void orderCellsAlongCurve(SimplexMesh& mesh) {
  const int npc = mesh.dim + 1;
  const std::vector<long long> order = coarseCellsAlongCurve(mesh);
  std::vector<long long> cells;
  cells.reserve(mesh.cells.size());
  for (long long c : order) cells.insert(cells.end(), &mesh.cells[npc * c], &mesh.cells[npc * c] + npc);
  mesh.cells.swap(cells);
  if (!mesh.cellTags.empty()) {
    std::vector<int> tags(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) tags[i] = mesh.cellTags[order[i]];
    mesh.cellTags.swap(tags);
  }
}

void orderAlongCurve(SimplexMesh& mesh) {
  orderCellsAlongCurve(mesh);
  numberVerticesByCells(mesh);
}

std::vector<long long> numberVerticesByCells(SimplexMesh& mesh) {
  std::vector<long long> newVertex(mesh.numVertices(), -1);
  long long next = 0;
  for (long long& v : mesh.cells) {
    long long& id = newVertex[v];
    if (id < 0) id = next++;
    v = id;
  }
  for (long long& id : newVertex)
    if (id < 0) id = next++;  // in no cell
  std::vector<double> vertices(mesh.vertices.size());
  for (std::size_t v = 0; v < newVertex.size(); ++v)
    std::copy_n(&mesh.vertices[mesh.dim * v], mesh.dim, &vertices[mesh.dim * newVertex[v]]);
  mesh.vertices.swap(vertices);
  for (auto* ids : {&mesh.facets, &mesh.geometryFacets, &mesh.geometryEdges})
    for (long long& id : *ids) id = newVertex[id];
  return newVertex;
}

std::vector<long long> nodesByLocality(const LagrangeSpace& space, const std::vector<long long>& coarseOrder,
                                       long long perCoarse) {
  std::vector<long long> order;
  order.reserve(space.numNodes());
  std::vector<char> seen(space.numNodes(), 0);
  for (long long coarse : coarseOrder)
    for (long long cell = coarse * perCoarse; cell < (coarse + 1) * perCoarse; ++cell)
      for (int local = 0; local < space.nodesPerCell(); ++local) {
        const long long node = space.cellNodes(cell)[local];
        if (!seen[node]) {
          seen[node] = 1;
          order.push_back(node);
        }
      }
  return order;
}

LatticePoint nodePoint(const LatticeSimplex& corners, const std::array<int, 4>& index, int dim) {
  LatticePoint point{0, 0, 0, 0};
  for (int v = 0; v <= dim; ++v)
    for (int i = 0; i <= dim; ++i) point[i] += index[v] * corners[v][i];
  return point;
}

RefinedLevel refineLocally(const CoarseMeshLattice& lattice, const SimplexRefinement& refinement, int level,
                           bool withFacets) {
  const SimplexMesh& coarse = lattice.mesh();
  const int d = coarse.dim;
  const long long n = 1LL << level;
  const auto& templateCells = refinement.cells(level);
  RefinedLevel result;
  SimplexMesh& mesh = result.mesh;
  mesh.dim = d;
  mesh.boundaryTags = coarse.boundaryTags;
  mesh.bodyTags = coarse.bodyTags;

  // The ids of every coarse cell's lattice points; the vertices are their distinct values.
  const auto& points = refinement.points(level);
  const long long perCell = static_cast<long long>(points.size());
  std::vector<long long> pointIds(coarse.numCells() * perCell);
  for (long long c = 0; c < coarse.numCells(); ++c)
    for (long long p = 0; p < perCell; ++p) pointIds[c * perCell + p] = lattice.pointId(c, points[p], n);
  // The vertices: the distinct ids, ascending, each first met in the coarse cell of lowest
  // index; one sort of (id, position) numbers them all.
  std::vector<long long>& ids = result.vertexIds;
  std::vector<std::pair<long long, std::size_t>> byId(pointIds.size());
  for (std::size_t k = 0; k < pointIds.size(); ++k) byId[k] = {pointIds[k], k};
  sortPairs(byId);
  for (const auto& [id, at] : byId) {
    if (ids.empty() || ids.back() != id) {
      ids.push_back(id);
      result.vertexCells.push_back(static_cast<long long>(at) / perCell);
      result.vertexPoints.push_back(points[at % perCell]);
    }
    pointIds[at] = static_cast<long long>(ids.size()) - 1;
  }
  std::vector<std::pair<long long, std::size_t>>().swap(byId);
  mesh.vertices.resize(d * ids.size());
  for (std::size_t v = 0; v < ids.size(); ++v)
    lattice.pointCoordinates(result.vertexCells[v], result.vertexPoints[v], n, &mesh.vertices[d * v]);
  mesh.cells.reserve(coarse.numCells() * templateCells.size() * (d + 1));
  for (long long c = 0; c < coarse.numCells(); ++c)
    for (const std::array<int, 4>& cell : refinement.cellPoints(level))
      for (int v = 0; v <= d; ++v) mesh.cells.push_back(pointIds[c * perCell + cell[v]]);
  if (!coarse.cellTags.empty()) {  // children are in their parent's body
    mesh.cellTags.resize(coarse.numCells() * templateCells.size());
    for (long long c = 0; c < coarse.numCells(); ++c)
      std::fill_n(mesh.cellTags.begin() + c * templateCells.size(), templateCells.size(), coarse.cellTags[c]);
  }
  const auto localVertex = [&](long long id) { return std::lower_bound(ids.begin(), ids.end(), id) - ids.begin(); };
  if (!withFacets) return result;

  // A boundary facet's refinement: the (d-1)-simplex's, its vertices those of its cell
  // without the one opposite it.
  const LagrangeSpace coarseSpace(coarse, 1);
  const SimplexRefinement facetRefinement(d - 1, level);
  for (long long f = 0; f < coarse.numFacets(); ++f) {
    const auto [c, opposite] = coarseSpace.facetCell(f);
    int corner[3];
    for (int v = 0, i = 0; v <= d; ++v)
      if (v != opposite) corner[i++] = v;
    for (const LatticeSimplex& piece : facetRefinement.cells(level)) {
      for (int v = 0; v < d; ++v) {
        LatticePoint point{0, 0, 0, 0};
        for (int i = 0; i < d; ++i) point[corner[i]] = piece[v][i];
        mesh.facets.push_back(localVertex(lattice.pointId(c, point, n)));
      }
      mesh.facetTags.push_back(coarse.facetTags[f]);
    }
  }
  return result;
}

PartWithSpace makeRefinedMeshPart(const CoarseMeshLattice& lattice, const SimplexRefinement& refinement, int degree,
                                  RefinedLevel& finest) {
  const int levels = refinement.levels();
  PartWithSpace result;
  MeshPart& part = result.part;
  part.mesh.dim = finest.mesh.dim;
  part.mesh.vertices = finest.mesh.vertices;
  part.mesh.cells = std::move(finest.mesh.cells);
  part.mesh.facets = std::move(finest.mesh.facets);
  // The lattice numbering puts a cell's vertices in the distant ranges of the coarse vertices,
  // edges, faces and cells; the loops over cells (assembly) read the data of their nodes.
  const std::vector<long long> partVertex = numberVerticesByCells(part.mesh);
  finest.partVertexIds.resize(partVertex.size());
  for (std::size_t v = 0; v < partVertex.size(); ++v) finest.partVertexIds[partVertex[v]] = finest.vertexIds[v];
  part.mesh.facetTags = std::move(finest.mesh.facetTags);
  part.mesh.boundaryTags = finest.mesh.boundaryTags;
  part.mesh.cellTags = std::move(finest.mesh.cellTags);
  part.mesh.bodyTags = finest.mesh.bodyTags;
  const long long perCoarse = static_cast<long long>(refinement.cells(levels).size());
  part.globalCells.resize(lattice.mesh().numCells() * perCoarse);
  for (long long c = 0; c < lattice.mesh().numCells(); ++c)
    for (long long t = 0; t < perCoarse; ++t)
      part.globalCells[c * perCoarse + t] = lattice.globalCell(c) * perCoarse + t;
  result.numGlobalCells = lattice.numGlobalCells() * perCoarse;

  result.mesh = std::make_shared<const SimplexMesh>(std::move(part.mesh));
  result.space = std::make_unique<LagrangeSpace>(*result.mesh, degree);
  const LagrangeSpace& space = *result.space;
  const long long numNodes = space.numNodes(), n = degree * (1LL << levels);
  std::vector<GlobalOrdinal> keys(numNodes);
  part.nodeOwners.resize(numNodes);
  const std::vector<int>& tags = lattice.boundaryTags();
  std::vector<std::vector<long long>> tagNodes(tags.size());
  std::vector<char> seen(numNodes, 0);
  const int d = result.mesh->dim;
  forEachCellNode(space, refinement, [&](long long node, long long, long long coarseCell, const LatticeSimplex& corners,
                                         const std::array<int, 4>& index) {
    if (seen[node]) return;
    seen[node] = 1;
    const LatticePoint point = nodePoint(corners, index, d);
    keys[node] = lattice.pointId(coarseCell, point, n);
    part.nodeOwners[node] = lattice.pointOwner(coarseCell, point);
    for (std::size_t t = 0; t < tags.size(); ++t)
      if (lattice.onBoundary(coarseCell, point, tags[t])) tagNodes[t].push_back(node);
  });
  long long numGlobalNodes = 0;
  part.nodeIds = ownerOrderedIds(lattice.comm(), keys, part.nodeOwners, numGlobalNodes,
                                 nodesByLocality(space, coarseCellsAlongCurve(lattice.mesh()), perCoarse));
  result.numGlobalNodes = numGlobalNodes;

  part.boundaryTags = tags;
  part.boundaryStart.push_back(0);
  for (std::vector<long long>& nodes : tagNodes) {
    std::sort(nodes.begin(), nodes.end());
    part.boundaryNodes.insert(part.boundaryNodes.end(), nodes.begin(), nodes.end());
    part.boundaryStart.push_back(static_cast<long long>(part.boundaryNodes.size()));
  }
  return result;
}

}  // namespace signorini::detail
