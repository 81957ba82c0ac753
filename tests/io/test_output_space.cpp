// The output directory's free space is checked before the solve against an estimate of the
// solution files: the estimate is checked against the files writeSolution writes (2D and 3D,
// P1 and P2), and a directory without room for it is refused with the figures.
#include "io/OutputSpace.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/io/SolutionOutput.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "support/TestProblems.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

// The bytes of the solution files in `directory`, read on rank 0 and sent to every rank.
double solutionFileBytes(const std::string& directory, const Comm& comm) {
  double bytes = 0;
  if (comm.getRank() == 0)
    for (const auto& entry : fs::directory_iterator(directory))
      if (entry.path().filename().string().rfind("solution", 0) == 0) bytes += static_cast<double>(entry.file_size());
  Teuchos::broadcast(comm, 0, 1, &bytes);
  return bytes;
}

TEST(OutputSpace, EstimateCoversTheSolutionFiles) {
  auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3})
    for (int degree : {1, 2}) {
      const std::string label = std::to_string(dim) + "D P" + std::to_string(degree);
      Teuchos::ParameterList problem = testing::contactBoxProblem(dim, dim == 2 ? 8 : 4);
      problem.set("element: degree", degree);
      const AssembledProblem q = buildProblem(problem, comm);
      const SolveResult r = InteriorPointSolver().solve(q.qp, q.multigrid);
      const std::string directory =
          (fs::temp_directory_path() / ("signorini-output-space-" + std::to_string(comm->getSize()))).string();
      if (comm->getRank() == 0) fs::remove_all(directory);
      writeSolution(q, r, {}, directory);
      comm->barrier();
      const double written = solutionFileBytes(directory, *comm);
      const double estimate = static_cast<double>(detail::estimatedSolutionBytes(*q.space));
      EXPECT_GE(estimate, written) << label;
      EXPECT_LE(estimate, 1.5 * written) << label;
    }
}

TEST(OutputSpace, ADirectoryWithoutRoomIsRefusedWithTheFigures) {
  auto comm = Tpetra::getDefaultComm();
  const std::string directory = fs::temp_directory_path().string();
  EXPECT_NO_THROW(detail::checkOutputSpace(directory, 1024, *comm));
  try {
    detail::checkOutputSpace(directory, std::uintmax_t(1) << 62, *comm);  // 4 EiB
    ADD_FAILURE() << "no file system here has 4 EiB free";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("MiB free; the solution files need about"), std::string::npos) << message;
    EXPECT_NE(message.find("Output/write solution"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace signorini
