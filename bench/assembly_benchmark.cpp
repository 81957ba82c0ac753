// Benchmark: time and memory of building and assembling a problem of the family.
// Usage: mpirun -np N build/bin/signorini_bench_assembly DIM DEGREE NX [OUTPUT.json]
// Writes one JSON object: sizes, ranks, rank 0's serial mesh phase (arrays and peak
// resident growth, MiB), seconds of mesh + space (setup) and of assembly (max over ranks),
// and the peak resident memory per rank (max and sum).
#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "BenchmarkSupport.hpp"
#include "assembly/DistributedSpace.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "driver/HugePages.hpp"

int main(int argc, char** argv) {
  signorini::detail::restartWithHugePages(argv);  // as the signorini program does
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  if (argc < 4) {
    if (comm->getRank() == 0) std::cerr << "usage: signorini_bench_assembly DIM DEGREE NX [OUTPUT.json]\n";
    return 2;
  }
  const int dim = std::atoi(argv[1]), degree = std::atoi(argv[2]), nx = std::atoi(argv[3]);
  Teuchos::ParameterList problem = signorini::bench::clampedBox(dim, degree, nx);
  problem.set("name", "assembly benchmark");
  // The family's load and contact boundary (doc/benchmark-family.md).
  const std::string t4x = "(8*(2*x-1)^4 - 8*(2*x-1)^2 + 1)", t4y = "(8*(2*y-1)^4 - 8*(2*y-1)^2 + 1)";
  problem.set(std::string("body force: ") + (dim == 2 ? "y" : "z"), dim == 2 ? "-" + t4x : "-(" + t4x + " + " + t4y + ")/2");
  problem.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");

  signorini::BuildRecorder built;
  signorini::AssembledProblem p =
      signorini::buildProblem(problem, comm, ".", signorini::StiffnessNeed::AsConfigured, &built);

  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  double rssMiB = usage.ru_maxrss / 1024.0, maxRss = 0, sumRss = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &rssMiB, &maxRss);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &rssMiB, &sumRss);
  std::ostringstream json;
  json << "{\"dim\": " << dim << ", \"degree\": " << degree << ", \"nx\": " << nx
       << ", \"n\": " << p.qp.b->getGlobalLength() << ", \"m\": " << p.qp.d->getGlobalLength()
       << ", \"nonzeros\": " << signorini::assembledStiffness(p.qp, p.multigrid)->getGlobalNumEntries() << ", \"ranks\": " << comm->getSize()
       << ", \"serial_mesh_mib\": " << signorini::distributedSpace(*p.space).serialPhaseBytes() / (1024.0 * 1024.0)
       << ", \"serial_mesh_peak_rss_mib\": " << built.setupPeakMiB[0]
       << ", \"setup_seconds\": " << built.setupSeconds << ", \"assembly_seconds\": " << built.assemblySeconds
       << ", \"peak_rss_mib_max_rank\": " << maxRss << ", \"peak_rss_mib_all_ranks\": " << sumRss << "}";
  if (comm->getRank() == 0) {
    std::cout << json.str() << std::endl;
    if (argc > 4) std::ofstream(argv[4]) << json.str() << "\n";
  }
  return 0;
}
