#include "assembly/CoarseMeshLattice.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <Teuchos_CommHelpers.hpp>

#include "assembly/GlobalPartition.hpp"
#include "assembly/RefinedMeshPart.hpp"
#include "assembly/SortByKey.hpp"
#include "assembly/SplitMeshPart.hpp"
#include "core/RootTask.hpp"
#include "fe/GmshMesh.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

// The padding of boundary entity keys past their vertices.
constexpr GlobalOrdinal kNone = std::numeric_limits<GlobalOrdinal>::max();

// The first `count` ids, sorted, padded with kNone.
std::array<GlobalOrdinal, 3> sortedKey(const long long* ids, int count) {
  std::array<GlobalOrdinal, 3> key{kNone, kNone, kNone};
  std::copy_n(ids, count, key.begin());
  std::sort(key.begin(), key.end());
  return key;
}

// Position of edge (i, j), i < j, among a d-simplex's edges (0,1), (0,2), .., (d-1,d).
int edgeIndex(int i, int j, int d) { return i * (2 * d + 1 - i) / 2 + j - i - 1; }

long long binomial(long long m, int k) {
  if (m < k) return 0;
  long long value = 1;
  for (int i = 1; i <= k; ++i) value = value * (m - k + i) / i;
  return value;
}

// Lexicographic rank of (x_1..x_k) among the k-tuples of integers >= 0 with sum <= m.
long long tupleRank(const long long* x, int k, long long m) {
  long long rank = 0, used = 0;
  for (int i = 0; i < k; ++i) {
    for (long long t = 0; t < x[i]; ++t) rank += binomial(m - used - t + (k - 1 - i), k - 1 - i);
    used += x[i];
  }
  return rank;
}

// Global ids and owners of the entities with `size` vertices (edges: 2, faces: 3) of every
// cell, entity e of cell c at [c * perCell + e]: entities numbered in order of their sorted
// vertex ids, owned by the lowest part among their cells.
struct Entities {
  std::vector<long long> ids;
  std::vector<int> owners;  // per entity
  long long count = 0;
};

Entities numberEntities(const SimplexMesh& mesh, const GlobalPartition& partition, int size) {
  const int d = mesh.dim;
  // The entities of one cell as subsets of its vertex positions: edges in edgeIndex() order,
  // faces by the vertex they leave out.
  std::vector<std::array<int, 3>> local;
  if (size == 2) {
    for (int i = 0; i <= d; ++i)
      for (int j = i + 1; j <= d; ++j) local.push_back({i, j, -1});
  } else {
    for (int f = 0; f <= d; ++f) {
      std::array<int, 3> face{};
      for (int v = 0, n = 0; v <= d; ++v)
        if (v != f) face[n++] = v;
      local.push_back(face);
    }
  }
  const long long numCells = mesh.numCells();
  const int perCell = static_cast<int>(local.size());
  std::vector<std::tuple<std::array<long long, 3>, long long>> all;  // (sorted vertices, cell entity)
  all.reserve(numCells * perCell);
  for (long long c = 0; c < numCells; ++c)
    for (int e = 0; e < perCell; ++e) {
      std::array<long long, 3> key{-1, -1, -1};
      for (int v = 0; v < size; ++v) key[v] = mesh.cells[(d + 1) * c + local[e][v]];
      std::sort(key.begin(), key.begin() + size);
      all.emplace_back(key, c * perCell + e);
    }
  sortByKey(all, [](const auto& entity) { return std::get<0>(entity)[0]; }, std::less<>());
  Entities result;
  result.ids.resize(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& [key, cellEntity] = all[i];
    if (i == 0 || std::get<0>(all[i - 1]) != key) {
      ++result.count;
      result.owners.push_back(partition.cellPart(cellEntity / perCell));
    }
    result.ids[cellEntity] = result.count - 1;
    result.owners.back() = std::min(result.owners.back(), partition.cellPart(cellEntity / perCell));
  }
  return result;
}

// The elements (`size` vertex ids each, with a label) with at least two vertices in the
// part, as renumbered vertex ids.
void addNear(const std::vector<long long>& elements, const std::vector<int>& labels, int size,
             const std::vector<char>& inPart, const GlobalPartition& partition, std::vector<long long>& nearElements,
             std::vector<int>& nearLabels) {
  for (std::size_t e = 0; e < labels.size(); ++e) {
    int near = 0;
    for (int v = 0; v < size; ++v) near += inPart[elements[size * e + v]];
    if (near < 2) continue;
    for (int v = 0; v < size; ++v) nearElements.push_back(partition.nodeId(elements[size * e + v]));
    nearLabels.push_back(labels[e]);
  }
}

