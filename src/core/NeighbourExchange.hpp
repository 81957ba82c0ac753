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

}  // namespace signorini
