#pragma once
// A lower bound on the memory a solve needs, checked before the mesh and the matrices are
// made: a problem that cannot fit stops with the numbers, not with std::bad_alloc.
#include <array>
#include <string>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// Bytes a solve with `unknowns` unknowns of P_degree elements in `dim` dimensions needs at
// least, with the stiffness assembled or not (`assembledStiffness` false: a matrix-free P2/P3
// stiffness on a box mesh, of which no matrix is stored): about four fifths of what whole
// solves of the benchmark family keep per unknown beyond the ranks' fixed memory
// (bench/results/reference-solve.json, matrix-free-solve.json). With `refinedGrid` (P2/P3,
// Problem/stiffness: P1 grid = refined at nodes) the multigrid's P1 level has as many
// unknowns again, its stiffness and hierarchy at least what a P1 solve keeps.
double minimumSolveBytes(double unknowns, int dim, int degree, bool assembledStiffness, bool refinedGrid = false);

// The unknowns of the P_degree space on a box mesh with these cells per direction (an upper
// bound in 3D for P2/P3, whose cube centres carry no node), as a double: it may not fit an
// integer type for absurd inputs.
double boxMeshUnknowns(int dim, const std::array<long long, 3>& cells, int degree);

// Throws an InputError on every rank if minimumSolveBytes, shared evenly by the ranks, is
// more than some machine has available for the ranks it runs (MemAvailable in
// /proc/meminfo); does nothing where that is unknown. Collective.
void checkMemoryFits(double unknowns, int dim, int degree, bool assembledStiffness, bool refinedGrid,
                     const Comm& comm);

}  // namespace signorini