// closestPointsOnGeometry() for every rank's points (`targets`: dimension and tag per point),
// computed by rank 0, which alone reads the file. Collective.
std::vector<double> closestPointsOnRoot(const Comm& comm, const std::string& path, const std::vector<int>& targets,
                                        const std::vector<double>& points) {
  const int rank = comm.getRank(), size = comm.getSize();
  std::vector<long long> counts(size);
  const long long count = static_cast<long long>(targets.size() / 2);
  Teuchos::gatherAll(comm, 1, &count, size, counts.data());
  std::vector<int> allTargets;
  std::vector<double> allPoints, placed;
  if (rank == 0) {
    for (int r = 0; r < size; ++r) {
      std::vector<int> t(2 * counts[r]);
      std::vector<double> x(3 * counts[r]);
      if (r == 0) {
        t = targets;
        x = points;
      } else if (counts[r] > 0) {
        Teuchos::receive(comm, r, static_cast<int>(t.size()), t.data());
        Teuchos::receive(comm, r, static_cast<int>(x.size()), x.data());
      }
      allTargets.insert(allTargets.end(), t.begin(), t.end());
      allPoints.insert(allPoints.end(), x.begin(), x.end());
    }
  } else if (count > 0) {
    Teuchos::send(comm, static_cast<int>(targets.size()), targets.data(), 0);
    Teuchos::send(comm, static_cast<int>(points.size()), points.data(), 0);
  }
  runOnRoot(comm, [&] {
    std::vector<int> dims, entities;
    for (std::size_t i = 0; i < allTargets.size(); i += 2) {
      dims.push_back(allTargets[i]);
      entities.push_back(allTargets[i + 1]);
    }
    placed = closestPointsOnGeometry(path, dims, entities, allPoints);
  });
  std::vector<double> mine(points.size());
  if (rank == 0) {
    std::copy_n(placed.begin(), mine.size(), mine.begin());
    long long at = 3 * counts[0];
    for (int r = 1; r < size; ++r) {
      if (counts[r] > 0) Teuchos::send(comm, static_cast<int>(3 * counts[r]), placed.data() + at, r);
      at += 3 * counts[r];
    }
  } else if (count > 0) {
    Teuchos::receive(comm, 0, static_cast<int>(mine.size()), mine.data());
  }
  return mine;
}

// Adds the lattice data of the mesh's entities to each part (rank 0); the edges and faces
// only where they are numbered.
void addEntities(const SimplexMesh& mesh, const GlobalPartition& partition, const Entities* edges,
                 const Entities* faces, std::vector<MeshPart>& parts) {
  const int d = mesh.dim, edgesPerCell = d * (d + 1) / 2;
  std::vector<char> inPart(mesh.numVertices());
  for (std::size_t r = 0; r < parts.size(); ++r) {
    MeshPart& part = parts[r];
    std::fill(inPart.begin(), inPart.end(), 0);
    for (long long c : part.globalCells) {
      for (int v = 0; v <= d; ++v) inPart[mesh.cells[(d + 1) * c + v]] = 1;
      if (edges)
        for (int e = 0; e < edgesPerCell; ++e) {
          const long long id = edges->ids[c * edgesPerCell + e];
          part.cellEdges.push_back(id);
          part.edgeOwners.push_back(edges->owners[id]);
        }
      if (faces)
        for (int f = 0; f <= d; ++f) {
          const long long id = faces->ids[c * (d + 1) + f];
          part.cellFaces.push_back(id);
          part.faceOwners.push_back(faces->owners[id]);
        }
    }
    addNear(mesh.facets, mesh.facetTags, d, inPart, partition, part.nearFacets, part.nearFacetTags);
    addNear(mesh.geometryFacets, mesh.geometryFacetEntities, d, inPart, partition, part.nearGeometryFacets,
            part.nearGeometryFacetEntities);
    addNear(mesh.geometryEdges, mesh.geometryEdgeEntities, 2, inPart, partition, part.nearGeometryEdges,
            part.nearGeometryEdgeEntities);
    part.entityCounts = {mesh.numVertices(), edges ? edges->count : 0, faces ? faces->count : 0, mesh.numCells()};
  }
}

