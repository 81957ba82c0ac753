#include "signorini/ProblemBuilder.hpp"

#include <filesystem>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "signorini/BoxMesh.hpp"
#include "signorini/ElasticityAssembler.hpp"
#include "signorini/Error.hpp"
#include "signorini/GmshMesh.hpp"

namespace signorini {
namespace {

double maxOverRanks(const Comm& comm, double value) {
  double result = value;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &value, &result);
  return result;
}

}  // namespace

AssembledProblem buildProblem(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                              const std::string& baseDirectory) {
  AssembledProblem result;
  Teuchos::Time setup("setup"), assembly("assembly");
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: 1 mesh and space"));
    setup.start(true);
    // The definition is read twice for a Gmsh mesh: the file decides the dimension.
    ProblemDefinition def = ProblemDefinition::fromParameters(problem);
    std::shared_ptr<SimplexMesh> mesh;
    if (def.meshType == "gmsh") {
      std::filesystem::path file(def.meshFile);
      if (file.is_relative()) file = std::filesystem::path(baseDirectory) / file;
      mesh = std::make_shared<SimplexMesh>(readGmshMesh(file.string()));
      def = ProblemDefinition::fromParameters(problem, mesh->dim);
    } else {
      mesh = std::make_shared<SimplexMesh>(makeBoxMesh(def.dim, def.cells, def.lengths));
    }
    result.definition = std::move(def);
    result.mesh = mesh;
    result.space = std::make_unique<DistributedSpace>(comm, mesh, result.definition.degree);
    setup.stop();
  }
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: 2 assembly"));
    assembly.start(true);
    result.qp = assembleContactQP(*result.space, result.definition);
    assembly.stop();
  }
  result.setupSeconds = maxOverRanks(*comm, setup.totalElapsedTime());
  result.assemblySeconds = maxOverRanks(*comm, assembly.totalElapsedTime());
  return result;
}

}  // namespace signorini
