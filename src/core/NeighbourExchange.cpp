#include "core/NeighbourExchange.hpp"

#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

std::vector<double> exchangeWithRanks(const Comm& comm, const std::vector<std::vector<double>>& toRank) {
  const int size = comm.getSize();
  if (static_cast<int>(toRank.size()) != size) throw Error("exchangeWithRanks: one block per rank expected");
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (mpi == nullptr) {  // a serial communicator: this rank is the only one
    return toRank[0];
  }
  const MPI_Comm raw = *mpi->getRawMpiComm();
  std::vector<int> sendCounts(size), receiveCounts(size), sendStart(size + 1, 0), receiveStart(size + 1, 0);
  std::vector<double> sent;
  for (int r = 0; r < size; ++r) {
    sendCounts[r] = static_cast<int>(toRank[r].size());
    sendStart[r + 1] = sendStart[r] + sendCounts[r];
    sent.insert(sent.end(), toRank[r].begin(), toRank[r].end());
  }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, raw);
  for (int r = 0; r < size; ++r) receiveStart[r + 1] = receiveStart[r] + receiveCounts[r];
  std::vector<double> received(receiveStart[size]);
  MPI_Alltoallv(sent.data(), sendCounts.data(), sendStart.data(), MPI_DOUBLE, received.data(), receiveCounts.data(),
                receiveStart.data(), MPI_DOUBLE, raw);
  return received;
}

}  // namespace signorini
