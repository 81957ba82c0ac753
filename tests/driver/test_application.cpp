// The XML-configured application: shipped inputs validate, mistakes get clear messages,
// --set works, outputs match the solver's counters.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "core/ParameterValidation.hpp"
#include "driver/Application.hpp"
#include "problem/MemoryEstimate.hpp"
#include "signorini/core/Error.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using signorini::testing::sourceDir;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError that `f` throws ("" if none).
template <class F>
std::string inputErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Teuchos::ParameterList fileList(const std::string& relative) {
  return readParameterFile(sourceDir() + "/" + relative, *Tpetra::getDefaultComm());
}

TEST(Application, EveryShippedXmlValidates) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  int count = 0;
  for (const auto& dir : {"xml", "xml/paper", "xml/family"})
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir() + "/" + dir)) {
      if (entry.path().extension() != ".xml") continue;
      const std::string relative = std::string(dir) + "/" + entry.path().filename().string();
      EXPECT_EQ(inputErrorOf([&] { validatedParameters(fileList(relative), valid, ""); }), "") << relative;
      ++count;
    }
  EXPECT_GE(count, 24);
}

// The input shown in the README is problem M, and solves as xml/paper/M.xml does.
TEST(Application, ReadmeInputExampleIsProblemM) {
  auto comm = Tpetra::getDefaultComm();
  const std::string readme = readFile(sourceDir() + "/README.md");
  const std::size_t begin = readme.find("```xml\n"), end = readme.find("```", begin + 7);
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string dir = std::string(binary ? binary : "/tmp") + "/app-readme-np" + std::to_string(comm->getSize());
  if (comm->getRank() == 0) {
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/example.xml") << readme.substr(begin + 7, end - begin - 7);
  }
  comm->barrier();
  std::ostringstream log;
  CommandLine example, paper;
  example.input = dir + "/example.xml";
  example.output = dir + "/example";
  paper.input = sourceDir() + "/xml/paper/M.xml";
  paper.output = dir + "/M";
  const SolveResult fromReadme = runApplication(example, comm, log);
  const SolveResult fromPaper = runApplication(paper, comm, log);
  ASSERT_TRUE(fromReadme.converged()) << log.str();
  EXPECT_NEAR(fromReadme.objective, fromPaper.objective, 1e-12 * std::abs(fromPaper.objective));
}

TEST(Application, DefaultsXmlIsCurrent) {
  EXPECT_EQ(readFile(sourceDir() + "/xml/defaults.xml"), defaultsXml(true))
      << "regenerate it: build/bin/signorini --defaults=all > xml/defaults.xml, then scripts/parameters_md.py";
}

// --defaults leaves out the expert parameters; --defaults=all shows them, documented as
// such, and both are valid parameter lists.
TEST(Application, DefaultsHideExpertParameters) {
  const std::string common = defaultsXml(false), all = defaultsXml(true);
  EXPECT_EQ(common.find("Expert:"), std::string::npos);
  EXPECT_NE(all.find("Expert:"), std::string::npos);
  EXPECT_EQ(common.find("\"gamma: max\""), std::string::npos);
  EXPECT_NE(all.find("\"gamma: max\""), std::string::npos);
  EXPECT_NE(common.find("\"kkt: tolerance\""), std::string::npos);
  const Teuchos::ParameterList valid = validTopLevelParameters();
  for (const std::string& text : {common, all}) {
    const auto list = Teuchos::getParametersFromXmlString(text);
    EXPECT_EQ(inputErrorOf([&] { validatedParameters(*list, valid, ""); }), "");
  }
}

// How many entries of `list` and its sublists are marked expert, and whether any documentation
// carries the mark as text instead.
void countExpertMarks(const Teuchos::ParameterList& list, int& marked, int& inText) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Teuchos::ParameterEntry& entry = list.entry(it);
    marked += isExpert(entry) ? 1 : 0;
    inText += entry.docString().rfind("Expert", 0) == 0 ? 1 : 0;
    if (entry.isList()) countExpertMarks(Teuchos::getValue<Teuchos::ParameterList>(entry), marked, inText);
  }
}