// Each tetrahedron's vertices rotated (an even permutation: the orientation stays) so that
// Bey's rule cuts its inner octahedron along the shortest of the three diagonals, between
// the midpoints of edges 02 and 13; the later levels follow Bey's order from there.
SimplexMesh withShortestDiagonals(const SimplexMesh& mesh) {
  SimplexMesh result = mesh;
  if (mesh.dim != 3) return result;
  // The three pairings of opposite edges, and the even orders that put each on (02, 13).
  const int orders[3][4] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {3, 1, 0, 2}};
  const int pairs[3][4] = {{0, 2, 1, 3}, {0, 1, 2, 3}, {0, 3, 1, 2}};
  for (long long c = 0; c < mesh.numCells(); ++c) {
    const long long* v = &mesh.cells[4 * c];
    double best = 0.0;
    int choice = 0;
    for (int k = 0; k < 3; ++k) {
      double length = 0.0;  // |(x_a + x_b) - (x_c + x_d)|^2, four times the diagonal's squared length
      for (int x = 0; x < 3; ++x) {
        const double t = mesh.vertices[3 * v[pairs[k][0]] + x] + mesh.vertices[3 * v[pairs[k][1]] + x] -
                         mesh.vertices[3 * v[pairs[k][2]] + x] - mesh.vertices[3 * v[pairs[k][3]] + x];
        length += t * t;
      }
      if (k == 0 || length < best) {
        best = length;
        choice = k;
      }
    }
    for (int i = 0; i < 4; ++i) result.cells[4 * c + i] = v[orders[choice][i]];
  }
  return result;
}

}  // namespace

CoarseMeshLattice::CoarseMeshLattice(const RCP<const Comm>& comm, std::shared_ptr<const SimplexMesh> mesh,
                                     long long resolution)
    : comm_(comm) {
  const int size = comm_->getSize();
  std::vector<MeshPart> parts;
  long long serialBytes = 0;
  runOnRoot(*comm_, [&] {
    if (!mesh) throw InputError("coarse mesh: rank 0 has no mesh");
    SimplexMesh rotated = withShortestDiagonals(*mesh);
    mesh.reset();
    orderAlongCurve(rotated);
    mesh = std::make_shared<const SimplexMesh>(std::move(rotated));
    GlobalPartition partition(*mesh, 1, size);
    for (int r = 0; r < size; ++r) parts.push_back(partition.part(r));
    // Edges hold lattice points from resolution 2 on, faces (3D) from 3 on.
    Entities edges, faces;
    if (resolution >= 2) edges = numberEntities(*mesh, partition, 2);
    if (mesh->dim == 3 && resolution >= 3) faces = numberEntities(*mesh, partition, 3);
    addEntities(*mesh, partition, resolution >= 2 ? &edges : nullptr,
                mesh->dim == 3 && resolution >= 3 ? &faces : nullptr, parts);
    serialBytes = static_cast<long long>(mesh->bytes() + partition.bytes());
  });
  Teuchos::broadcast(*comm_, 0, 1, &serialBytes);
  serialPhaseBytes_ = static_cast<std::size_t>(serialBytes);
  if (comm_->getRank() == 0) {
    for (int r = 1; r < size; ++r) {
      sendMeshPart(*comm_, parts[r], r);
      parts[r] = MeshPart();
    }
    part_ = std::move(parts[0]);
  } else {
    part_ = receiveMeshPart(*comm_, 0);
  }
  mesh.reset();
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  indexNearEntities();
}

CoarseMeshLattice::CoarseMeshLattice(const RCP<const Comm>& comm, GmshMeshPart&& part, long long resolution)
    : comm_(comm) {
  part.mesh = withShortestDiagonals(part.mesh);
  orderCellsAlongCurve(part.mesh);
  part_ = latticePartOfSplitMesh(comm_, std::move(part), resolution);
  indexNearEntities();
}

