#include "driver/Application.hpp"

#include <sys/resource.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <system_error>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_Time.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/ElasticityAssembler.hpp"
#include "core/Collectives.hpp"
#include "core/CommunicationPhase.hpp"
#include "core/ParameterValidation.hpp"
#include "core/RootTask.hpp"
#include "driver/HugePages.hpp"
#include "io/OutputSpace.hpp"
#include "io/QPCells.hpp"
#include "io/RunSummary.hpp"
#include "io/XmlEscape.hpp"
#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/io/QPFiles.hpp"
#include "signorini/io/SolutionOutput.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/problem/ProblemParameters.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/KKTMeasures.hpp"

namespace signorini {
namespace {

// What precedes the documentation of an expert parameter (isExpert) in the XML.
constexpr const char* kExpert = "Expert: ";

Teuchos::ParameterList outputParameters() {
  Teuchos::ParameterList p("Output");
  p.set("directory", "results", "Directory of solution.pvtu, summary.json and history.csv (--output overrides)");
  p.set("write solution", true, "Write solution.pvtu with one .vtu per rank");
  p.set("write history", true, "Write history.csv, one row per Newton step");
  p.set("contact pressure", "auto",
        "Pressure recovered from nodal multipliers: \"consistent\" (boundary mass matrix solve), "
        "\"lumped\" (HRZ weights), \"patch\" (lumped, averaged over each active node's facet patch; the "
        "nodal pressures of dual mortar constraints are averaged the same way) or \"auto\" (lumped for 2D P1, "
        "patch for 3D P1, consistent for P2, P3); the multipliers of weighted gaps are the pressure's "
        "coefficients already; see doc/hertz-validation.md",
        choices<PressureRecovery>({{"auto", PressureRecovery::Auto},
                                   {"consistent", PressureRecovery::Consistent},
                                   {"lumped", PressureRecovery::Lumped},
                                   {"patch", PressureRecovery::Patch}},
                                  "contact pressure"));
  p.set("write contact samples", false,
        "Write contact.csv: the recovered contact pressure at quadrature points of the contact "
        "boundary (coordinates, weight, pressure), for integrating errors against a reference");
  return p;
}

// Parses "text" as the type of `model`; throws InputError naming `where`.
Teuchos::ParameterEntry parseLike(const Teuchos::ParameterEntry* model, const std::string& text,
                                  const std::string& where) {
  Teuchos::ParameterEntry entry;
  std::istringstream in(text);
  auto fail = [&](const std::string& type) {
    return InputError("--set " + where + ": \"" + text + "\" is not a valid " + type);
  };
  if (model && model->isType<int>()) {
    int v;
    if (!(in >> v) || !in.eof()) throw fail("int");
    entry.setValue(v);
  } else if (model && model->isType<double>()) {
    double v;
    if (!(in >> v) || !in.eof()) throw fail("double");
    entry.setValue(v);
  } else if (model && model->isType<bool>()) {
    if (text != "true" && text != "false") throw fail("bool (true or false)");
    entry.setValue(text == "true");
  } else if (model && model->isType<std::string>()) {
    entry.setValue(text);
  } else if (model && model->isArray()) {
    // Arrays keep Teuchos' "{a, b}" syntax.
    Teuchos::ParameterList tmp;
    std::string xml = "<ParameterList><Parameter name=\"x\" type=\"" + model->getAny(false).typeName() +
                      "\" value=\"" + text + "\"/></ParameterList>";
    try {
      tmp = *Teuchos::getParametersFromXmlString(xml);
    } catch (const std::exception& e) {
      throw fail(model->getAny(false).typeName());
    }
    entry = tmp.getEntry("x");
  } else {
    // Unknown to the valid lists (e.g. inside a MueLu or Belos sublist): infer the type.
    int i;
    double d;
    std::istringstream asInt(text), asDouble(text);
    if ((asInt >> i) && asInt.eof())
      entry.setValue(i);
    else if ((asDouble >> d) && asDouble.eof())
      entry.setValue(d);
    else if (text == "true" || text == "false")
      entry.setValue(text == "true");
    else
      entry.setValue(text);
  }
  return entry;
}

void logContact(const ContactStatistics& c, std::ostream& out, const std::string& label = "Contact") {
  out << label << ": force (";
  for (int i = 0; i < c.dim; ++i) out << (i ? ", " : "") << c.force[i];
  out << ")";
  if (c.masterForce) {
    out << " (on the master body: (";
    for (int i = 0; i < c.dim; ++i) out << (i ? ", " : "") << (*c.masterForce)[i];
    out << "))";
  }
  out << ", normal force " << c.normalForce << ", ";
  if (std::isfinite(c.area))
    out << (c.dim == 2 ? "length " : "area ") << c.area << ", peak pressure " << c.peakPressure << ", ";
  out << c.activeNodes << " active nodes" << (std::isfinite(c.area) ? "" : " (no mesh: no pressure)") << "\n";
}

std::string shortest(double x) {
  char buffer[32];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

// The value as a user would type it in XML.
std::string valueText(const Teuchos::ParameterEntry& entry) {
  if (entry.isType<bool>()) return Teuchos::getValue<bool>(entry) ? "true" : "false";
  if (entry.isType<double>()) return shortest(Teuchos::getValue<double>(entry));
  if (entry.isType<Teuchos::Array<double>>()) {
    std::string text = "{";
    for (double x : Teuchos::getValue<Teuchos::Array<double>>(entry)) text += (text.size() > 1 ? ", " : "") + shortest(x);
    return text + "}";
  }
  return Teuchos::toString(entry.getAny(false));
}

// Comments may not contain "--".
std::string commentText(std::string text) {
  for (std::size_t at; (at = text.find("--")) != std::string::npos;) text.replace(at, 2, "- -");
  return text;
}

// Expert parameters (isExpert) are left out unless `all`; their documentation says "Expert: ".
void writeDocumented(const Teuchos::ParameterList& list, const std::string& name, int depth, bool all,
                     std::ostringstream& out) {
  const std::string indent(2 * depth, ' ');
  out << indent << "<ParameterList name=\"" << detail::xmlEscaped(name) << "\">\n";
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& key = list.name(it);
    const Teuchos::ParameterEntry& entry = list.entry(it);
    if (!all && isExpert(entry)) continue;
    if (!entry.docString().empty())
      out << indent << "  <!-- " << (isExpert(entry) ? kExpert : "") << commentText(entry.docString()) << " -->\n";
    if (key == kAnyNameSublist) {
      // A template for user-named sublists: shown commented out, not a parameter. They are
      // named after bodies in "Bodies", as the user likes in "Contact" (pairs), after
      // boundaries elsewhere.
      const std::string named = name == "Bodies" ? "body" : name == "Contact" ? "pair" : "boundary";
      std::string placeholder = named + " name";
      for (char& c : placeholder) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      std::ostringstream templ;
      writeDocumented(Teuchos::getValue<Teuchos::ParameterList>(entry), placeholder, depth + 1, all, templ);
      out << indent << "  <!-- one sublist per " << named << (named == "pair" ? ", named as you like" : ", named after it")
          << ":\n" << commentText(templ.str()) << indent << "  -->\n";
    } else if (entry.isList()) {
      writeDocumented(Teuchos::getValue<Teuchos::ParameterList>(entry), key, depth + 1, all, out);
    } else {
      out << indent << "  <Parameter name=\"" << detail::xmlEscaped(key) << "\" type=\"" << entry.getAny(false).typeName()
          << "\" value=\"" << detail::xmlEscaped(valueText(entry)) << "\"/>\n";
    }
  }
  out << indent << "</ParameterList>\n";
}

}  // namespace

std::string defaultsXml(bool all) {
  std::ostringstream out;
  if (all)
    out << "<!-- Every parameter of Signorini with its default value and documentation.\n"
           "     Generated by the command: signorini (double dash)defaults=all; tests/driver checks that\n"
           "     it is current. -->\n";
  else
    out << "<!-- The common parameters of Signorini with their defaults and documentation; the\n"
           "     expert ones too: signorini (double dash)defaults=all, or xml/defaults.xml. -->\n";
  writeDocumented(validTopLevelParameters(), "Signorini", 0, all, out);
  return out.str();
}

Teuchos::ParameterList validTopLevelParameters() {
  Teuchos::ParameterList p("Signorini");
  p.set("Problem", validProblemParameters(), "The contact problem");
  p.set("Solver", InteriorPointSolver::validParameters(), "The interior point solver");
  p.set("Output", outputParameters(), "What the run writes");
  return p;
}

Teuchos::ParameterList readParameterFile(const std::string& path, const Comm& comm) {
  std::string text, error;
  if (comm.getRank() == 0) {
    std::ifstream in(path);
    if (!in) {
      error = "cannot open parameter file " + path;
    } else {
      std::ostringstream s;
      s << in.rdbuf();
      text = s.str();
    }
  }
  // Broadcast the error (or the text) so every rank fails, or parses, alike.
  int sizes[2] = {static_cast<int>(error.size()), static_cast<int>(text.size())};
  Teuchos::broadcast(comm, 0, 2, sizes);
  error.resize(sizes[0]);
  text.resize(sizes[1]);
  if (sizes[0]) Teuchos::broadcast(comm, 0, sizes[0], error.data());
  if (!error.empty()) throw InputError(error);
  if (sizes[1]) Teuchos::broadcast(comm, 0, sizes[1], text.data());
  return parseParameterXml(text, path);
}

Teuchos::ParameterList parseParameterXml(const std::string& text, const std::string& path) {
  try {
    return *Teuchos::getParametersFromXmlString(text);
  } catch (const std::exception& e) {
    throw InputError(path + ": not a valid Teuchos XML parameter list: " + e.what());
  }
}

void applyOverride(Teuchos::ParameterList& list, const std::string& assignment,
                   const Teuchos::ParameterList& valid) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set \"" + assignment + "\": expected \"Sublist/name=value\"");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  Teuchos::ParameterList* target = &list;
  const Teuchos::ParameterList* validTarget = &valid;
  std::size_t start = 0;
  for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1) {
    const std::string name = path.substr(start, slash - start);
    target = &target->sublist(name);
    if (validTarget && validTarget->isSublist(name))
      validTarget = &validTarget->sublist(name);
    else if (validTarget && validTarget->isSublist(kAnyNameSublist))
      validTarget = &validTarget->sublist(kAnyNameSublist);
    else
      validTarget = nullptr;
  }
  const std::string name = path.substr(start);
  const Teuchos::ParameterEntry* model = nullptr;
  if (validTarget && validTarget->isParameter(name)) model = validTarget->getEntryPtr(name);
  else if (target->isParameter(name)) model = target->getEntryPtr(name);
  target->setEntry(name, parseLike(model, text, path));
}

