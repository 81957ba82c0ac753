// Signorini as a QP solver for a code with its own assembly: a membrane over an obstacle.
//
// A membrane spans the unit square, clamped on its edges, under a uniform downward load
// f = 8 (tension 1); a dome-shaped obstacle phi(x, y) = -0.05 - |x - c|^2 lies below it, so
// the membrane comes to rest on the dome's top. With P1 elements on a uniform grid of N x N
// interior nodes (spacing h), the energy 1/2 |grad u|^2 - f u gives the five-point stencil:
//
//     minimise 1/2 u^T Q u - b^T u   subject to   -u <= -phi   (u >= phi at every node),
//
// Q = 5-point Laplacian, b = -f h^2. This file builds Q, b, A = -I and d = -phi as plain
// Tpetra objects distributed over the ranks, hands them to InteriorPointSolver, and reads
// the displacement, the multipliers (the obstacle's force on each node), the active set and
// the history of the Newton steps.
//
// Build against an installed Signorini and run on 2 ranks:
//   cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix> && cmake --build build
//   mpirun -np 2 build/obstacle_membrane [N]
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/signorini.hpp"

using namespace signorini;

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const RCP<const Comm> comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  const long long N = argc > 1 ? std::atoll(argv[1]) : 63;
  const double h = 1.0 / (N + 1), f = 8.0;
  auto position = [&](long long node, double* x) {
    x[0] = (node % N + 1) * h;
    x[1] = (node / N + 1) * h;
  };
  auto obstacle = [](const double* x) { return -0.05 - (x[0] - 0.5) * (x[0] - 0.5) - (x[1] - 0.5) * (x[1] - 0.5); };

  // 1. One unknown per interior node, rows split evenly over the ranks; one constraint per
  //    node, on the same map.
  const RCP<const Map> map = rcp(new Map(N * N, 0, comm));
  auto Q = rcp(new CrsMatrix(map, 5));
  auto A = rcp(new CrsMatrix(map, 1));
  auto b = rcp(new Vector(map)), d = rcp(new Vector(map));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GlobalOrdinal row = map->getGlobalElement(k);
    const long long i = row % N, j = row / N;
    std::vector<GlobalOrdinal> cols{row};
    std::vector<Scalar> vals{4.0};
    for (auto [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}})
      if (i + di >= 0 && i + di < N && j + dj >= 0 && j + dj < N) {
        cols.push_back(row + di + N * dj);
        vals.push_back(-1.0);
      }
    Q->insertGlobalValues(row, Teuchos::ArrayView<const GlobalOrdinal>(cols), Teuchos::ArrayView<const Scalar>(vals));
    const GlobalOrdinal self[] = {row};
    const Scalar minusOne[] = {-1.0};
    A->insertGlobalValues(row, Teuchos::ArrayView<const GlobalOrdinal>(self, 1),
                          Teuchos::ArrayView<const Scalar>(minusOne, 1));
    double x[2];
    position(row, x);
    b->replaceLocalValue(k, -f * h * h);
    d->replaceLocalValue(k, -obstacle(x));
  }
  Q->fillComplete();
  A->fillComplete(map, map);  // domain: the unknowns; range: the constraints

  // 2. The QP. Q is a CrsMatrix, so the default preconditioner (MueLu) can use it; a scalar
  //    problem needs no rigid body modes, nor anything else a MultigridInput could give.
  ContactQP qp;
  qp.Q = Q;
  qp.b = b;
  qp.A = A;
  qp.d = d;

  // 3. Solve with the default parameters (primal-dual, Mehrotra, CG + MueLu); the recorder
  //    keeps what the solve reports of each step (MultigridInput() when there is none to give).
  SolveRecorder record;
  const SolveResult result = InteriorPointSolver().solve(qp, MultigridInput(), nullptr, &record);

  // 4. The result: u = result.v, the obstacle's force on node i is -lambda_i >= 0.
  const double deflection = result.v->normInf();
  const double obstacleForce = result.lambda->norm1();  // -sum of lambda: every lambda_i <= 0
  if (root) {
    std::printf("membrane on %lld x %lld nodes over a dome: %s after %d main iterations, %d Newton steps, "
                "%lld CG iterations\n", N, N, toString(result.status), result.outerIterations, result.newtonSteps,
                result.krylovIterations);
    std::printf("  nodes on the obstacle: %lld (contact area %.4f), total obstacle force %.4f (load %.4f)\n",
                result.activeConstraints, result.activeConstraints * h * h, obstacleForce, f * N * N * h * h);
    std::printf("  largest deflection %.4f, energy %.6f, worst relative KKT residual %.1e\n", deflection,
                result.objective, result.kkt.worst());
    std::printf("  main iteration  mu         worst KKT  CG\n");
    for (const NewtonStepRecord& step : record.history())
      std::printf("  %14d  %.3e  %.2e  %d\n", step.outer, step.mu, step.kkt.worst(), step.krylovIterations);
  }
  return result.converged() ? 0 : 1;
}
