// The owner-ordered numbering of a part's nodes (ownerOrderedIds) on a chain of nodes cut
// between the ranks: rank r holds keys 100 r .. 100 r + 10, the last shared with rank r + 1,
// which owns it. Each owner numbers its nodes in the order it is given, after the ranks
// before it, and a rank that shares a node gets the owner's id for it.
#include <gtest/gtest.h>

#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "assembly/MeshPart.hpp"
#include "signorini/core/Error.hpp"

namespace {

using namespace signorini;

struct Chain {
  std::vector<GlobalOrdinal> keys;
  std::vector<int> owners;
};

// Rank r's part of the chain, its shared last node owned by rank r + 1 (the last rank owns all).
Chain chainPart(int rank, int size) {
  Chain part;
  for (int k = 0; k <= 10; ++k) {
    part.keys.push_back(100 * rank + (k == 10 ? 100 : k));
    part.owners.push_back(k == 10 && rank + 1 < size ? rank + 1 : rank);
  }
  return part;
}

TEST(MeshPart, OwnersNumberTheirNodesInTheGivenOrder) {
  auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const Chain part = chainPart(rank, size);
  std::vector<long long> reversed(part.keys.size());
  for (std::size_t i = 0; i < reversed.size(); ++i) reversed[i] = static_cast<long long>(reversed.size() - 1 - i);
  long long numGlobal = 0;
  const std::vector<GlobalOrdinal> ids = detail::ownerOrderedIds(comm, part.keys, part.owners, numGlobal, reversed);

  const long long ownedBefore = 10LL * rank;  // every rank but the last owns 10 nodes
  EXPECT_EQ(numGlobal, 10LL * size + 1);
  // Owned nodes, numbered backwards from the last owned one: node k has id before + owned - 1 - k
  // (the last rank owns its 11th node too).
  const int owned = rank + 1 < size ? 10 : 11;
  for (int k = 0; k < owned; ++k) EXPECT_EQ(ids[k], ownedBefore + owned - 1 - k) << "key " << part.keys[k];
  // The shared node is the next rank's node 0, the last one it numbers in reverse order.
  if (rank + 1 < size) {
    const int nextOwned = rank + 2 < size ? 10 : 11;
    EXPECT_EQ(ids[10], ownedBefore + 10 + nextOwned - 1);
  }
  // Every id once over the ranks: the owned ones are the ranges above.
  long long sum = 0;
  for (int k = 0; k < owned; ++k) sum += ids[k];
  long long total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &sum, &total);
  EXPECT_EQ(total, numGlobal * (numGlobal - 1) / 2);
}

TEST(MeshPart, RefusesANodeItsOwnerDoesNotHold) {
  auto comm = Tpetra::getDefaultComm();
  if (comm->getSize() < 2) GTEST_SKIP() << "needs a second rank";
  Chain part = chainPart(comm->getRank(), comm->getSize());
  if (comm->getRank() == 0) part.keys[10] = 999999;  // rank 1 holds no such key
  long long numGlobal = 0;
  EXPECT_THROW(detail::ownerOrderedIds(comm, part.keys, part.owners, numGlobal), Error);
}

}  // namespace