namespace {

// Creates the output directory on rank 0 and writes a probe file in it, so that a directory
// that cannot hold the results stops the run before the mesh is built. Collective.
void checkOutputDirectory(const std::string& directory, const Comm& comm) {
  detail::runOnRoot(comm, [&] {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    const std::string probe = directory + "/.signorini-write-test";
    if (!error && std::ofstream(probe).good()) {
      std::filesystem::remove(probe, error);
      return;
    }
    const std::string what = error ? "created (" + error.message() + ")" : "written";
    throw InputError("output directory \"" + directory + "\" cannot be " + what +
                     "; choose another with --output or Output/directory");
  });
}

// True on every rank if the solution and the multipliers are finite everywhere.
bool isFinite(const SolveResult& result) {
  return !result.v.is_null() && !result.lambda.is_null() && std::isfinite(result.v->norm1()) &&
         std::isfinite(result.lambda->norm1());
}

void append(ContactPressureSamples& to, const ContactPressureSamples& from) {
  to.dim = from.dim;
  to.points.insert(to.points.end(), from.points.begin(), from.points.end());
  to.weights.insert(to.weights.end(), from.weights.begin(), from.weights.end());
  to.pressures.insert(to.pressures.end(), from.pressures.begin(), from.pressures.end());
}

// Each contact pair's recovered pressure and statistics (logged when there are several; the
// totals always), contact.csv and the solution files, as Output asks; the statistics go into
// `summary` (none without contact). Collective.
void writeSolutionOutputs(const AssembledProblem& problem, const SolveResult& result,
                          const Teuchos::ParameterList& output, const std::string& directory, std::ostream& out,
                          RunSummary& summary) {
  const ProblemDefinition& def = problem.definition;
  const Comm& comm = *problem.qp.b->getMap()->getComm();
  const RCP<const Vector> active = activeIndicator(problem.qp, *result.v, *result.lambda);
  const bool writeSolutionFiles = output.get<bool>("write solution");
  if (problem.qp.d->getGlobalLength() == 0) {
    if (writeSolutionFiles) writeSolution(problem, result, {}, directory);
    return;
  }
  std::vector<std::unique_ptr<ContactPressure>> recoveries;
  std::vector<RCP<Vector>> pressures;
  std::vector<ContactFields> fields;
  std::vector<ContactStatistics> statistics;
  ContactPressureSamples samples;
  for (std::size_t p = 0; p < def.contacts.size(); ++p) {
    const ContactPair& pair = def.contacts[p];
    recoveries.push_back(std::make_unique<ContactPressure>(*problem.space, def, problem.qp.A->getRangeMap(), p));
    const ContactPressure& recovery = *recoveries.back();
    pressures.push_back(recovery.recover(choice<PressureRecovery>(output, "contact pressure"), *result.lambda, *active));
    fields.push_back({recovery, *pressures.back(), *active});
    statistics.push_back(
        contactStatistics(recovery, *pressures.back(), *problem.qp.A, *result.lambda, *active, pair.obstacleDirection));
    summary.contactPairs.push_back({pair.name, pair.boundary, pair.masterBoundary, statistics.back()});
    if (comm.getRank() == 0 && def.contacts.size() > 1)
      logContact(statistics.back(), out, "Contact pair \"" + pair.name + "\"");
    if (output.get<bool>("write contact samples")) append(samples, recovery.samples(*pressures.back()));
  }
  summary.contact = combinedStatistics(statistics);
  if (comm.getRank() == 0) logContact(*summary.contact, out, def.contacts.size() > 1 ? "Contact, all pairs" : "Contact");
  if (output.get<bool>("write contact samples")) writeContactSamples(samples, comm, directory + "/contact.csv");
  if (writeSolutionFiles) writeSolution(problem, result, fields, directory);
}

}  // namespace

