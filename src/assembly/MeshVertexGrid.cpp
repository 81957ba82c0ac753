#include "assembly/MeshVertexGrid.hpp"

#include <algorithm>
#include <numeric>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/MeshPieces.hpp"
#include "fe/ElasticityElement.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {

MeshVertexGrid::MeshVertexGrid(std::shared_ptr<const DistributedSpace> space, Refinement refinement)
    : space_(std::move(space)), refinement_(refinement) {
  const DistributedSpace& ds = *space_;
  const LagrangeSpace& lspace = ds.space();
  const int dim = ds.dim();
  const long long numNodes = lspace.numNodes();
  if (refinement_ == Refinement::atNodes) {
    numVertices_ = ds.numGlobalNodes();
    vertexId_.resize(numNodes);
    for (long long node = 0; node < numNodes; ++node) vertexId_[node] = ds.globalNode(node);
  } else {
    numberMeshVertices();
    cellOfNode_.assign(numNodes, -1);
    for (long long c = 0; c < ds.mesh().numCells(); ++c)
      for (int a = 0; a < lspace.nodesPerCell(); ++a) cellOfNode_[lspace.cellNodes(c)[a]] = c;
  }

  const double* xyz = lspace.nodeCoordinates().data();
  nodesByPlace_.resize(numNodes);
  std::iota(nodesByPlace_.begin(), nodesByPlace_.end(), 0LL);
  std::sort(nodesByPlace_.begin(), nodesByPlace_.end(), [&](long long a, long long b) {
    return std::lexicographical_compare(xyz + dim * a, xyz + dim * (a + 1), xyz + dim * b, xyz + dim * (b + 1));
  });
  bodyOfNode_ = meshPieces(ds).ofSpaceNode;
  vertexById_.resize(vertexId_.size());
  std::iota(vertexById_.begin(), vertexById_.end(), 0LL);
  std::sort(vertexById_.begin(), vertexById_.end(), [&](long long a, long long b) { return vertexId_[a] < vertexId_[b]; });
}

// Each owner numbers its vertices in the order of their node ids, after the vertices of the
// ranks before it; the ghosts learn theirs through the node maps.
void MeshVertexGrid::numberMeshVertices() {
  const DistributedSpace& ds = *space_;
  const long long numLocalVertices = ds.mesh().numVertices();
  std::vector<long long> owned;
  for (long long v = 0; v < numLocalVertices; ++v)
    if (ds.ownsNode(v)) owned.push_back(v);
  std::sort(owned.begin(), owned.end(), [&](long long a, long long b) { return ds.globalNode(a) < ds.globalNode(b); });
  const long long count = static_cast<long long>(owned.size());
  long long upTo = 0;
  Teuchos::scan(*ds.comm(), Teuchos::REDUCE_SUM, 1, &count, &upTo);
  Teuchos::reduceAll(*ds.comm(), Teuchos::REDUCE_SUM, 1, &count, &numVertices_);
  Vector ownedIds(ds.ownedNodeMap()), overlapIds(ds.overlapNodeMap());  // id + 1, exact in a double
  {
    auto data = ownedIds.getDataNonConst();
    for (long long k = 0; k < count; ++k)
      data[ds.ownedNodeMap()->getLocalElement(ds.globalNode(owned[k]))] = static_cast<double>(upTo - count + k + 1);
  }
  overlapIds.doImport(ownedIds, Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node>(ds.ownedNodeMap(), ds.overlapNodeMap()),
                      Tpetra::INSERT);
  vertexId_.assign(numLocalVertices, -1);
  auto data = overlapIds.getData();
  const auto& spaceNodes = ds.overlapSpaceNodes();
  for (std::size_t i = 0; i < spaceNodes.size(); ++i)
    if (spaceNodes[i] < numLocalVertices) vertexId_[spaceNodes[i]] = static_cast<long long>(data[i]) - 1;
  if (std::find(vertexId_.begin(), vertexId_.end(), -1) != vertexId_.end())
    throw Error("MeshVertexGrid: a vertex of the local cells has no owner's id");
}