// Expert parameters carry a mark, not a word in their documentation, and keep it through
// validation; a marked parameter validates, and reads, as it would unmarked.
TEST(Application, ExpertParametersAreMarked) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  int marked = 0, inText = 0;
  countExpertMarks(valid, marked, inText);
  EXPECT_GT(marked, 20);
  EXPECT_EQ(inText, 0);
  EXPECT_TRUE(isExpert(valid.sublist("Solver").getEntry("gamma: max")));
  EXPECT_FALSE(isExpert(valid.sublist("Solver").getEntry("kkt: tolerance")));

  Teuchos::ParameterList user;
  user.sublist("Solver").set("gamma: max", 0.9);
  user.sublist("Solver").sublist("Preconditioner").set("contact correction: blocks", "gathered");
  const Teuchos::ParameterList validated = validatedParameters(user, valid, "");
  EXPECT_TRUE(isExpert(validated.sublist("Solver").getEntry("gamma: max")));
  EXPECT_TRUE(isExpert(validated.sublist("Solver").sublist("Preconditioner").getEntry("contact correction: blocks")));
  EXPECT_EQ(validated.sublist("Solver").get<double>("gamma: max"), 0.9);

  user.sublist("Solver").set("gamma: max", 2.0);
  const std::string message = inputErrorOf([&] { validatedParameters(user, valid, ""); });
  EXPECT_NE(message.find("Solver/gamma: max"), std::string::npos) << message;
  EXPECT_NE(message.find("a number from"), std::string::npos) << message;
}

TEST(Application, MisspelledNamesGetAHint) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  Teuchos::ParameterList user;
  user.sublist("Solver").set("methd", "primal");
  const std::string message = inputErrorOf([&] { validatedParameters(user, valid, ""); });
  EXPECT_NE(message.find("Solver/methd"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean \"method\""), std::string::npos) << message;

  Teuchos::ParameterList nested;
  nested.sublist("Problem").sublist("Contact").set("gap: valeu", 0.1);
  const std::string nestedMessage = inputErrorOf([&] { validatedParameters(nested, valid, ""); });
  EXPECT_NE(nestedMessage.find("Problem/Contact/gap: valeu"), std::string::npos) << nestedMessage;
  EXPECT_NE(nestedMessage.find("did you mean \"gap: value\""), std::string::npos) << nestedMessage;
}

// A sublist the list does not have is named as one, its clause ended before the valid names.
TEST(Application, UnknownSublistIsNamedAsOne) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  Teuchos::ParameterList user;
  user.sublist("Solver").sublist("Newton").set("maximum iterations", 0);
  const std::string message = inputErrorOf([&] { validatedParameters(user, valid, ""); });
  EXPECT_NE(message.find("Solver/Newton: unknown sublist. Valid names here: "), std::string::npos) << message;
  EXPECT_NE(message.find("\"Krylov\""), std::string::npos) << message;
}

