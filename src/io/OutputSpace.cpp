#include "io/OutputSpace.hpp"

#include <filesystem>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

#include "core/RootTask.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

// What writeSolution writes per point and per cell, in bytes before base64: the coordinates
// and the node fields (displacement padded to 3 components, pressure, force, gap, active);
// per cell its connectivity, offset and type and the cell fields (von Mises stress, rank).
constexpr double kPointBytes = 8.0 * (3 + 3 + 4);
double cellBytes(int dim, int degree) {
  int nodes = 1;
  for (int i = 1; i <= dim; ++i) nodes = nodes * (degree + i) / i;  // binomial(degree + dim, dim)
  return 8.0 * nodes + 8.0 + 1.0 + 8.0 * 2;
}
constexpr double kBase64 = 4.0 / 3.0;
constexpr double kPieceOverhead = 4096;  // XML around the arrays, the .pvtu index

}  // namespace

std::uintmax_t estimatedSolutionBytes(const FiniteElementSpace& space) {
  const double local = kBase64 * (kPointBytes * static_cast<double>(space.numOverlapNodes()) +
                                  cellBytes(space.dim(), space.degree()) * static_cast<double>(space.numLocalCells())) +
                       kPieceOverhead;
  double total = 0;
  Teuchos::reduceAll(*space.comm(), Teuchos::REDUCE_SUM, 1, &local, &total);
  return static_cast<std::uintmax_t>(total + kPieceOverhead);
}

void checkOutputSpace(const std::string& directory, std::uintmax_t bytes, const Comm& comm) {
  runOnRoot(comm, [&] {
    std::error_code error;
    const std::filesystem::space_info space = std::filesystem::space(directory, error);
    if (error || space.available >= bytes) return;  // a file system that cannot say is not refused
    std::ostringstream message;
    message.precision(3);
    message << "output directory \"" << directory << "\" has " << space.available / 1048576.0
            << " MiB free; the solution files need about " << bytes / 1048576.0
            << " MiB: free some space, choose another directory with --output or Output/directory, or set "
               "Output/write solution to false";
    throw InputError(message.str());
  });
}

}  // namespace signorini::detail
