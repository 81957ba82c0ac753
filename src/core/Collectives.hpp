#pragma once
// Reductions over the ranks of a communicator, for the pattern "compute on this rank's
// entries, then combine": the same value on every rank. Each is collective.
#include <cstddef>

#include <Teuchos_CommHelpers.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

template <class T>
T sumOverRanks(const Comm& comm, T local) {
  T global = local;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 1, &local, &global);
  return global;
}

template <class T>
T minOverRanks(const Comm& comm, T local) {
  T global = local;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local, &global);
  return global;
}

template <class T>
T maxOverRanks(const Comm& comm, T local) {
  T global = local;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local, &global);
  return global;
}

// True on every rank if `local` is true on every rank.
inline bool onEveryRank(const Comm& comm, bool local) { return minOverRanks(comm, local ? 1 : 0) == 1; }

// sum over the ranks of sum_{i < localLength} term(i), i a local index.
template <class Term>
double sumOverEntries(const Comm& comm, std::size_t localLength, Term term) {
  double local = 0;
  for (std::size_t i = 0; i < localLength; ++i) local += term(i);
  return sumOverRanks(comm, local);
}

}  // namespace signorini