TEST(Application, BadValuesNameTheParameterAndTheAcceptedRange) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  struct Case {
    std::function<void(Teuchos::ParameterList&)> set;
    std::string path, accepted;
  };
  const Case cases[] = {
      {[](auto& l) { l.sublist("Problem").set("element: degree", 4); }, "Problem/element: degree",
       "accepted: an integer from 1 to 3"},
      {[](auto& l) { l.sublist("Solver").set("method", "dual"); }, "Solver/method",
       "accepted: one of \"primal-dual\", \"primal\""},
      {[](auto& l) { l.sublist("Problem").set("material: poisson ratio", 0.49999); },
       "Problem/material: poisson ratio", "accepted: a number from -0.999 to 0.4999"},
      // A range rule holds whichever hierarchy reads the parameter.
      {[](auto& l) {
         auto& prec = l.sublist("Solver").sublist("Preconditioner");
         prec.set("hierarchy", "algebraic");
         prec.set("geometric: eigenvalue update steps", 2);
       },
       "Solver/Preconditioner/geometric: eigenvalue update steps", "accepted: 0, or an integer from 3 to 1000"},
      {[](auto& l) { l.sublist("Solver").set("maximum iterations", "many"); }, "Solver/maximum iterations", "int"},
      {[](auto& l) { l.sublist("Solver").sublist("Preconditioner").set("amg of H: rebuild tolerance", 1.5); },
       "Solver/Preconditioner/amg of H: rebuild tolerance", "accepted: \"auto\", or a number from 0 to 1"},
      {[](auto& l) { l.sublist("Solver").sublist("Preconditioner").set("amg of H: rebuild tolerance", "often"); },
       "Solver/Preconditioner/amg of H: rebuild tolerance", "accepted: \"auto\", or a number from 0 to 1"},
  };
  for (const Case& c : cases) {
    Teuchos::ParameterList user;
    c.set(user);
    const std::string message = inputErrorOf([&] { validatedParameters(user, valid, ""); });
    EXPECT_NE(message.find(c.path), std::string::npos) << message;
    EXPECT_NE(message.find(c.accepted), std::string::npos) << message;
  }
  // Mistakes found while building the problem name their place too.
  Teuchos::ParameterList problem = signorini::testing::boxProblem(2, 4, 1);
  problem.set("body force: y", "-(1 + ");
  const std::string message = inputErrorOf([&] { buildProblem(problem, Tpetra::getDefaultComm()); });
  EXPECT_NE(message.find("Problem/body force: y"), std::string::npos) << message;
  problem.set("body force: y", "0");
  problem.sublist("Contact").set("boundary", "bottom");
  const std::string boundary = inputErrorOf([&] { buildProblem(problem, Tpetra::getDefaultComm()); });
  EXPECT_NE(boundary.find("ymin"), std::string::npos) << boundary;  // lists the known names
}

TEST(Application, SetOverridesTakeTheTypeOfTheParameter) {
  const Teuchos::ParameterList valid = validTopLevelParameters();
  Teuchos::ParameterList user;
  applyOverride(user, "Solver/kkt: tolerance=1e-6", valid);
  applyOverride(user, "Problem/element: degree=2", valid);
  applyOverride(user, "Problem/mesh: cells={4, 8}", valid);
  applyOverride(user, "Problem/Dirichlet/ymax/displacement: y=-0.1*x", valid);
  applyOverride(user, "Solver/Preconditioner/MueLu/smoother: sweeps=3", valid);
  EXPECT_EQ(user.sublist("Solver").get<double>("kkt: tolerance"), 1e-6);
  EXPECT_EQ(user.sublist("Problem").get<int>("element: degree"), 2);
  EXPECT_EQ(user.sublist("Problem").get<Teuchos::Array<int>>("mesh: cells"), Teuchos::Array<int>(Teuchos::tuple<int>(4, 8)));
  EXPECT_EQ(user.sublist("Problem").sublist("Dirichlet").sublist("ymax").get<std::string>("displacement: y"), "-0.1*x");
  EXPECT_EQ(user.sublist("Solver").sublist("Preconditioner").sublist("MueLu").get<int>("smoother: sweeps"), 3);
  EXPECT_NO_THROW(validatedParameters(user, valid, ""));
  // "auto" or a number: --set gives the text, an XML file may give a double; both are read as numbers.
  const char* tolerance = "amg of H: rebuild tolerance";
  applyOverride(user, std::string("Solver/Preconditioner/") + tolerance + "=0.5", valid);
  EXPECT_EQ(autoOrNumber(validatedParameters(user, valid, "").sublist("Solver").sublist("Preconditioner"), tolerance, 0),
            0.5);
  user.sublist("Solver").sublist("Preconditioner").set(tolerance, 0.25);
  EXPECT_EQ(autoOrNumber(validatedParameters(user, valid, "").sublist("Solver").sublist("Preconditioner"), tolerance, 0),
            0.25);
  user.sublist("Solver").sublist("Preconditioner").remove(tolerance);
  EXPECT_EQ(autoOrNumber(validatedParameters(user, valid, "").sublist("Solver").sublist("Preconditioner"), tolerance, 7),
            7.0);
  EXPECT_NE(inputErrorOf([&] { applyOverride(user, "Problem/element: degree=two", valid); }).find("int"),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { applyOverride(user, "no equals sign", valid); }), "");
}

