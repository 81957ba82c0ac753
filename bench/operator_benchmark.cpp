// Benchmark: the stiffness Q of a family member applied as the assembled matrix and as the
// matrix-free operator (MatrixFreeElasticityOperator): bytes each keeps per unknown and
// seconds per application (median of REPEATS, max over ranks).
// Usage: mpirun -np N build/bin/signorini_bench_operator DIM DEGREE NX [REPEATS]
// Writes one JSON object on rank 0's standard output.
#include <cstdlib>
#include <iostream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "BenchmarkSupport.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "driver/HugePages.hpp"

int main(int argc, char** argv) {
  signorini::detail::restartWithHugePages(argv);  // as the signorini program does
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  if (argc < 4) {
    if (comm->getRank() == 0) std::cerr << "usage: signorini_bench_operator DIM DEGREE NX [REPEATS]\n";
    return 2;
  }
  const int dim = std::atoi(argv[1]), degree = std::atoi(argv[2]), nx = std::atoi(argv[3]);
  const int repeats = argc > 4 ? std::atoi(argv[4]) : 11;
  signorini::AssembledProblem p = signorini::buildProblem(signorini::bench::clampedBox(dim, degree, nx), comm);
  const auto& K = *signorini::assembledStiffness(p.qp, p.multigrid);
  const auto Q = signorini::matrixFreeStiffness(signorini::distributedSpace(p.space), p.definition);
  signorini::Vector x(K.getDomainMap()), y(K.getRangeMap());
  x.randomize();
  Q->apply(x, y);  // allocates its work vectors before they are counted and timed

  // CSR: values and column indices per entry, a row offset per row.
  const double n = static_cast<double>(K.getGlobalNumRows());
  const double csrBytes = K.getGlobalNumEntries() * (sizeof(double) + sizeof(signorini::LocalOrdinal)) +
                          n * sizeof(std::size_t);
  double freeBytes = static_cast<double>(Q->bytes()), freeTotal = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &freeBytes, &freeTotal);
  const double assembledSeconds = signorini::bench::medianSeconds(*comm, repeats, [&] { K.apply(x, y); });
  const double freeSeconds = signorini::bench::medianSeconds(*comm, repeats, [&] { Q->apply(x, y); });
  std::ostringstream json;
  json << "{\"dim\": " << dim << ", \"degree\": " << degree << ", \"nx\": " << nx << ", \"n\": " << K.getGlobalNumRows()
       << ", \"ranks\": " << comm->getSize() << ", \"nonzeros\": " << K.getGlobalNumEntries()
       << ", \"assembled_bytes_per_unknown\": " << csrBytes / n << ", \"matrix_free_bytes_per_unknown\": "
       << freeTotal / n << ", \"assembled_seconds_per_apply\": " << assembledSeconds
       << ", \"matrix_free_seconds_per_apply\": " << freeSeconds << "}";
  if (comm->getRank() == 0) std::cout << json.str() << std::endl;
  return 0;
}
