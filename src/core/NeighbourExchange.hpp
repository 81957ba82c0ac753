#pragma once
// Sends each rank its own block of values and receives what every rank sent this one: the
// exchange of data between ranks that need each other's (an all-to-all with counts).
// Collective.
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// toRank[r]: the values for rank r (empty: none). Returns the values received, ordered by
// the sending rank.
std::vector<double> exchangeWithRanks(const Comm& comm, const std::vector<std::vector<double>>& toRank);

// The same for integers, received as one block per sending rank.
std::vector<std::vector<long long>> exchangeWithRanks(const Comm& comm,
                                                      const std::vector<std::vector<long long>>& toRank);

// The same for integers, received in one array ordered by the sending rank (no copy per block).
std::vector<long long> exchangeWithRanksJoined(const Comm& comm, const std::vector<std::vector<long long>>& toRank);

// The same for integers already in one array by destination rank: sendCounts[r] of them for
// rank r, rank 0's first. For the largest exchanges: the values are not copied into blocks.
std::vector<long long> exchangePacked(const Comm& comm, const std::vector<long long>& sent,
                                      const std::vector<int>& sendCounts);

}  // namespace signorini