namespace {

// The vertex counts of the grids given to the geometric multigrid, finest first (the
// preconditioner may take fewer); empty without a grid.
std::vector<long long> gridVertexCounts(const MultigridInput& multigrid) {
  std::vector<long long> counts;
  for (auto grid = multigrid.grid; grid; grid = grid->coarser()) counts.push_back(grid->numVertices());
  return counts;
}

void logGridVertices(const std::vector<long long>& counts, std::ostream& out) {
  if (counts.empty()) return;
  out << "Signorini: geometric grids of";
  for (std::size_t k = 0; k < counts.size(); ++k) out << (k ? ", " : " ") << counts[k];
  out << " vertices\n";
}

// The user's parameters (the XML file, if any, then the --set overrides) and what the driver
// reads of them: each list is validated once, by its reader. The top level and Output here;
// Solver by the solver, made here, so that its mistakes stop the run before anything is built;
// Problem by buildProblem, before the mesh. The output directory is checked here too.
struct RunParameters {
  Teuchos::ParameterList user, output;
  std::optional<InteriorPointSolver> solver;
  std::string directory;
};

RunParameters runParameters(const CommandLine& cl, const Comm& comm) {
  RunParameters run;
  const Teuchos::ParameterList valid = validTopLevelParameters();
  if (!cl.input.empty()) run.user = readParameterFile(cl.input, comm);
  for (const std::string& assignment : cl.overrides) applyOverride(run.user, assignment, valid);
  Teuchos::ParameterList topLevel = run.user, validTopLevel = valid;
  for (const char* readElsewhere : {"Problem", "Solver"}) {
    validTopLevel.set(readElsewhere, Teuchos::ParameterList());
    if (topLevel.isSublist(readElsewhere)) topLevel.set(readElsewhere, Teuchos::ParameterList());
  }
  run.output = validatedParameters(topLevel, validTopLevel, "").sublist("Output");
  run.solver.emplace(run.user.sublist("Solver"));
  run.directory = cl.output.empty() ? run.output.get<std::string>("directory") : cl.output;
  checkOutputDirectory(run.directory, comm);
  return run;
}

// One solve with the iteration log on rank 0, recorded into `record`; its time is the
// slowest rank's.
SolveResult solveLogged(const ContactQP& qp, const MultigridInput& multigrid, const InteriorPointSolver& solver,
                        std::ostream& out, SolveRecorder& record, double& seconds) {
  const Comm& comm = *qp.Q->getDomainMap()->getComm();
  IterationLog log(out, comm.getRank() == 0);
  ObserverList observers{&log, &record};
  Teuchos::Time solveTime("solve");
  solveTime.start(true);
  SolveResult result;
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::solve);
    result = solver.solve(qp, multigrid, nullptr, &observers);
  }
  seconds = maxOverRanks(comm, solveTime.stop());
  return result;
}

