#include "assembly/BoxMeshPart.hpp"

#include <array>

namespace signorini::detail {
namespace {

using Point = std::array<long long, 3>;

// Every node's point on the lattice of spacing h/k, h the box size: a vertex (i,j,l) is
// k (i,j,l), a node with barycentric lattice indices a_v is sum_v a_v (vertex v).
std::vector<Point> latticePoints(const LagrangeSpace& space, const BoxBlock& block) {
  const SimplexMesh& mesh = space.mesh();
  const int dim = mesh.dim, k = space.degree(), npc = space.nodesPerCell();
  const long long count[3] = {block.end[0] - block.begin[0] + 1, block.end[1] - block.begin[1] + 1,
                              block.end[2] - block.begin[2] + 1};
  std::vector<Point> point(space.numNodes(), Point{0, 0, 0});
  for (long long v = 0; v < mesh.numVertices(); ++v) {
    long long rest = v;
    for (int axis = 0; axis < dim; ++axis) {
      point[v][axis] = k * (block.begin[axis] + rest % count[axis]);
      rest /= count[axis];
    }
  }
  const auto& lattice = space.basis().latticeIndices();
  for (long long cell = 0; cell < mesh.numCells(); ++cell) {
    const long long* nodes = space.cellNodes(cell);
    for (int local = dim + 1; local < npc; ++local) {
      Point& x = point[nodes[local]];
      x = Point{0, 0, 0};
      for (int v = 0; v <= dim; ++v)
        for (int axis = 0; axis < dim; ++axis) x[axis] += lattice[local][v] * point[nodes[v]][axis] / k;
    }
  }
  return point;
}

}  // namespace

PartWithSpace makeBoxMeshPart(const RCP<const Comm>& comm, const BoxGrid& box, const BoxDecomposition& blocks,
                              int degree) {
  const int rank = comm->getRank(), dim = box.dim;
  const BoxBlock block = blocks.block(rank);
  PartWithSpace result;
  MeshPart& part = result.part;
  result.mesh = std::make_shared<const SimplexMesh>(makeBoxMesh(dim, box.cells, box.lengths, block));
  part.globalCells = boxBlockCells(dim, box.cells, block);
  result.space = std::make_unique<LagrangeSpace>(*result.mesh, degree);
  const LagrangeSpace& space = *result.space;
  const long long numNodes = space.numNodes();

  // Lattice points, their keys (the point's index on the whole lattice) and owners.
  const std::vector<Point> point = latticePoints(space, block);
  const long long side[3] = {degree * box.cells[0] + 1, degree * box.cells[1] + 1, 0};
  std::vector<GlobalOrdinal> key(numNodes);
  part.nodeOwners.resize(numNodes);
  for (long long n = 0; n < numNodes; ++n) {
    key[n] = point[n][0] + side[0] * (point[n][1] + side[1] * point[n][2]);
    part.nodeOwners[n] = blocks.lowestBlockHolding(point[n], degree);
  }
  part.nodeIds = ownerOrderedIds(comm, key, part.nodeOwners, result.numGlobalNodes);

  // Boundary nodes by their lattice point: tag 2a + 1 is the plane x_a = 0, 2a + 2 is x_a = L_a.
  part.boundaryStart.push_back(0);
  for (int axis = 0; axis < dim; ++axis)
    for (int sideOfBox = 0; sideOfBox < 2; ++sideOfBox) {
      const long long plane = sideOfBox == 0 ? 0 : degree * box.cells[axis];
      part.boundaryTags.push_back(2 * axis + sideOfBox + 1);
      for (long long n = 0; n < numNodes; ++n)
        if (point[n][axis] == plane) part.boundaryNodes.push_back(n);
      part.boundaryStart.push_back(static_cast<long long>(part.boundaryNodes.size()));
    }
  result.numGlobalCells = simplicesPerBox(dim) * box.cells[0] * box.cells[1] * (dim == 3 ? box.cells[2] : 1);
  return result;
}

}  // namespace signorini::detail
