#pragma once
// Which rank holds which node of a QP read from files. The files' own order, cut into equal
// shares, is good for a code that numbers its nodes by position (a box, a mesh sorted along
// an axis) and poor for one that numbers them cell by cell; METIS' parts of Q's node graph
// are good for both. With QPPartition::Auto METIS' parts are used where they cut at most
// half the node couplings that the equal shares cut.
#include <vector>

#include "signorini/core/TpetraTypes.hpp"
#include "signorini/io/QPFiles.hpp"

namespace signorini::detail {

struct NodeDistribution {
  std::vector<int> owner;          // per global node, on every rank
  bool repartitioned = false;      // METIS' parts, not the equal shares in file order
  double fileOrderCut = 0;         // fraction of Q's node couplings across ranks, equal shares
  double chosenCut = 0;            // the same for `owner`
};

// Q's rows in the files' order, a contiguous block of whole nodes per rank in rank order
// (readQP's equal shares), dim unknowns per node. Collective; rank 0 gathers
// the node graph (its couplings, not its values) and partitions it.
NodeDistribution distributeNodes(const CrsMatrix& Q, int dim, QPPartition partition);

}  // namespace signorini::detail