// The memory figures of `summary`, then summary.json (and --summary) and history.csv on rank 0.
void writeRunSummary(RunSummary& summary, const CommandLine& cl, const Teuchos::ParameterList& output,
                     const std::string& directory, bool solutionWritten, const Comm& comm, std::ostream& out) {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double rss = usage.ru_maxrss / 1024.0;  // Linux reports KiB
  summary.peakMemoryMiBMaxRank = maxOverRanks(comm, rss);
  summary.peakMemoryMiBAllRanks = sumOverRanks(comm, rss);
  summary.hugePages = onEveryRank(comm, detail::mallocAsksForHugePages());
  if (comm.getRank() != 0) return;
  writeSummaryJson(summary, directory + "/summary.json");
  if (!cl.summary.empty()) writeSummaryJson(summary, cl.summary);
  if (output.get<bool>("write history")) writeHistoryCsv(*summary.record, directory + "/history.csv");
  out << "Results in " << directory << "/ (summary.json" << (output.get<bool>("write history") ? ", history.csv" : "")
      << (solutionWritten ? ", solution.pvtu" : "") << ")\n";
}

// signorini --qp DIR: the QP of DIR solved with the Solver list, summary.json and history.csv
// written (no mesh: no solution files).
SolveResult runQP(const CommandLine& cl, const RCP<const Comm>& comm, std::ostream& out) {
  Teuchos::Time total("total");
  total.start(true);
  const RunParameters run = runParameters(cl, *comm);
  Teuchos::Time setup("setup");
  setup.start(true);
  const QPFromFiles files = readQP(cl.qp, comm);
  const ContactQP& qp = files.qp;
  const double setupSeconds = maxOverRanks(*comm, setup.stop());
  const long long n = qp.b->getGlobalLength(), m = qp.d->getGlobalLength();
  if (comm->getRank() == 0)
    out << "Signorini: QP of " << cl.qp << "/: n = " << n << ", m = " << m << ", " << files.multigrid.blockSize
        << " unknowns per node, " << comm->getSize() << " MPI rank(s); read in " << setupSeconds << " s\n";
  if (comm->getRank() == 0 && comm->getSize() > 1)
    out << "  nodes " << (files.repartitioned ? "repartitioned by METIS" : "in file order") << ": "
        << 100 * files.crossRankCouplings << "% of Q's node couplings between ranks (file order: "
        << 100 * files.crossRankCouplingsInFileOrder << "%)\n";
  if (comm->getRank() == 0) logGridVertices(gridVertexCounts(files.multigrid), out);
  RunSummary summary;
  SolveRecorder record;
  SolveResult result = solveLogged(qp, files.multigrid, *run.solver, out, record, summary.solveSeconds);
  if (m > 0 && isFinite(result)) {
    summary.contact = contactStatistics(qp, files.multigrid, *result.v, *result.lambda);
    if (comm->getRank() == 0) logContact(*summary.contact, out);
  }
  summary.problem = "qp:" + cl.qp;
  summary.method = run.solver->parameters().get<std::string>("method");
  summary.dim = files.multigrid.blockSize;
  summary.ranks = comm->getSize();
  summary.n = n;
  summary.m = m;
  summary.result = &result;
  summary.record = &record;
  summary.setupSeconds = setupSeconds;
  summary.gridVertices = gridVertexCounts(files.multigrid);
  summary.totalSeconds = maxOverRanks(*comm, total.stop());
  writeRunSummary(summary, cl, run.output, run.directory, false, *comm, out);
  return result;
}

}  // namespace