long long MeshVertexGrid::nodeAt(const double* x, int body) const {
  const int dim = dimension();
  const double* xyz = space_->space().nodeCoordinates().data();
  auto at = std::lower_bound(nodesByPlace_.begin(), nodesByPlace_.end(), x, [&](long long node, const double* p) {
    return std::lexicographical_compare(xyz + dim * node, xyz + dim * (node + 1), p, p + dim);
  });
  for (; at != nodesByPlace_.end() && std::equal(x, x + dim, xyz + dim * *at); ++at)
    if (body < 0 || bodyOfNode_[*at] == body) return *at;
  return -1;
}

VertexGraph MeshVertexGrid::vertexGraph() const {
  if (refinement_ == Refinement::atNodes) throw Error("MeshVertexGrid: no vertex graph of a grid refined at the nodes");
  const DistributedSpace& ds = *space_;
  const SimplexMesh& mesh = ds.mesh();
  const int dim = ds.dim();
  const long long count = mesh.numVertices();
  VertexGraph g;
  g.dim = dim;
  g.ids = vertexId_;
  g.owned.resize(count);
  for (long long v = 0; v < count; ++v) g.owned[v] = ds.ownsNode(v);
  const auto& xyz = ds.space().nodeCoordinates();
  g.coordinates.assign(xyz.begin(), xyz.begin() + dim * count);
  g.bodies.assign(bodyOfNode_.begin(), bodyOfNode_.begin() + count);
  g.setEdgesAndFeaturesOfCells(*ds.comm(), mesh.cells);
  return g;
}

long long MeshVertexGrid::vertexAt(const double* x) const { return vertexOfBodyAt(x, -1); }

long long MeshVertexGrid::vertexOfBodyAt(const double* x, int body) const {
  const long long node = nodeAt(x, body);
  return node >= 0 && node < static_cast<long long>(vertexId_.size()) ? vertexId_[node] : -1;
}

void MeshVertexGrid::vertexCoordinates(long long vertex, double* x) const {
  const auto at = std::lower_bound(vertexById_.begin(), vertexById_.end(), vertex,
                                   [&](long long v, long long id) { return vertexId_[v] < id; });
  if (at == vertexById_.end() || vertexId_[*at] != vertex)
    throw Error("MeshVertexGrid: vertex " + std::to_string(vertex) + " is not in this rank's part of the mesh");
  const int dim = dimension();
  std::copy_n(&space_->space().nodeCoordinates()[dim * *at], dim, x);
}

void MeshVertexGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  interpolationInBody(x, -1, vertices, weights);
}

void MeshVertexGrid::interpolationInBody(const double* x, int body, long long* vertices, double* weights) const {
  const long long node = nodeAt(x, body);
  if (node < 0) throw Error("MeshVertexGrid: interpolation at a point that is not a node of this rank's part");
  const int dim = dimension();
  if (refinement_ == Refinement::atNodes) {  // every node is a vertex
    std::fill_n(vertices, dim + 1, vertexId_[node]);
    std::fill_n(weights, dim + 1, 0.0);
    weights[0] = 1.0;
    return;
  }
  const long long cell = cellOfNode_[node];
  double coords[12], Jinv[9];
  space_->mesh().cellVertexCoordinates(cell, coords);
  inverseJacobian(dim, coords, Jinv);
  // The reference coordinates of x are the P1 weights of vertices 1 .. dim.
  double sum = 0.0;
  for (int s = 0; s < dim; ++s) {
    weights[s + 1] = 0.0;
    for (int c = 0; c < dim; ++c) weights[s + 1] += Jinv[s * dim + c] * (x[c] - coords[c]);
    sum += weights[s + 1];
  }
  weights[0] = 1.0 - sum;
  const long long* nodes = space_->space().cellNodes(cell);  // its vertices first
  for (int k = 0; k <= dim; ++k) {
    vertices[k] = vertexId_[nodes[k]];
    weights[k] = std::max(weights[k], 0.0);  // round-off below 0 at nodes on the cell's boundary
  }
}

std::string MeshVertexGrid::description() const {
  if (refinement_ == Refinement::atNodes)
    return "P1 grid of the mesh refined at its " + std::to_string(numVertices_) + " nodes";
  return "P1 grid of the mesh's " + std::to_string(numVertices_) + " vertices";
}

}  // namespace signorini
