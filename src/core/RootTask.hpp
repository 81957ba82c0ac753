#pragma once
// Private to the library: work only rank 0 does (reading or generating the global mesh, the
// serial partition), or every rank does on its own, with its errors thrown on every rank so
// that no rank waits forever.
#include <functional>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

// Runs `task` on rank 0 only. If it throws, every rank throws the same kind of error with
// rank 0's message: InputError stays InputError, anything else (Error, bad_alloc...) becomes
// Error. Collective over comm.
void runOnRoot(const Comm& comm, const std::function<void()>& task);

// Runs `task` on every rank (each on its own data, e.g. its own part of a mesh). If it throws
// on any rank, every rank throws the error of the lowest such rank, as runOnRoot does.
// Collective over comm.
void runOnEveryRank(const Comm& comm, const std::function<void()>& task);

}  // namespace signorini::detail
