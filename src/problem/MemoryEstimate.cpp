#include "problem/MemoryEstimate.hpp"

#include <mpi.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <Teuchos_DefaultMpiComm.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Lower bounds of the bytes per unknown, by dimension and degree, with Q assembled and with a
// matrix-free P2/P3 stiffness (P1 keeps Q assembled): about four fifths of the peak resident
// memory per unknown beyond the ranks' fixed memory that the largest members of the family
// reach (bench/results/matrix-free-solve*.json record it), so that a refusal is certain.
constexpr double kAssembledBytesPerUnknown[2][3] = {{650, 770, 830}, {1100, 1390, 1900}};
constexpr double kMatrixFreeBytesPerUnknown[2][3] = {{650, 610, 530}, {1100, 660, 460}};

// MemAvailable of this machine in bytes, 0 if unknown.
double availableBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kib = 0;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024.0;
  return 0.0;
}

// The ranks of `comm` on this machine.
int ranksOnThisMachine(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (!mpi) return 1;
  MPI_Comm local;
  MPI_Comm_split_type(*mpi->getRawMpiComm(), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  int size = 1;
  MPI_Comm_size(local, &size);
  MPI_Comm_free(&local);
  return size;
}

std::string bytesText(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (bytes >= 1024 && u < 6) {
    bytes /= 1024;
    ++u;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
  return text;
}

}  // namespace

double minimumSolveBytes(double unknowns, int dim, int degree, bool assembledStiffness, bool refinedGrid) {
  const auto& perUnknown = assembledStiffness ? kAssembledBytesPerUnknown : kMatrixFreeBytesPerUnknown;
  const double gridLevel = refinedGrid && degree > 1 ? kAssembledBytesPerUnknown[dim - 2][0] : 0.0;
  return unknowns * (perUnknown[dim - 2][degree - 1] + gridLevel);
}

double boxMeshUnknowns(int dim, const std::array<long long, 3>& cells, int degree) {
  double nodes = 1;
  for (int axis = 0; axis < dim; ++axis) nodes *= static_cast<double>(degree) * cells[axis] + 1;
  return dim * nodes;
}

void checkMemoryFits(double unknowns, int dim, int degree, bool assembledStiffness, bool refinedGrid,
                     const Comm& comm) {
  const double needed = minimumSolveBytes(unknowns, dim, degree, assembledStiffness, refinedGrid);
  const int ranks = ranksOnThisMachine(comm);
  const double available = availableBytes();
  const double local = available > 0 ? needed / comm.getSize() * ranks / available : 0.0;
  const double worst = maxOverRanks(comm, local);
  if (worst <= 1) return;
  char count[32];
  std::snprintf(count, sizeof count, "%.4g", unknowns);
  throw InputError("Problem: " + std::string(count) + " unknowns (P" + std::to_string(degree) + ", " +
                   std::to_string(dim) + "D) need at least " + bytesText(needed) + " for the solve, " +
                   bytesText(needed / comm.getSize()) + " on each of the " + std::to_string(comm.getSize()) +
                   " rank(s), more than the " + bytesText(needed / comm.getSize() * ranks / worst) +
                   " a machine has available for its " + std::to_string(ranks) +
                   " rank(s); use fewer cells (Problem/mesh: cells, mesh: size factor or mesh: refinements)" +
                   (refinedGrid && degree > 1 ? ", the mesh as the P1 grid (Problem/stiffness: P1 grid)" : "") +
                   " or more machines");
}

}  // namespace signorini
