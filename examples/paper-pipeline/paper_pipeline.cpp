// The application's pipeline in code: read one of the shipped inputs, change it, solve it with
// the paper's primal method (Algorithm 3.1), follow the solve with an observer of one's own,
// and write the same outputs as the application.
//
// The input is an XML file with the "Problem" (and optionally "Solver") lists of the
// application, for example xml/paper/H.xml of the source tree (the paper's problem H: a
// square of P2 elements on a rigid foundation, clamped on top, loaded by a body force).
// The example doubles the mesh cells, switches to the primal method with the barrier
// parameter divided by 10 per main iteration, prints one line per main iteration from its own
// observer, reports the contact force and writes solution.pvtu (open it in ParaView) to the
// output directory.
//
// Build against an installed Signorini and run on 2 ranks:
//   cmake -S . -B build -DCMAKE_PREFIX_PATH=<prefix> && cmake --build build
//   mpirun -np 2 build/paper_pipeline <signorini source>/xml/paper/H.xml [output directory]
#include <cstdio>
#include <string>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "signorini/signorini.hpp"

using namespace signorini;

// An observer of one's own: one line at the end of each main iteration (the primal method
// takes several Newton steps per main iteration), printed by rank 0 only.
class MainIterationPrinter : public IterationObserver {
 public:
  explicit MainIterationPrinter(bool print) : print_(print) {}

  void onStart(const std::string& method, long long n, long long m) override {
    if (print_) std::printf("%s method, n = %lld unknowns, m = %lld constraints\n", method.c_str(), n, m);
  }
  void onNewtonStep(const NewtonStepRecord& step) override {
    if (step.outer != last_.outer && newtonSteps_ > 0) printLast();
    last_ = step;
    ++newtonSteps_;
  }
  void onFinish(const SolveResult& result) override {
    if (newtonSteps_ > 0) printLast();
    if (print_) std::printf("%s after %d main iterations\n", toString(result.status), result.outerIterations);
  }

 private:
  void printLast() const {
    if (print_)
      std::printf("  main iteration %2d: mu = %8.2e  J = %+.10e  worst relative KKT measure %8.2e  (%d Newton steps so far)\n",
                  last_.outer, last_.mu, last_.objective, last_.kkt.worst(), newtonSteps_);
  }

  bool print_;
  NewtonStepRecord last_;
  int newtonSteps_ = 0;
};

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  const RCP<const Comm> comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 2) {
    if (root) std::fprintf(stderr, "usage: paper_pipeline <input.xml> [output directory]\n");
    return 2;
  }
  const std::string directory = argc > 2 ? argv[2] : "paper-pipeline-output";

  try {
    // 1. The input, as the application reads it, then changed in code.
    RCP<Teuchos::ParameterList> input = Teuchos::getParametersFromXmlFile(argv[1]);
    Teuchos::ParameterList& problem = input->sublist("Problem");
    Teuchos::Array<int> cells = problem.get<Teuchos::Array<int>>("mesh: cells");
    for (int& c : cells) c *= 2;
    problem.set("mesh: cells", cells);
    Teuchos::ParameterList& solverParameters = input->sublist("Solver");
    solverParameters.set("method", "primal");
    solverParameters.set("primal: gamma", 0.1);

    // 2. Mesh, partition, space and the assembled QP; a relative "mesh: file" is found
    //    next to the input.
    const std::string file = argv[1];
    const std::string base = file.find('/') == std::string::npos ? "." : file.substr(0, file.rfind('/'));
    AssembledProblem assembled = buildProblem(problem, comm, base);

    // 3. The solve, followed by the observer.
    InteriorPointSolver solver(solverParameters);
    MainIterationPrinter printer(root);
    const SolveResult result = solver.solve(assembled.qp, assembled.multigrid, nullptr, &printer);

    // 4. Contact pressure and statistics, then the ParaView output.
    const RCP<Vector> active = activeIndicator(assembled.qp, *result.v, *result.lambda);
    const ContactPressure recovery(*assembled.space, assembled.definition, assembled.qp.A->getRangeMap());
    const RCP<Vector> pressure = recovery.pressure(*result.lambda, *active);
    const ContactStatistics contact = contactStatistics(recovery, *pressure, *assembled.qp.A, *result.lambda,
                                                        *active, assembled.definition.contacts.front().obstacleDirection);
    const ContactFields fields{recovery, *pressure, *active};
    writeSolution(assembled, result, {fields}, directory);
    if (root)
      std::printf("J = %.12e; %lld active contact nodes, normal force %.6e, peak pressure %.6e\n"
                  "written: %s/solution.pvtu\n",
                  result.objective, contact.activeNodes, contact.normalForce, contact.peakPressure, directory.c_str());
    return result.converged() ? 0 : 1;
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "paper_pipeline: %s\n", e.what());
    return 1;
  }
}