TEST(Application, CommandLineErrorsShowTheUsage) {
  const char* unknown[] = {"signorini", "in.xml", "--frobnicate"};
  EXPECT_NE(inputErrorOf([&] { CommandLine::parse(3, unknown); }).find("usage"), std::string::npos);
  const char* missing[] = {"signorini", "in.xml", "--output"};
  EXPECT_NE(inputErrorOf([&] { CommandLine::parse(3, missing); }).find("--output needs a value"), std::string::npos);
  const char* none[] = {"signorini"};
  EXPECT_NE(inputErrorOf([&] { CommandLine::parse(1, none); }).find("no input file"), std::string::npos);
  const char* full[] = {"signorini", "a.xml", "--output", "o", "--set", "Solver/method=primal", "--export-qp", "q"};
  const CommandLine cl = CommandLine::parse(8, full);
  EXPECT_EQ(cl.input, "a.xml");
  EXPECT_EQ(cl.output, "o");
  EXPECT_EQ(cl.exportQp, "q");
  ASSERT_EQ(cl.overrides.size(), 1u);
  const char* joined[] = {"signorini", "a.xml", "--output=o", "--set=Solver/method=primal", "--defaults=all"};
  const CommandLine withEquals = CommandLine::parse(5, joined);
  EXPECT_EQ(withEquals.output, "o");
  ASSERT_EQ(withEquals.overrides.size(), 1u);
  EXPECT_EQ(withEquals.overrides[0], "Solver/method=primal");
  EXPECT_TRUE(withEquals.allDefaults);
  const char* flagWithValue[] = {"signorini", "a.xml", "--version=2"};
  EXPECT_NE(inputErrorOf([&] { CommandLine::parse(3, flagWithValue); }).find("takes no value"), std::string::npos);
}

TEST(Application, MissingInputFileFailsOnEveryRank) {
  const std::string message =
      inputErrorOf([] { readParameterFile("/nonexistent/problem.xml", *Tpetra::getDefaultComm()); });
  EXPECT_NE(message.find("/nonexistent/problem.xml"), std::string::npos);
}

// An output directory that cannot be created stops the run before the problem is built.
TEST(Application, UnwritableOutputDirectoryStopsTheRunBeforeTheSolve) {
  auto comm = Tpetra::getDefaultComm();
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string file = std::string(binary ? binary : "/tmp") + "/app-test-file-np" + std::to_string(comm->getSize());
  if (comm->getRank() == 0) std::ofstream(file) << "a file, not a directory\n";
  comm->barrier();
  CommandLine cl;
  cl.input = sourceDir() + "/xml/paper/M.xml";
  cl.output = file + "/out";
  std::ostringstream log;
  const std::string message = inputErrorOf([&] { runApplication(cl, comm, log); });
  EXPECT_NE(message.find("output directory \"" + cl.output + "\" cannot be created"), std::string::npos) << message;
  EXPECT_EQ(log.str(), "");  // nothing built, nothing solved
}

// A directory of its own for a test on this rank count, in the build tree when known.
std::string scratchDirectory(const std::string& name, const Comm& comm) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  return std::string(binary ? binary : "/tmp") + "/" + name + "-np" + std::to_string(comm.getSize());
}