void CoarseMeshLattice::indexNearEntities() {
  std::copy(part_.entityCounts.begin(), part_.entityCounts.end(), counts_);
  const int d = dim();
  positionsById_.resize(part_.mesh.numCells());
  for (long long cell = 0; cell < part_.mesh.numCells(); ++cell) {
    std::array<unsigned char, 4>& order = positionsById_[cell];
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.begin() + d + 1,
              [&](int i, int j) { return vertexId(cell, i) < vertexId(cell, j); });
  }
  for (std::size_t f = 0; f < part_.nearFacetTags.size(); ++f) {
    const EntityKey facet = sortedKey(&part_.nearFacets[d * f], d);
    boundaryEntities_[facet].push_back(part_.nearFacetTags[f]);
    if (d == 3)
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) boundaryEntities_[{facet[i], facet[j], kNone}].push_back(part_.nearFacetTags[f]);
  }
  for (std::size_t f = 0; f < part_.nearGeometryFacetEntities.size(); ++f) {
    const EntityKey facet = sortedKey(&part_.nearGeometryFacets[d * f], d);
    const int surface = part_.nearGeometryFacetEntities[f];
    facetEntity_[facet] = surface;
    if (d == 3)
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
          std::vector<int>& surfaces = edgeSurfaces_[{facet[i], facet[j], kNone}];
          if (std::find(surfaces.begin(), surfaces.end(), surface) == surfaces.end()) surfaces.push_back(surface);
        }
  }
  for (std::size_t e = 0; e < part_.nearGeometryEdgeEntities.size(); ++e)
    edgeCurve_[sortedKey(&part_.nearGeometryEdges[2 * e], 2)] = part_.nearGeometryEdgeEntities[e];
}

long long CoarseMeshLattice::numPoints(long long n) const {
  const long long inner = counts_[1] * (n - 1) + (dim() == 3 ? counts_[2] * binomial(n - 1, 2) + counts_[3] * binomial(n - 1, 3)
                                                             : counts_[3] * binomial(n - 1, 2));
  return counts_[0] + inner;
}

int CoarseMeshLattice::carrier(long long cell, const LatticePoint& a, int* positions) const {
  int count = 0;
  const std::array<unsigned char, 4>& order = positionsById_[cell];
  for (int i = 0; i <= dim(); ++i)
    if (a[order[i]] > 0) positions[count++] = order[i];
  return count;
}

long long CoarseMeshLattice::pointId(long long cell, const LatticePoint& a, long long n) const {
  const int d = dim();
  int at[4];
  const int count = carrier(cell, a, at);
  if (count == 1) return vertexId(cell, at[0]);
  // Inside the entity: the lattice indices past its lowest vertex, less one each.
  long long inner[3];
  for (int i = 1; i < count; ++i) inner[i - 1] = a[at[i]] - 1;
  const long long rank = tupleRank(inner, count - 1, n - count);
  long long base = counts_[0];
  if (count == 2) {
    const long long edge = part_.cellEdges[cell * d * (d + 1) / 2 + edgeIndex(std::min(at[0], at[1]), std::max(at[0], at[1]), d)];
    return base + edge * (n - 1) + rank;
  }
  base += counts_[1] * (n - 1);
  if (count == 3 && d == 3) {
    const int missing = 6 - at[0] - at[1] - at[2];
    return base + part_.cellFaces[cell * 4 + missing] * binomial(n - 1, 2) + rank;
  }
  if (d == 3) base += counts_[2] * binomial(n - 1, 2);
  return base + globalCell(cell) * binomial(n - 1, d) + rank;
}

int CoarseMeshLattice::pointOwner(long long cell, const LatticePoint& a) const {
  const int d = dim();
  int at[4];
  const int count = carrier(cell, a, at);
  if (count == 1) return part_.nodeOwners[part_.mesh.cells[(d + 1) * cell + at[0]]];
  if (count == 2)
    return part_.edgeOwners[cell * d * (d + 1) / 2 + edgeIndex(std::min(at[0], at[1]), std::max(at[0], at[1]), d)];
  if (count == 3 && d == 3) return part_.faceOwners[cell * 4 + (6 - at[0] - at[1] - at[2])];
  return comm_->getRank();
}

bool CoarseMeshLattice::onBoundary(long long cell, const LatticePoint& a, int tag) const {
  const int d = dim();
  int at[4];
  const int count = carrier(cell, a, at);
  if (count > d) return false;
  if (count == 1) {
    const auto it = std::lower_bound(part_.boundaryTags.begin(), part_.boundaryTags.end(), tag);
    if (it == part_.boundaryTags.end() || *it != tag) return false;
    const std::size_t i = it - part_.boundaryTags.begin();
    const long long vertex = part_.mesh.cells[(d + 1) * cell + at[0]];
    return std::binary_search(part_.boundaryNodes.begin() + part_.boundaryStart[i],
                              part_.boundaryNodes.begin() + part_.boundaryStart[i + 1], vertex);
  }
  const auto it = boundaryEntities_.find(entityKey(cell, at, count));
  return it != boundaryEntities_.end() && std::find(it->second.begin(), it->second.end(), tag) != it->second.end();
}

