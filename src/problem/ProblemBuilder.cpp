#include "signorini/problem/ProblemBuilder.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/CoarseMeshLattice.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "assembly/MeshVertexGrid.hpp"
#include "assembly/RefinedMeshGrid.hpp"
#include "core/Collectives.hpp"
#include "core/CommunicationPhase.hpp"
#include "core/RootTask.hpp"
#include "fe/BoxGrid.hpp"
#include "fe/GmshMesh.hpp"
#include "core/ParameterValidation.hpp"
#include "problem/MemoryEstimate.hpp"
#include "problem/ValidatedProblem.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/problem/ProblemParameters.hpp"

namespace signorini {
namespace {

// Resident set now (Linux' /proc/self/statm; 0 elsewhere) and its peak so far, in MiB.
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0.0;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double peakResidentMiB() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

// A matrix-free P_k stiffness (k > 1) is never assembled: the geometric multigrid starts from
// the P1 stiffness of the same mesh. A P1 one keeps Q assembled for the preconditioners (the
// multigrid's Galerkin products, MueLu).
bool storesNoStiffness(const ProblemDefinition& def) { return def.matrixFreeStiffness && def.degree > 1; }

}  // namespace

AssembledProblem::AssembledProblem() = default;
AssembledProblem::AssembledProblem(AssembledProblem&&) noexcept = default;
AssembledProblem& AssembledProblem::operator=(AssembledProblem&&) noexcept = default;
AssembledProblem::~AssembledProblem() = default;

namespace {

// The space of a Gmsh mesh refined `gmsh.refinements` times: rank 0 sends each rank its part
// of the coarse mesh (held by rank 0 alone in `mesh`); every rank refines its own, its new
// boundary vertices placed on a .geo geometry. Returns the levels' grids.
std::shared_ptr<const GeometricGrid> refinedGmshSpace(const Teuchos::ParameterList& problem, const GmshSource& gmsh,
                                                      const std::filesystem::path& file,
                                                      std::shared_ptr<SimplexMesh> mesh, const RCP<const Comm>& comm,
                                                      AssembledProblem& result,
                                                      std::shared_ptr<const DistributedSpace>& space) {
  const auto lattice = std::make_shared<detail::CoarseMeshLattice>(comm, std::move(mesh));
  result.definition = detail::definitionOf(problem, lattice->dim());
  const ProblemDefinition& def = result.definition;
  checkMemoryFits(static_cast<double>(def.dim) * lattice->numPoints(def.degree << gmsh.refinements), def.dim,
                  def.degree, !storesNoStiffness(def), def.gridRefinedAtNodes, *comm);
  const SimplexRefinement refinement(def.dim, gmsh.refinements);
  if (file.extension() == ".geo") lattice->placeOnGeometry(file.string(), refinement);
  detail::RefinedLevel finest = detail::refineLocally(*lattice, refinement, gmsh.refinements, true);
  space = std::make_shared<const DistributedSpace>(*lattice, refinement, def.degree, finest);
  return RefinedMeshGrid::hierarchy(lattice, refinement, *space, finest);
}

// The definition of the validated `problem` list and the space, with the grids of a refined
// mesh if there are. Every rank
// makes its own part of a box mesh. A Gmsh mesh is read by rank 0 alone, once, and freed once
// each rank has its part (of the mesh, or of the coarse mesh it refines); its dimension
// decides the one the rest of the definition is read with.
std::shared_ptr<const GeometricGrid> makeSpace(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                                               const std::string& baseDirectory, AssembledProblem& result,
                                               std::shared_ptr<const DistributedSpace>& space) {
  const GmshSource gmsh = detail::gmshSourceOf(problem);
  if (gmsh.file.empty()) {
    ProblemDefinition def = detail::definitionOf(problem, 0);
    checkMemoryFits(boxMeshUnknowns(def.dim, def.cells, def.degree), def.dim, def.degree, !storesNoStiffness(def),
                    def.gridRefinedAtNodes, *comm);
    space = std::make_shared<const DistributedSpace>(comm, BoxGrid(def.dim, def.cells, def.lengths), def.degree);
    result.definition = std::move(def);
    return nullptr;
  }
  std::shared_ptr<SimplexMesh> mesh;
  std::filesystem::path file(gmsh.file);
  if (file.is_relative()) file = std::filesystem::path(baseDirectory) / file;
  detail::runOnRoot(*comm, [&] { mesh = std::make_shared<SimplexMesh>(readGmshMesh(file.string(), gmsh.sizeFactor)); });
  if (gmsh.refinements > 0) return refinedGmshSpace(problem, gmsh, file, std::move(mesh), comm, result, space);
  int dim = mesh ? mesh->dim : 0;
  Teuchos::broadcast(*comm, 0, 1, &dim);
  result.definition = detail::definitionOf(problem, dim);
  const ProblemDefinition& def = result.definition;
  space = std::make_shared<const DistributedSpace>(comm, std::move(mesh), def.degree);
  checkMemoryFits(static_cast<double>(def.dim) * space->numGlobalNodes(), def.dim, def.degree,
                  !storesNoStiffness(def), def.gridRefinedAtNodes, *comm);
  return nullptr;
}

// The QP on `space`, and the grids of the geometric multigrid: a box's or a refined
// mesh's nested ones, a P_k space's own mesh, or that mesh refined at the nodes, whose
// stiffness is no Galerkin product of Q's.
void assembleQP(AssembledProblem& result, const std::shared_ptr<const DistributedSpace>& space,
                std::shared_ptr<const GeometricGrid> refinedGrid) {
  const ProblemDefinition& def = result.definition;
  const bool onlyGridStiffness = storesNoStiffness(def);
  result.qp = assembleContactQP(*space, def, !onlyGridStiffness);
  MultigridInput& multigrid = result.multigrid;
  multigrid = meshMultigridInput(*space);
  if (def.matrixFreeStiffness) {
    multigrid.assembledQ = assembledStiffness(result.qp, multigrid);
    result.qp.Q = matrixFreeStiffness(space, def);
  }
  if (def.gridRefinedAtNodes)
    multigrid.grid = std::make_shared<MeshVertexGrid>(space, MeshVertexGrid::Refinement::atNodes);
  else if (refinedGrid)
    multigrid.grid = std::move(refinedGrid);
  else if (def.meshType == "box")
    multigrid.grid = std::make_shared<BoxGrid>(def.dim, def.cells, def.lengths);
  else if (def.degree > 1)
    multigrid.grid = std::make_shared<MeshVertexGrid>(space);
  if (onlyGridStiffness || def.gridRefinedAtNodes)
    multigrid.gridStiffness = assembleGridStiffness(*space, def, *multigrid.grid);
}

}  // namespace

void BuildRecorder::onPhase(const std::string& phase, double seconds) {
  (phase == "assembly" ? assemblySeconds : setupSeconds) = seconds;
}

AssembledProblem buildProblem(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                              const std::string& baseDirectory, StiffnessNeed stiffness, BuildObserver* observer) {
  BuildObserver none;
  BuildObserver& report = observer ? *observer : none;
  AssembledProblem result;
  std::shared_ptr<const DistributedSpace> space;
  std::shared_ptr<const GeometricGrid> refinedGrid;  // the levels of a refined Gmsh mesh
  Teuchos::Time setup("setup"), assembly("assembly");
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::meshAndSpace);
    setup.start(true);
    const double residentBefore = residentMiB();
    Teuchos::ParameterList validated = validatedParameters(problem, validProblemParameters(), "Problem");
    if (stiffness == StiffnessNeed::Assembled && validated.get<std::string>("stiffness: operator") == "auto")
      validated.set("stiffness: operator", "assembled");
    refinedGrid = makeSpace(validated, comm, baseDirectory, result, space);
    result.space = space;
    setup.stop();
    const double growth = std::max(0.0, peakResidentMiB() - residentBefore);
    std::vector<double> growthPerRank(comm->getSize());
    Teuchos::gatherAll(*comm, 1, &growth, comm->getSize(), growthPerRank.data());
    report.onSetupMemory(growthPerRank);
  }
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: assembly"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::assembly);
    assembly.start(true);
    assembleQP(result, space, std::move(refinedGrid));
    assembly.stop();
  }
  report.onPhase("mesh and space", maxOverRanks(*comm, setup.totalElapsedTime()));
  report.onPhase("assembly", maxOverRanks(*comm, assembly.totalElapsedTime()));
  return result;
}

}  // namespace signorini
