// Benchmark: the factorization of a coarsest-level matrix on one rank, by Amesos2's KLU2 (LU)
// and by CHOLMOD (SparseCholesky, Cholesky): seconds for a first factorization, for a
// refactorization of new values on the same pattern, and per solve (medians of REPEATS).
// The matrix is the stiffness Q of a P1 box of the family (clamped top face).
// Usage: build/bin/signorini_bench_direct_solver DIM NX [REPEATS]  (one rank)
// Writes one JSON object on standard output.
#include <cstdlib>
#include <iostream>

#include <Amesos2.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "BenchmarkSupport.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "solver/preconditioner/SparseCholesky.hpp"
#include "driver/HugePages.hpp"

using namespace signorini;

int main(int argc, char** argv) {
  signorini::detail::restartWithHugePages(argv);  // as the signorini program does
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  if (argc < 3 || comm->getSize() != 1) {
    std::cerr << "usage: signorini_bench_direct_solver DIM NX [REPEATS] (on one rank)\n";
    return 2;
  }
  const int dim = std::atoi(argv[1]), nx = std::atoi(argv[2]);
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 5;
  const AssembledProblem p = buildProblem(bench::clampedBox(dim, 1, nx), comm);
  const auto Q = Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(p.qp, p.multigrid));

  MultiVector b(Q->getRangeMap(), 1), x(Q->getDomainMap(), 1);
  b.randomize();
  auto lu = Amesos2::create<CrsMatrix, MultiVector>("KLU2", Q);
  const double luFirst = bench::medianSeconds(*comm, repeats, [&] {
    lu = Amesos2::create<CrsMatrix, MultiVector>("KLU2", Q);
    lu->symbolicFactorization().numericFactorization();
  });
  const double luRefactor = bench::medianSeconds(*comm, repeats, [&] { lu->numericFactorization(); });
  const double luSolve = bench::medianSeconds(*comm, repeats, [&] { lu->solve(Teuchos::ptrFromRef(x), Teuchos::ptrFromRef(b)); });

  SparseCholesky cholesky;
  const double cholFirst = bench::medianSeconds(*comm, repeats, [&] {
    SparseCholesky fresh;
    fresh.factor(*Q);
  });
  cholesky.factor(*Q);
  const double cholRefactor = bench::medianSeconds(*comm, repeats, [&] { SparseCholesky(cholesky).factor(*Q); });
  const double cholSolve = bench::medianSeconds(*comm, repeats, [&] { cholesky.solve(b, x); });

  std::cout << "{\"dim\": " << dim << ", \"nx\": " << nx << ", \"n\": " << Q->getGlobalNumRows()
            << ", \"nonzeros\": " << Q->getGlobalNumEntries() << ", \"klu2_first_seconds\": " << luFirst
            << ", \"klu2_refactor_seconds\": " << luRefactor << ", \"klu2_solve_seconds\": " << luSolve
            << ", \"cholmod_first_seconds\": " << cholFirst << ", \"cholmod_refactor_seconds\": " << cholRefactor
            << ", \"cholmod_solve_seconds\": " << cholSolve << "}" << std::endl;
  return 0;
}
