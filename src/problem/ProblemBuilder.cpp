#include "signorini/problem/ProblemBuilder.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/CoarseMeshLattice.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "solver/DelaunayCoarseGrid.hpp"
#include "assembly/MeshVertexGrid.hpp"
#include "assembly/MortarFacet.hpp"
#include "assembly/ParallelMshRead.hpp"
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

// The timer of one step of the mesh and space setup, listed in the log's timer table.
RCP<Teuchos::Time> setupTimer(const std::string& step) {
  return Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space: " + step);
}

}  // namespace

AssembledProblem::AssembledProblem() = default;
AssembledProblem::AssembledProblem(AssembledProblem&&) noexcept = default;
AssembledProblem& AssembledProblem::operator=(AssembledProblem&&) noexcept = default;
AssembledProblem::~AssembledProblem() = default;

namespace {

// The space on `lattice`'s coarse mesh refined `gmsh.refinements` times, every rank refining
// its own part, its new boundary vertices placed on a .geo geometry; without refinement, the
// space on the mesh itself. Either way its cells come in Morton order of the coarse cells,
// which keeps a cell's nodes near in memory. Returns the levels' grids (none without
// refinement).
std::shared_ptr<const GeometricGrid> latticeSpace(const Teuchos::ParameterList& problem, const GmshSource& gmsh,
                                                  const std::filesystem::path& file,
                                                  const std::shared_ptr<detail::CoarseMeshLattice>& lattice,
                                                  AssembledProblem& result,
                                                  std::shared_ptr<const DistributedSpace>& space) {
  result.definition = detail::definitionOf(problem, lattice->dim());
  const ProblemDefinition& def = result.definition;
  checkMemoryFits(static_cast<double>(def.dim) * lattice->numPoints(def.degree << gmsh.refinements), def.dim,
                  def.degree, !storesNoStiffness(def), def.gridRefinedAtNodes, *lattice->comm());
  const SimplexRefinement refinement(def.dim, gmsh.refinements);
  if (file.extension() == ".geo") {
    const Teuchos::TimeMonitor timer(*setupTimer("placement on the geometry"));
    lattice->placeOnGeometry(file.string(), refinement);
  }
  detail::RefinedLevel finest;
  {
    const Teuchos::TimeMonitor timer(*setupTimer("refinement"));
    finest = detail::refineLocally(*lattice, refinement, gmsh.refinements, true);
  }
  {
    const Teuchos::TimeMonitor timer(*setupTimer("space"));
    space = std::make_shared<const DistributedSpace>(*lattice, refinement, def.degree, finest);
  }
  if (gmsh.refinements == 0) return nullptr;
  const Teuchos::TimeMonitor timer(*setupTimer("levels"));
  return RefinedMeshGrid::hierarchy(lattice, refinement, space, std::move(finest), def.delaunayCoarseGrids);
}

// The resolution of the finest lattice points of a Gmsh mesh: its space's nodes, k 2^r.
long long finestResolution(const Teuchos::ParameterList& problem, int dim, const GmshSource& gmsh) {
  return static_cast<long long>(detail::definitionOf(problem, dim).degree) << gmsh.refinements;
}

// File k (from 1) of a mesh written in parts: name_k.ext for `file` name.ext, as Gmsh names them.
std::filesystem::path partFile(const std::filesystem::path& file, int k) {
  std::filesystem::path part = file;
  part.replace_filename(file.stem().string() + "_" + std::to_string(k) + file.extension().string());
  return part;
}

// How many part files name_1.ext, name_2.ext, .. rank 0 finds for a `file` that does not
// exist itself (0: it exists, or has no parts), the same on every rank.
int numPartFiles(const Comm& comm, const std::filesystem::path& file) {
  int count = 0;
  if (comm.getRank() == 0 && !std::filesystem::exists(file))
    while (std::filesystem::exists(partFile(file, count + 1))) ++count;
  Teuchos::broadcast(comm, 0, 1, &count);
  return count;
}

// The space of a mesh of which every rank holds its own part (rank r part r).
std::shared_ptr<const GeometricGrid> partSpace(const Teuchos::ParameterList& problem, const GmshSource& gmsh,
                                               const std::filesystem::path& file, GmshMeshPart&& part,
                                               const RCP<const Comm>& comm, AssembledProblem& result,
                                               std::shared_ptr<const DistributedSpace>& space) {
  const long long resolution = finestResolution(problem, part.mesh.dim, gmsh);
  std::shared_ptr<detail::CoarseMeshLattice> lattice;
  {
    const Teuchos::TimeMonitor timer(*setupTimer("lattice"));
    lattice = std::make_shared<detail::CoarseMeshLattice>(comm, std::move(part), resolution);
  }
  return latticeSpace(problem, gmsh, file, lattice, result, space);
}

// The space of a Gmsh mesh written in `numParts` part files, one per rank: each rank reads
// its own and no rank holds the mesh.
std::shared_ptr<const GeometricGrid> splitGmshSpace(const Teuchos::ParameterList& problem, const GmshSource& gmsh,
                                                    const std::filesystem::path& file, int numParts,
                                                    const RCP<const Comm>& comm, AssembledProblem& result,
                                                    std::shared_ptr<const DistributedSpace>& space) {
  const int ranks = comm->getSize();
  if (numParts != ranks)
    throw InputError("Problem/mesh: file: '" + file.string() + "' is written in " + std::to_string(numParts) +
                     " parts (" + partFile(file, 1).filename().string() + " .. " +
                     partFile(file, numParts).filename().string() + "), and a mesh in parts is read one part per rank: "
                     "run on " + std::to_string(numParts) + " ranks, or partition the mesh again into " +
                     std::to_string(ranks) + " (gmsh -part " + std::to_string(ranks) + " -part_split)");
  GmshMeshPart part;
  {
    const Teuchos::TimeMonitor timer(*setupTimer("mesh read"));
    detail::runOnEveryRank(*comm, [&] {
      const std::string path = partFile(file, comm->getRank() + 1).string();
      part = readGmshMeshPart(path);
      if (part.part != comm->getRank())
        throw InputError("Gmsh mesh file '" + path + "': it holds part " + std::to_string(part.part + 1) + ", not part " +
                         std::to_string(comm->getRank() + 1));
    });
  }
  return partSpace(problem, gmsh, file, std::move(part), comm, result, space);
}

// The definition of the validated `problem` list and the space, with the grids of a refined
// mesh if there are. Every rank makes its own part of a box mesh. A mesh written in parts:
// each rank its own part. A .msh file with `mesh: read` = "all ranks", on more than one rank:
// all ranks together, each keeping a slice and then its part (readMshInParallel), where the
// parallel reader knows the file's format. Any other Gmsh mesh is read by rank 0 alone, once,
// and freed once each rank has its part (CoarseMeshLattice); `report` hears why where all ranks
// were asked to read it. The mesh's dimension decides the one the rest of the definition is
// read with.
std::shared_ptr<const GeometricGrid> makeSpace(const Teuchos::ParameterList& problem, const RCP<const Comm>& comm,
                                               const std::string& baseDirectory, AssembledProblem& result,
                                               std::shared_ptr<const DistributedSpace>& space, BuildObserver& report) {
  const GmshSource gmsh = detail::gmshSourceOf(problem);
  if (gmsh.file.empty()) {
    ProblemDefinition def = detail::definitionOf(problem, 0);
    checkMemoryFits(boxMeshUnknowns(def.dim, def.cells, def.degree), def.dim, def.degree, !storesNoStiffness(def),
                    def.gridRefinedAtNodes, *comm);
    {
      const Teuchos::TimeMonitor timer(*setupTimer("space"));
      space = std::make_shared<const DistributedSpace>(comm, BoxGrid(def.dim, def.cells, def.lengths), def.degree);
    }
    result.definition = std::move(def);
    return nullptr;
  }
  std::shared_ptr<SimplexMesh> mesh;
  std::filesystem::path file(gmsh.file);
  if (file.is_relative()) file = std::filesystem::path(baseDirectory) / file;
  if (const int numParts = numPartFiles(*comm, file); numParts > 0)
    return splitGmshSpace(problem, gmsh, file, numParts, comm, result, space);
  if (gmsh.readByAllRanks && comm->getSize() > 1 && file.extension() == ".msh") {
    std::string unsupported;  // the file is then read whole by rank 0
    GmshMeshPart part;
    {
      const Teuchos::TimeMonitor timer(*setupTimer("mesh read"));
      part = detail::readMshInParallel(comm, file.string(), unsupported);
    }
    if (unsupported.empty()) return partSpace(problem, gmsh, file, std::move(part), comm, result, space);
    report.onNote("mesh file '" + file.string() + "' read whole by rank 0, not by all ranks: " + unsupported);
  }
  {
    const Teuchos::TimeMonitor timer(*setupTimer("mesh read"));
    detail::runOnRoot(*comm, [&] { mesh = std::make_shared<SimplexMesh>(readGmshMesh(file.string(), gmsh.sizeFactor)); });
  }
  if (mesh)
    for (const std::string& note : mesh->notes) report.onNote(note);
  int dim = mesh ? mesh->dim : 0;
  Teuchos::broadcast(*comm, 0, 1, &dim);
  std::shared_ptr<detail::CoarseMeshLattice> lattice;
  {
    const Teuchos::TimeMonitor timer(*setupTimer("partition and lattice"));
    lattice = std::make_shared<detail::CoarseMeshLattice>(comm, std::move(mesh), finestResolution(problem, dim, gmsh));
  }
  return latticeSpace(problem, gmsh, file, lattice, result, space);
}

// A pair between two bodies without an obstacle: direction gets the one from the master into
// the slave body: against the slave boundary's mean outward normal, or the last axis where
// that boundary faces every way (its mean normal shorter than a tenth).
void orientMortarPairs(ProblemDefinition& def, const DistributedSpace& space) {
  for (ContactPair& pair : def.contacts) {
    const auto& d = pair.obstacleDirection;
    if (pair.masterBoundary.empty() || d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0) continue;
    const std::array<double, 3> n = meanOutwardNormal(space, space.mesh().tag(pair.boundary));
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int c = 0; c < 3; ++c)
      pair.obstacleDirection[c] = length >= 0.1 ? -n[c] / length : c == def.dim - 1 ? 1.0 : 0.0;
  }
}

