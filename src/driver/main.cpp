// The signorini program: solves the contact problem an XML parameter list describes.
// Errors: one line on rank 0 (or on the rank that failed alone), a non-zero exit code on
// every rank, never a hang.
#include <chrono>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <mpi.h>

#include <Trilinos_version.h>
#include <Tpetra_Core.hpp>

#include "driver/Application.hpp"
#include "driver/CommandLine.hpp"
#include "driver/HugePages.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/Version.hpp"

namespace {

// The kinds of error and their exit statuses (documented in CommandLine::usage()).
struct ErrorKind {
  const char* name;
  int status;
};
constexpr ErrorKind kInputError{"error", 2}, kInternalError{"internal error", 3}, kOutputError{"output error", 4};

// Called by every rank that caught an error. If all ranks caught it (the usual case: input
// errors are detected on every rank), they leave together; if some rank is elsewhere, for
// instance waiting in a collective, the job is aborted instead of left hanging.
int leaveAfterError(const std::string& message, const ErrorKind& kind) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  int allArrived = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!allArrived && std::chrono::steady_clock::now() < deadline) {
    MPI_Test(&request, &allArrived, MPI_STATUS_IGNORE);
    if (!allArrived) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (allArrived) {
    if (rank == 0) std::cerr << "signorini: " << kind.name << ": " << message << std::endl;
    return kind.status;
  }
  std::cerr << "signorini: " << kind.name << " on rank " << rank << ": " << message << std::endl;
  MPI_Abort(MPI_COMM_WORLD, kind.status);
  return kind.status;
}

}  // namespace

int main(int argc, char** argv) {
  signorini::detail::restartWithHugePages(argv);
  // Kokkos prints its own options when it sees --help: it gets the arguments without it.
  std::vector<char*> args;
  bool help = false;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i > 0 && (arg == "--help" || arg == "-h"))
      help = true;
    else
      args.push_back(argv[i]);
  }
  int count = static_cast<int>(args.size());
  args.push_back(nullptr);
  char** remaining = args.data();
  Tpetra::ScopeGuard tpetra(&count, &remaining);
  auto comm = Tpetra::getDefaultComm();
  try {
    if (help) {
      if (comm->getRank() == 0) std::cout << signorini::CommandLine::usage();
      return 0;
    }
    const signorini::CommandLine cl = signorini::CommandLine::parse(count, remaining);
    if (cl.version || cl.defaults) {
      if (comm->getRank() == 0) {
        if (cl.version)
          std::cout << "signorini " << signorini::kVersion << " (" << signorini::gitCommit() << "), Trilinos "
                    << TRILINOS_VERSION_STRING << "\n";
        if (cl.defaults) std::cout << signorini::defaultsXml(cl.allDefaults);
      }
      return 0;
    }
    const signorini::SolveResult result = signorini::runApplication(cl, comm, std::cout);
    return result.converged() ? 0 : 1;
  } catch (const signorini::InputError& e) {
    return leaveAfterError(e.what(), kInputError);
  } catch (const signorini::OutputError& e) {
    return leaveAfterError(e.what(), kOutputError);
  } catch (const std::exception& e) {
    return leaveAfterError(e.what(), kInternalError);
  }
}
