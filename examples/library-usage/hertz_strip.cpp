// Using Signorini as a library: describe a problem in code, assemble it, hand the QP to the
// interior point solver, and read the result.
//
// An elastic block [0,2]x[0,1] is pushed down by 0.01 on its top face onto a rigid
// cylinder of radius R = 5 under its bottom face (gap g(x) = (x - 1)^2 / (2 R)): the
// contact zone is a strip around x = 1 whose width grows with the push (Hertz).
#include <iostream>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/InteriorPointSolver.hpp"
#include "signorini/ProblemBuilder.hpp"

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();

  // 1. The problem, as the "Problem" list of an XML file would give it.
  Teuchos::ParameterList problem("Problem");
  problem.set("name", "hertz strip");
  problem.set("mesh: dimension", 2);
  problem.set("mesh: cells", Teuchos::Array<int>(Teuchos::tuple<int>(80, 40)));
  problem.set("mesh: lengths", Teuchos::Array<double>(Teuchos::tuple<double>(2.0, 1.0)));
  problem.set("element: degree", 2);
  auto& top = problem.sublist("Dirichlet").sublist("ymax");
  top.set("displacement: x", "0");
  top.set("displacement: y", "-0.01");
  auto& contact = problem.sublist("Contact");
  contact.set("boundary", "ymin");
  contact.set("gap: type", "paraboloid");
  contact.set("gap: center", Teuchos::Array<double>(Teuchos::tuple<double>(1.0, 0.0)));
  contact.set("gap: radius", 5.0);

  // 2. Assembly: a ContactQP {Q, b, A, d, rigid body modes, coordinates} of Tpetra objects.
  //    A code with its own assembly builds a ContactQP itself and starts at step 3.
  signorini::AssembledProblem assembled = signorini::buildProblem(problem, comm);

  // 3. The solver, with default parameters (primal-dual, Mehrotra, CG + MueLu).
  signorini::InteriorPointSolver solver;
  signorini::IterationLog log(std::cout, comm->getRank() == 0);
  signorini::SolveResult result = solver.solve(assembled.qp, nullptr, &log);

  if (comm->getRank() == 0)
    std::cout << "active contact nodes: " << result.activeConstraints << ", energy J = " << result.objective
              << ", status: " << signorini::toString(result.status) << "\n";
  return result.converged() ? 0 : 1;
}