CoarseMeshLattice::EntityKey CoarseMeshLattice::entityKey(long long cell, const int* positions, int count) const {
  EntityKey key{kNone, kNone, kNone};
  for (int i = 0; i < count; ++i) key[i] = vertexId(cell, positions[i]);  // positions come sorted by id
  return key;
}

void CoarseMeshLattice::pointCoordinates(long long cell, const LatticePoint& a, long long n, double* x) const {
  const int d = dim();
  int at[4];
  const int count = carrier(cell, a, at);
  if (count >= 2 && count <= d && !placedIds_.empty() && placedResolution_ % n == 0) {
    LatticePoint scaled = a;
    for (int& entry : scaled) entry *= static_cast<int>(placedResolution_ / n);
    const long long id = pointId(cell, scaled, placedResolution_);
    const auto it = std::lower_bound(placedIds_.begin(), placedIds_.end(), id);
    if (it != placedIds_.end() && *it == id) {
      std::copy_n(&placedCoordinates_[d * (it - placedIds_.begin())], d, x);
      return;
    }
  }
  std::fill(x, x + d, 0.0);
  for (int i = 0; i < count; ++i) {
    const double weight = static_cast<double>(a[at[i]]) / static_cast<double>(n);
    const long long vertex = part_.mesh.cells[(d + 1) * cell + at[i]];
    for (int c = 0; c < d; ++c) x[c] += weight * part_.mesh.vertices[d * vertex + c];
  }
}

bool CoarseMeshLattice::geometryTarget(long long cell, const LatticePoint& a, int& entityDim, int& entity) const {
  const int d = dim();
  int at[4];
  const int count = carrier(cell, a, at);
  if (count < 2 || count > d) return false;
  const EntityKey key = entityKey(cell, at, count);
  if (count == d) {  // inside a facet
    const auto it = facetEntity_.find(key);
    if (it == facetEntity_.end()) return false;
    entityDim = d - 1;
    entity = it->second;
    return true;
  }
  // Inside an edge of a tetrahedron: on its curve, or on the one surface around it.
  if (const auto curve = edgeCurve_.find(key); curve != edgeCurve_.end()) {
    entityDim = 1;
    entity = curve->second;
    return true;
  }
  const auto surfaces = edgeSurfaces_.find(key);
  if (surfaces == edgeSurfaces_.end() || surfaces->second.size() != 1) return false;
  entityDim = 2;
  entity = surfaces->second[0];
  return true;
}

void CoarseMeshLattice::placeOnGeometry(const std::string& path, const SimplexRefinement& refinement) {
  const int d = dim();
  placedIds_.clear();
  placedCoordinates_.clear();
  const long long n = 1LL << refinement.levels();
  // The points to place, each once: (id, entity dimension, entity, straight coordinates).
  std::vector<std::tuple<long long, int, int, std::array<double, 3>>> points;
  for (long long c = 0; c < part_.mesh.numCells(); ++c)
    for (const LatticePoint& a : refinement.points(refinement.levels())) {
      int entityDim = 0, entity = 0;
      if (!geometryTarget(c, a, entityDim, entity)) continue;
      std::array<double, 3> x{0, 0, 0};
      pointCoordinates(c, a, n, x.data());
      points.emplace_back(pointId(c, a, n), entityDim, entity, x);
    }
  std::sort(points.begin(), points.end(), [](const auto& p, const auto& q) { return std::get<0>(p) < std::get<0>(q); });
  points.erase(std::unique(points.begin(), points.end(),
                           [](const auto& p, const auto& q) { return std::get<0>(p) == std::get<0>(q); }),
               points.end());
  std::vector<int> targets;  // dimension and tag per point
  std::vector<double> straight;
  for (const auto& [id, entityDim, entity, x] : points) {
    targets.insert(targets.end(), {entityDim, entity});
    straight.insert(straight.end(), x.begin(), x.end());
  }
  const std::vector<double> placed = closestPointsOnRoot(*comm_, path, targets, straight);
  placedResolution_ = n;
  for (std::size_t i = 0; i < points.size(); ++i) {
    placedIds_.push_back(std::get<0>(points[i]));
    placedCoordinates_.insert(placedCoordinates_.end(), &placed[3 * i], &placed[3 * i + d]);
  }
}

}  // namespace signorini::detail
