// Interior point solvers on problems of the benchmark family.
#include <gtest/gtest.h>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/InteriorPointSolver.hpp"
#include "signorini/ProblemBuilder.hpp"

namespace {

using namespace signorini;

std::string sourceDir() {
  const char* dir = std::getenv("SIGNORINI_SOURCE_DIR");
  return dir ? dir : ".";
}

Teuchos::ParameterList problemList(const std::string& name) {
  auto list = Teuchos::getParametersFromXmlFile(sourceDir() + "/xml/paper/" + name + ".xml");
  return list->sublist("Problem");
}

TEST(InteriorPoint, PrimalDualSolvesM) {
  auto comm = Tpetra::getDefaultComm();
  AssembledProblem p = buildProblem(problemList("M"), comm);
  Teuchos::ParameterList params;
  InteriorPointSolver solver(params);
  IterationLog log(std::cout, comm->getRank() == 0);
  SolveResult r = solver.solve(p.qp, nullptr, &log);
  EXPECT_TRUE(r.converged()) << r.message;
}

TEST(InteriorPoint, PrimalSolvesM) {
  auto comm = Tpetra::getDefaultComm();
  AssembledProblem p = buildProblem(problemList("M"), comm);
  Teuchos::ParameterList params;
  params.set("method", "primal");
  if (const char* g = std::getenv("GAMMA")) {
    params.set("gamma: adaptive", false);
    params.set("primal: gamma", std::atof(g));
    params.set("primal: delta", std::atof(g));
  }
  InteriorPointSolver solver(params);
  IterationLog log(std::cout, comm->getRank() == 0);
  SolveResult r = solver.solve(p.qp, nullptr, &log);
  EXPECT_TRUE(r.converged()) << r.message;
}

}  // namespace