// Problem C (P2 on a box) runs matrix-free by default; --export-qp assembles Q for its file.
TEST(Application, ExportAssemblesAStiffnessThatIsMatrixFreeByDefault) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDirectory("app-export", *comm);
  CommandLine cl;
  cl.input = sourceDir() + "/xml/paper/C.xml";
  cl.output = dir + "/out";
  cl.exportQp = dir + "/qp";
  std::ostringstream log;
  ASSERT_TRUE(runApplication(cl, comm, log).converged());
  comm->barrier();
  if (comm->getRank() == 0) {
    EXPECT_NE(readFile(dir + "/qp/Q.mtx").find("%%MatrixMarket matrix coordinate"), std::string::npos);
  }
}

// A whole run of problem M: outputs exist and summary.json carries the solver's counters.
TEST(Application, RunWritesSummaryHistoryAndQp) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDirectory("app-test", *comm);
  CommandLine cl;
  cl.input = sourceDir() + "/xml/paper/M.xml";
  cl.output = dir + "/out";
  cl.summary = dir + "/copy.json";
  cl.exportQp = dir + "/qp";
  std::ostringstream log;
  const SolveResult r = runApplication(cl, comm, log);
  ASSERT_TRUE(r.converged()) << r.message;
  comm->barrier();
  if (comm->getRank() != 0) return;
  const std::string summary = readFile(dir + "/out/summary.json");
  EXPECT_EQ(summary, readFile(dir + "/copy.json"));
  auto has = [&](const std::string& field) { return summary.find(field) != std::string::npos; };
  EXPECT_TRUE(has("\"outer_iterations\": " + std::to_string(r.outerIterations) + ","));
  EXPECT_TRUE(has("\"gradient_evaluations\": " + std::to_string(r.gradientEvaluations) + ","));
  EXPECT_TRUE(has("\"function_evaluations\": " + std::to_string(r.functionEvaluations) + ","));
  EXPECT_TRUE(has("\"krylov_iterations\": " + std::to_string(r.krylovIterations) + ","));
  EXPECT_TRUE(has("\"max_krylov_per_newton\": " + std::to_string(r.maxKrylovPerNewton) + ","));
  EXPECT_TRUE(has("\"preconditioner_setups\": " + std::to_string(r.preconditionerSetups) + ","));
  {  // the multigrid's matrix entries per level, finest first, and their sum over the first
    ASSERT_FALSE(r.multigridNonzeros.empty());
    std::string entries;
    for (long long count : r.multigridNonzeros) entries += (entries.empty() ? "" : ", ") + std::to_string(count);
    EXPECT_TRUE(has("\"multigrid_nonzeros\": [" + entries + "],")) << summary;
    EXPECT_NE(log.str().find("multigrid: matrix entries per level " + entries + " (operator complexity "),
              std::string::npos)
        << log.str();
    const std::size_t at = summary.find("\"operator_complexity\": ");
    ASSERT_NE(at, std::string::npos);
    const double complexity = std::stod(summary.substr(at + std::string("\"operator_complexity\": ").size()));
    double sum = 0;
    for (long long count : r.multigridNonzeros) sum += static_cast<double>(count);
    EXPECT_NEAR(complexity, sum / static_cast<double>(r.multigridNonzeros[0]), 1e-12);
    EXPECT_GE(complexity, 1.0);
  }
  EXPECT_TRUE(has("\"n\": 242,"));
  EXPECT_TRUE(has("\"m\": 11,"));
  EXPECT_TRUE(has("\"converged\": true"));
  EXPECT_TRUE(has("\"ranks\": " + std::to_string(comm->getSize()) + ","));
  EXPECT_TRUE(has("\"time\": {\"setup\": "));
  EXPECT_TRUE(has("\"memory_mib\": {\"max_rank\": "));
  EXPECT_TRUE(has("\"serial_mesh_mib\": "));
  EXPECT_TRUE(has("\"serial_mesh_peak_rss_mib\": "));
  EXPECT_TRUE(has("\"notes\": [],"));  // a box is made as asked
  // The box's geometric grids, the finest one of the mesh's 121 vertices, and the same in the log.
  EXPECT_TRUE(has("\"grid_vertices\": [121, ")) << summary;
  EXPECT_NE(log.str().find("geometric grids of 121, "), std::string::npos) << log.str();
  {  // one setup peak per rank
    const std::size_t at = summary.find("\"setup_peak_rss_mib\": [");
    ASSERT_NE(at, std::string::npos);
    const std::string list = summary.substr(at, summary.find(']', at) - at);
    EXPECT_EQ(std::count(list.begin(), list.end(), ','), comm->getSize() - 1) << list;
  }
  // Problem M is a box: every rank makes its own part, rank 0 holds no global mesh.
  EXPECT_TRUE(has("\"serial_mesh_mib\": 0,"));
  EXPECT_NE(log.str().find("each rank made its own part"), std::string::npos);
  // One history row per main iteration of the primal-dual method, plus the header.
  std::ifstream history(dir + "/out/history.csv");
  int lines = 0;
  for (std::string line; std::getline(history, line);) ++lines;
  EXPECT_EQ(lines, r.outerIterations + 1);
  // ParaView output: one piece per rank with the named fields (tests/io checks their values).
  const std::string pvtu = readFile(dir + "/out/solution.pvtu");
  for (const char* field : {"displacement", "contact pressure", "contact force", "gap", "active", "von Mises stress",
                            "rank"})
    EXPECT_NE(pvtu.find(std::string("Name=\"") + field + "\""), std::string::npos) << field;
  for (int r = 0; r < comm->getSize(); ++r)
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/solution_" + std::to_string(r) + ".vtu")) << r;
  for (const char* file : {"Q.mtx", "b.mtx", "A.mtx", "d.mtx", "coords.mtx"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/qp/" + file)) << file;
  // The log has the table header and the final status line.
  EXPECT_NE(log.str().find("stat"), std::string::npos);
  EXPECT_NE(log.str().find("converged after"), std::string::npos);
}

// The number after "key": in a summary.json text (NaN if absent).
double jsonNumber(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

// The run of `input` with `overrides` that exports its QP into dir/qp, and the run on those
// files (outputs in dir/direct and dir/imported); both must converge to the same optimum.
std::pair<SolveResult, SolveResult> exportedAndImported(const std::string& input,
                                                        const std::vector<std::string>& overrides,
                                                        const std::string& dir) {
  auto comm = Tpetra::getDefaultComm();
  CommandLine exporting;
  exporting.input = input;
  exporting.output = dir + "/direct";
  exporting.exportQp = dir + "/qp";
  exporting.overrides = overrides;
  std::ostringstream log;
  const SolveResult direct = runApplication(exporting, comm, log);
  CommandLine importing;
  importing.qp = dir + "/qp";
  importing.output = dir + "/imported";
  const SolveResult imported = runApplication(importing, comm, log);
  EXPECT_TRUE(direct.converged() && imported.converged()) << imported.message;
  EXPECT_LT(std::abs(direct.objective - imported.objective), 1e-10 * std::abs(direct.objective));
  return {direct, imported};
}

// signorini --qp: the QP that --export-qp wrote, solved to the same optimum, with
// summary.json and history.csv and no solution files (there is no mesh).
TEST(Application, ExportedQPSolvesToTheSameOptimum) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDirectory("app-qp", *comm);
  const auto [direct, imported] = exportedAndImported(sourceDir() + "/xml/paper/H.xml", {}, dir);
  EXPECT_LE(std::abs(direct.outerIterations - imported.outerIterations), 1);
  comm->barrier();
  if (comm->getRank() != 0) return;
  const std::string summary = readFile(dir + "/imported/summary.json");
  EXPECT_NE(summary.find("\"outer_iterations\": " + std::to_string(imported.outerIterations) + ","), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/imported/history.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/imported/solution.pvtu"));
  // The contact force and active nodes from the files alone; the pressure needs the mesh.
  const std::string withMesh = readFile(dir + "/direct/summary.json");
  const double force = jsonNumber(withMesh, "normal_force");
  EXPECT_GT(force, 0.0);
  EXPECT_NEAR(jsonNumber(summary, "normal_force"), force, 1e-8 * force);
  EXPECT_EQ(jsonNumber(summary, "active_nodes"), jsonNumber(withMesh, "active_nodes"));
  EXPECT_NE(summary.find("\"peak_pressure\": null"), std::string::npos) << summary;
}

// A P2 problem's export carries its mesh's cells (cells.mtx): the run on the files takes the
// same P2 -> P1 step as the direct run, so the same iterations, Krylov ones included.
TEST(Application, ExportedP2QPKeepsItsMultigridStep) {
  const std::string dir = scratchDirectory("app-qp-p2", *Tpetra::getDefaultComm());
  const auto [direct, imported] = exportedAndImported(
      sourceDir() + "/examples/hertz/half-disk-2d.xml",
      {"Problem/element: degree=2", "Problem/mesh: size factor=3", "Output/write solution=false",
       "Output/write contact samples=false"},
      dir);
  EXPECT_EQ(imported.outerIterations, direct.outerIterations);
  EXPECT_EQ(imported.krylovIterations, direct.krylovIterations);
}

// A P1 problem on a Gmsh mesh read as is: the export's cells give the run on the files the
// direct run's Delaunay coarse grids, so the same iterations, Krylov ones included.
TEST(Application, ExportedP1QPKeepsItsCoarseGrids) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDirectory("app-qp-p1", *comm);
  const auto [direct, imported] = exportedAndImported(
      sourceDir() + "/examples/hertz/half-disk-2d.xml",
      {"Output/write solution=false", "Output/write contact samples=false"}, dir);
  EXPECT_EQ(imported.outerIterations, direct.outerIterations);
  EXPECT_EQ(imported.krylovIterations, direct.krylovIterations);
  comm->barrier();
  if (comm->getRank() != 0) return;
  const auto grids = [](const std::string& summary) {
    const std::size_t at = summary.find("\"grid_vertices\": [");
    return at == std::string::npos ? std::string() : summary.substr(at, summary.find(']', at) - at);
  };
  const std::string ofDirect = grids(readFile(dir + "/direct/summary.json"));
  EXPECT_NE(ofDirect.find(','), std::string::npos) << ofDirect << ": coarse grids below the P1 grid";
  EXPECT_EQ(grids(readFile(dir + "/imported/summary.json")), ofDirect);
}

TEST(Application, QPDirectoryAndExportExcludeEachOther) {
  const char* argv[] = {"signorini", "--qp", "a", "--export-qp", "b"};
  EXPECT_NE(inputErrorOf([&] { CommandLine::parse(5, argv); }).find("exclude each other"), std::string::npos);
  const char* alone[] = {"signorini", "--qp", "a"};
  EXPECT_EQ(inputErrorOf([&] { CommandLine::parse(3, alone); }), "");
}

}  // namespace