SolveResult runApplication(const CommandLine& cl, const RCP<const Comm>& comm, std::ostream& out) {
  if (!cl.qp.empty()) return runQP(cl, comm, out);
  Teuchos::Time total("total");
  total.start(true);
  const bool root = comm->getRank() == 0;
  RunParameters run = runParameters(cl, *comm);
  const std::string& directory = run.directory;

  const std::string baseDirectory = std::filesystem::path(cl.input).parent_path().string();
  // The export writes Q as a matrix.
  BuildRecorder built;
  AssembledProblem problem =
      buildProblem(run.user.sublist("Problem"), comm, baseDirectory.empty() ? "." : baseDirectory,
                   cl.exportQp.empty() ? StiffnessNeed::AsConfigured : StiffnessNeed::Assembled, &built);
  const ProblemDefinition& def = problem.definition;
  const long long n = problem.qp.b->getGlobalLength(), m = problem.qp.d->getGlobalLength();
  const DistributedSpace& space = distributedSpace(*problem.space);
  const double serialMeshMiB = space.serialPhaseBytes() / (1024.0 * 1024.0);
  if (root) {
    out << "Signorini: problem \"" << def.name << "\": d = " << def.dim << ", P" << def.degree << ", "
        << problem.space->numGlobalCells() << " cells (";
    if (space.serialPhaseBytes() > 0)
      out << "serial mesh phase on rank 0: " << serialMeshMiB << " MiB of arrays, ";
    else
      out << "each rank made its own part, ";
    out << "setup peak resident on rank 0 +" << built.setupPeakMiB[0] << " MiB), n = " << n << ", m = " << m
        << ", " << comm->getSize() << " MPI rank(s); setup " << built.setupSeconds << " s, assembly "
        << built.assemblySeconds << " s\n";
    for (const std::string& note : built.notes) out << "Signorini: " << note << "\n";
    logGridVertices(gridVertexCounts(problem.multigrid), out);
  }

  if (!cl.exportQp.empty()) {
    writeQP(problem.qp, problem.multigrid, cl.exportQp);
    // The mesh's P1 cells: a run on these files makes the same geometric multigrid levels of
    // them (the P_k -> P1 step, the Delaunay coarse grids below) as of a mesh read as is.
    detail::writeCells(space, cl.exportQp);
    if (root) out << "Exported Q, b, A, d, coords, cells to " << cl.exportQp << "/\n";
  }

  const Teuchos::ParameterList& output = run.output;
  if (output.get<bool>("write solution"))
    detail::checkOutputSpace(directory, detail::estimatedSolutionBytes(*problem.space), *comm);
  RunSummary summary;
  SolveRecorder record;
  SolveResult result = solveLogged(problem.qp, problem.multigrid, *run.solver, out, record, summary.solveSeconds);

  const bool finite = isFinite(result);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: output"));
    const detail::CommunicationPhaseScope phase(detail::CommunicationPhase::output);
    if (finite)
      writeSolutionOutputs(problem, result, output, directory, out, summary);
    else if (root)
      out << "Solution not written: the solve ended in non-finite numbers (" << toString(result.status) << ")\n";
    total.stop();
    summary.problem = def.name;
    summary.method = run.solver->parameters().get<std::string>("method");
    summary.dim = def.dim;
    summary.degree = def.degree;
    summary.ranks = comm->getSize();
    summary.nx = def.meshType == "box" ? def.cells[0] : 0;
    summary.n = n;
    summary.m = m;
    summary.result = &result;
    summary.record = &record;
    summary.setupSeconds = built.setupSeconds;
    summary.assemblySeconds = built.assemblySeconds;
    summary.totalSeconds = maxOverRanks(*comm, total.totalElapsedTime());
    summary.serialMeshMiB = serialMeshMiB;
    summary.serialMeshPeakMiB = built.setupPeakMiB[0];
    summary.setupPeakMiBPerRank = built.setupPeakMiB;
    summary.notes = built.notes;
    summary.gridVertices = gridVertexCounts(problem.multigrid);
    writeRunSummary(summary, cl, output, directory, finite && output.get<bool>("write solution"), *comm, out);
  }
  Teuchos::TimeMonitor::summarize(comm.ptr(), out, false, true, false);
  return result;
}

}  // namespace signorini
