#pragma once
// Whether the output directory can hold the solution files, checked before the solve: a run
// should not end, after hours, on a full disk.
#include <cstdint>
#include <string>

#include "signorini/assembly/FiniteElementSpace.hpp"
#include "signorini/core/TpetraTypes.hpp"

namespace signorini::detail {

// The bytes that writeSolution writes for `space`, every rank's piece and the index: the
// base64 of the points, cells and the solution's fields. Collective.
std::uintmax_t estimatedSolutionBytes(const FiniteElementSpace& space);

// Throws InputError (on every rank) if the file system of `directory` (which exists) has
// less free space than `bytes`, naming both and the ways out. Collective.
void checkOutputSpace(const std::string& directory, std::uintmax_t bytes, const Comm& comm);

}  // namespace signorini::detail
