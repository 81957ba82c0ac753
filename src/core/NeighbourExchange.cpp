#include "core/NeighbourExchange.hpp"

#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// The all-to-all of `sent`, sendCounts[r] values of T (MPI type `type`) for rank r, rank 0's
// first; `receiveStart` gets the start of each sender's block (size + 1 entries).
template <class T>
std::vector<T> exchangePackedValues(const Comm& comm, const std::vector<T>& sent, const std::vector<int>& sendCounts,
                                    MPI_Datatype type, std::vector<int>& receiveStart) {
  const int size = comm.getSize();
  if (static_cast<int>(sendCounts.size()) != size) throw Error("exchangeWithRanks: one block per rank expected");
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (mpi == nullptr) {  // a serial communicator: this rank is the only one
    receiveStart = {0, sendCounts[0]};
    return sent;
  }
  const MPI_Comm raw = *mpi->getRawMpiComm();
  std::vector<int> receiveCounts(size), sendStart(size + 1, 0);
  for (int r = 0; r < size; ++r) sendStart[r + 1] = sendStart[r] + sendCounts[r];
  receiveStart.assign(size + 1, 0);
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, raw);
  for (int r = 0; r < size; ++r) receiveStart[r + 1] = receiveStart[r] + receiveCounts[r];
  std::vector<T> received(receiveStart[size]);
  MPI_Alltoallv(sent.data(), sendCounts.data(), sendStart.data(), type, received.data(), receiveCounts.data(),
                receiveStart.data(), type, raw);
  return received;
}

// The same for one block per rank.
template <class T>
std::vector<T> exchangeBlocks(const Comm& comm, const std::vector<std::vector<T>>& toRank, MPI_Datatype type,
                              std::vector<int>& receiveStart) {
  std::vector<int> sendCounts;
  std::size_t total = 0;
  for (const std::vector<T>& block : toRank) {
    sendCounts.push_back(static_cast<int>(block.size()));
    total += block.size();
  }
  std::vector<T> sent;
  sent.reserve(total);
  for (const std::vector<T>& block : toRank) sent.insert(sent.end(), block.begin(), block.end());
  return exchangePackedValues(comm, sent, sendCounts, type, receiveStart);
}

}  // namespace

std::vector<double> exchangeWithRanks(const Comm& comm, const std::vector<std::vector<double>>& toRank) {
  std::vector<int> start;
  return exchangeBlocks(comm, toRank, MPI_DOUBLE, start);
}

std::vector<std::vector<long long>> exchangeWithRanks(const Comm& comm,
                                                      const std::vector<std::vector<long long>>& toRank) {
  std::vector<int> start;
  const std::vector<long long> received = exchangeBlocks(comm, toRank, MPI_LONG_LONG, start);
  std::vector<std::vector<long long>> fromRank(start.size() - 1);
  for (std::size_t r = 0; r + 1 < start.size(); ++r)
    fromRank[r].assign(received.begin() + start[r], received.begin() + start[r + 1]);
  return fromRank;
}

std::vector<long long> exchangeWithRanksJoined(const Comm& comm, const std::vector<std::vector<long long>>& toRank) {
  std::vector<int> start;
  return exchangeBlocks(comm, toRank, MPI_LONG_LONG, start);
}

std::vector<long long> exchangePacked(const Comm& comm, const std::vector<long long>& sent,
                                     const std::vector<int>& sendCounts) {
  std::vector<int> start;
  return exchangePackedValues(comm, sent, sendCounts, MPI_LONG_LONG, start);
}

}  // namespace signorini