// Boundary conditions that cannot hold the body, or that contradict the contact, and data
// beyond double precision are bad input: one message that names the cause, before any
// output is written.
TEST(Application, BadPhysicsIsRefusedBeforeAnyOutput) {
  auto comm = Tpetra::getDefaultComm();
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::string dir = std::string(binary ? binary : "/tmp") + "/app-bad-physics-np" + std::to_string(comm->getSize());
  struct Case {
    std::vector<std::string> overrides;
    std::string expected;
  };
  const Case cases[] = {
      {{"Problem/Dirichlet/ymax/displacement: x="}, "the body is free to move by a translation along (1, 0)"},
      {{"Problem/Dirichlet/ymax/displacement: y=", "Problem/body force: y=1"},
       "the load pulls the body off the obstacle by a translation along (0, 1)"},
      {{"Problem/Contact/boundary=ymax"}, "Problem/Contact: 11 node(s) of the contact boundary \"ymax\""},
      // Finite data whose norms overflow double precision.
      {{"Problem/body force: y=-1e308"}, "Problem: the loads and prescribed displacements (largest entry 1e+306)"},
      {{"Problem/Contact/gap: value=1e200"}, "Problem: the gaps (largest entry 1e+200) overflow"},
  };
  for (const Case& c : cases) {
    CommandLine cl;
    cl.input = sourceDir() + "/xml/paper/M.xml";
    cl.output = dir;
    cl.overrides = c.overrides;
    std::ostringstream log;
    const std::string message = inputErrorOf([&] { runApplication(cl, comm, log); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    for (const char* file : {"summary.json", "solution.pvtu", "history.csv"})
      EXPECT_FALSE(std::filesystem::exists(dir + "/" + file)) << file << " after: " << message;
  }
  // Held by its contact alone (the top slides vertically), the body pressed down is solved.
  CommandLine cl;
  cl.input = sourceDir() + "/xml/paper/M.xml";
  cl.output = dir + "/held";
  cl.overrides = {"Problem/Dirichlet/ymax/displacement: y=", "Problem/body force: y=-1"};
  std::ostringstream log;
  EXPECT_TRUE(runApplication(cl, comm, log).converged()) << log.str();
}

// A problem far beyond the machine's memory stops before its mesh is made, with the numbers.
TEST(Application, ProblemThatCannotFitIsRefusedBeforeTheMesh) {
  auto comm = Tpetra::getDefaultComm();
  CommandLine cl;
  cl.input = sourceDir() + "/xml/paper/M.xml";
  cl.output = std::string(std::getenv("SIGNORINI_BINARY_DIR") ? std::getenv("SIGNORINI_BINARY_DIR") : "/tmp") +
              "/app-too-large-np" + std::to_string(comm->getSize());
  cl.overrides = {"Problem/mesh: cells={200000}"};
  std::ostringstream log;
  const std::string message = inputErrorOf([&] { runApplication(cl, comm, log); });
  EXPECT_NE(message.find("Problem: 8e+10 unknowns (P1, 2D) need at least"), std::string::npos) << message;
  EXPECT_NE(message.find("use fewer cells"), std::string::npos) << message;
  EXPECT_EQ(log.str(), "");
}

// The P1 grid refined at the nodes has as many unknowns as the P2 space: its stiffness and
// hierarchy count in the bound. A 3D P2 box sized for this machine's available memory fits
// matrix-free, and is refused with the refined grid, before its mesh is made.
TEST(Application, RefinedGridCountsInTheMemoryBound) {
  auto comm = Tpetra::getDefaultComm();
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kib = 0, available = 0;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") available = kib * 1024.0;
  if (available <= 0) GTEST_SKIP() << "no MemAvailable in /proc/meminfo";
  Teuchos::broadcast(*comm, 0, 1, &available);
  // Unknowns of the size where the matrix-free bound is about two thirds of the memory.
  const int nx = static_cast<int>(std::lround((std::cbrt(available / 1000.0 / 3.0) - 1.0) / 2.0));
  const double unknowns = signorini::boxMeshUnknowns(3, {nx, nx, nx}, 2);
  ASSERT_LT(signorini::minimumSolveBytes(unknowns, 3, 2, false), 0.8 * available);
  ASSERT_GT(signorini::minimumSolveBytes(unknowns, 3, 2, false, true), 1.3 * available);

  CommandLine cl;
  cl.input = sourceDir() + "/xml/family/3d-p2-nx32.xml";
  cl.output = std::string(std::getenv("SIGNORINI_BINARY_DIR") ? std::getenv("SIGNORINI_BINARY_DIR") : "/tmp") +
              "/app-refined-too-large-np" + std::to_string(comm->getSize());
  cl.overrides = {"Problem/mesh: cells={" + std::to_string(nx) + "}", "Problem/stiffness: P1 grid=refined at nodes"};
  std::ostringstream log;
  const std::string message = inputErrorOf([&] { runApplication(cl, comm, log); });
  EXPECT_NE(message.find("(P2, 3D) need at least"), std::string::npos) << message;
  EXPECT_NE(message.find("the mesh as the P1 grid (Problem/stiffness: P1 grid)"), std::string::npos) << message;
  EXPECT_EQ(log.str(), "");
}