// The P1 grid of a mesh without coarser levels of its own, with Delaunay coarse grids below.
std::shared_ptr<const GeometricGrid> delaunayHierarchy(const std::shared_ptr<const DistributedSpace>& space) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space: coarse grids"));
  auto grid = std::make_shared<MeshVertexGrid>(space);
  grid->setCoarser(DelaunayCoarseGrid::hierarchyBelow(space->comm(), grid->vertexGraph()));
  return grid;
}

// The QP on `space`, and the grids of the geometric multigrid: a box's or a refined
// mesh's nested ones, an unrefined mesh's Delaunay coarse grids (`meshGrid` holds either), a
// P_k space's own mesh, or that mesh refined at the nodes, whose stiffness is no Galerkin
// product of Q's.
void assembleQP(AssembledProblem& result, const std::shared_ptr<const DistributedSpace>& space,
                std::shared_ptr<const GeometricGrid> meshGrid) {
  orientMortarPairs(result.definition, *space);
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
  else if (meshGrid)
    multigrid.grid = std::move(meshGrid);
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
  // The levels of a refined Gmsh mesh, or the coarse grids made for an unrefined one.
  std::shared_ptr<const GeometricGrid> meshGrid;
  Teuchos::Time setup("setup"), assembly("assembly");
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::meshAndSpace);
    setup.start(true);
    const double residentBefore = residentMiB();
    Teuchos::ParameterList validated = validatedParameters(problem, validProblemParameters(), "Problem");
    if (stiffness == StiffnessNeed::Assembled && validated.get<std::string>("stiffness: operator") == "auto")
      validated.set("stiffness: operator", "assembled");
    meshGrid = makeSpace(validated, comm, baseDirectory, result, space, report);
    const ProblemDefinition& def = result.definition;
    if (!meshGrid && def.delaunayCoarseGrids && !def.gridRefinedAtNodes) meshGrid = delaunayHierarchy(space);
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
    assembleQP(result, space, std::move(meshGrid));
    assembly.stop();
  }
  report.onPhase("mesh and space", maxOverRanks(*comm, setup.totalElapsedTime()));
  report.onPhase("assembly", maxOverRanks(*comm, assembly.totalElapsedTime()));
  return result;
}

}  // namespace signorini
