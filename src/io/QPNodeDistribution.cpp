#include "io/QPNodeDistribution.hpp"

#include <metis.h>

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "core/RootTask.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

using Edge = std::pair<long long, long long>;

// This rank's couplings between distinct nodes, each once with the lower node first.
std::vector<Edge> localEdges(const CrsMatrix& Q, int dim) {
  std::vector<Edge> edges;
  const Map& rows = *Q.getRowMap();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(rows.getNodeNumElements()); ++i) {
    CrsMatrix::local_inds_host_view_type columns;
    CrsMatrix::values_host_view_type values;
    Q.getLocalRowView(i, columns, values);
    const long long node = rows.getGlobalElement(i) / dim;
    for (std::size_t k = 0; k < columns.extent(0); ++k) {
      const long long other = Q.getColMap()->getGlobalElement(columns(k)) / dim;
      if (other != node) edges.emplace_back(std::min(node, other), std::max(node, other));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// All ranks' edges on rank 0 (each once), nothing elsewhere.
std::vector<Edge> gatheredEdges(const Comm& comm, std::vector<Edge> edges) {
  std::vector<long long> flat;
  for (const Edge& e : edges) flat.insert(flat.end(), {e.first, e.second});
  long long count = static_cast<long long>(flat.size());
  if (comm.getRank() != 0) {
    Teuchos::send(comm, 1, &count, 0);
    if (count > 0) Teuchos::send(comm, static_cast<int>(count), flat.data(), 0);
    return {};
  }
  for (int rank = 1; rank < comm.getSize(); ++rank) {
    Teuchos::receive(comm, rank, 1, &count);
    std::vector<long long> block(count);
    if (count > 0) Teuchos::receive(comm, rank, static_cast<int>(count), block.data());
    for (long long k = 0; k < count; k += 2) edges.emplace_back(block[k], block[k + 1]);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

double cutFraction(const std::vector<Edge>& edges, const std::vector<int>& owner) {
  if (edges.empty()) return 0.0;
  long long cut = 0;
  for (const Edge& e : edges) cut += owner[e.first] != owner[e.second] ? 1 : 0;
  return static_cast<double>(cut) / static_cast<double>(edges.size());
}

// METIS' k-way parts of the graph with these edges.
std::vector<int> metisParts(const std::vector<Edge>& edges, long long numNodes, int parts) {
  if (numNodes > std::numeric_limits<idx_t>::max() || 2 * static_cast<long long>(edges.size()) > std::numeric_limits<idx_t>::max())
    throw Error("QP partition: graph too large for METIS' " + std::to_string(8 * sizeof(idx_t)) + "-bit indices");
  std::vector<idx_t> degree(numNodes + 1, 0);
  for (const Edge& e : edges) ++degree[e.first + 1], ++degree[e.second + 1];
  for (long long v = 0; v < numNodes; ++v) degree[v + 1] += degree[v];
  std::vector<idx_t> adjacency(degree.back()), next(degree.begin(), degree.end() - 1);
  for (const Edge& e : edges) {
    adjacency[next[e.first]++] = static_cast<idx_t>(e.second);
    adjacency[next[e.second]++] = static_cast<idx_t>(e.first);
  }
  idx_t n = static_cast<idx_t>(numNodes), constraints = 1, nparts = parts, objective = 0;
  std::vector<idx_t> part(numNodes, 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  const int status = METIS_PartGraphKway(&n, &constraints, degree.data(), adjacency.data(), nullptr, nullptr, nullptr,
                                         &nparts, nullptr, nullptr, options, &objective, part.data());
  if (status != METIS_OK) throw Error("QP partition: METIS_PartGraphKway failed with status " + std::to_string(status));
  return std::vector<int>(part.begin(), part.end());
}

}  // namespace

NodeDistribution distributeNodes(const CrsMatrix& Q, int dim, QPPartition partition) {
  const Comm& comm = *Q.getComm();
  const int ranks = comm.getSize();
  const long long numNodes = static_cast<long long>(Q.getGlobalNumRows()) / dim;
  // The files' order as Q is read: each rank a contiguous block of nodes, in rank order.
  NodeDistribution result;
  result.owner.resize(numNodes);
  const int localNodes = static_cast<int>(Q.getRowMap()->getNodeNumElements() / dim);
  std::vector<int> nodesPerRank(ranks);
  Teuchos::gatherAll(comm, 1, &localNodes, ranks, nodesPerRank.data());
  for (int rank = 0, first = 0; rank < ranks; first += nodesPerRank[rank++])
    std::fill(result.owner.begin() + first, result.owner.begin() + first + nodesPerRank[rank], rank);
  if (ranks == 1 || partition == QPPartition::AsWritten) return result;
  const std::vector<Edge> edges = gatheredEdges(comm, localEdges(Q, dim));
  double cuts[3] = {0, 0, 0};  // equal shares, METIS, METIS chosen
  std::vector<int> parts;
  runOnRoot(comm, [&] {
    parts = metisParts(edges, numNodes, ranks);
    cuts[0] = cutFraction(edges, result.owner);
    cuts[1] = cutFraction(edges, parts);
    cuts[2] = partition == QPPartition::Metis || cuts[1] <= 0.5 * cuts[0] ? 1 : 0;
  });
  Teuchos::broadcast(comm, 0, 3, cuts);
  result.fileOrderCut = cuts[0];
  result.chosenCut = cuts[2] > 0 ? cuts[1] : cuts[0];
  if (cuts[2] == 0) return result;
  if (comm.getRank() != 0) parts.resize(numNodes);
  Teuchos::broadcast(comm, 0, static_cast<int>(numNodes), parts.data());
  result.owner = std::move(parts);
  result.repartitioned = true;
  return result;
}

}  // namespace signorini::detail
