#include "io/RunSummary.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <Trilinos_version.h>

#include "io/AtomicFile.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/Version.hpp"

namespace signorini {
namespace {

std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string integerArray(const std::vector<long long>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + std::to_string(values[i]);
  return out + "]";
}

std::string kktJson(double stationarity, double complementarity, double primal, double dual) {
  return "{\"stationarity\": " + number(stationarity) + ", \"complementarity\": " + number(complementarity) +
         ", \"primal_feasibility\": " + number(primal) + ", \"dual_feasibility\": " + number(dual) + "}";
}

// The members of a "contact" object: forces, normal force, area (length in 2D), peak pressure,
// active nodes.
std::string contactJson(const ContactStatistics& c) {
  std::ostringstream j;
  j << "\"force\": [";
  for (int i = 0; i < c.dim; ++i) j << (i ? ", " : "") << number(c.force[i]);
  if (c.masterForce) {
    j << "], \"master_force\": [";
    for (int i = 0; i < c.dim; ++i) j << (i ? ", " : "") << number((*c.masterForce)[i]);
  }
  j << "], \"normal_force\": " << number(c.normalForce) << ", \"" << (c.dim == 2 ? "length" : "area")
    << "\": " << number(c.area) << ", \"peak_pressure\": " << number(c.peakPressure)
    << ", \"active_nodes\": " << c.activeNodes;
  return j.str();
}

}  // namespace

void writeSummaryJson(const RunSummary& s, const std::string& path) {
  const SolveResult& r = *s.result;
  const SolveRecorder& record = *s.record;
  std::ostringstream j;
  j << "{\n"
    << "  \"signorini\": {\"version\": " << quoted(kVersion) << ", \"commit\": " << quoted(gitCommit())
    << ", \"trilinos\": " << quoted(TRILINOS_VERSION_STRING) << "},\n"
    << "  \"problem\": " << quoted(s.problem) << ",\n"
    << "  \"d\": " << s.dim << ",\n"
    << "  \"kappa\": " << s.degree << ",\n"
    << "  \"nx\": " << s.nx << ",\n"
    << "  \"n\": " << s.n << ",\n"
    << "  \"m\": " << s.m << ",\n"
    << "  \"method\": " << quoted(s.method) << ",\n"
    << "  \"ranks\": " << s.ranks << ",\n"
    << "  \"converged\": " << (r.converged() ? "true" : "false") << ",\n"
    << "  \"status\": " << quoted(toString(r.status)) << ",\n"
    << "  \"message\": " << quoted(r.message) << ",\n"
    << "  \"outer_iterations\": " << r.outerIterations << ",\n"
    << "  \"newton_steps\": " << r.newtonSteps << ",\n"
    << "  \"gradient_evaluations\": " << r.gradientEvaluations << ",\n"
    << "  \"function_evaluations\": " << r.functionEvaluations << ",\n"
    << "  \"krylov_iterations\": " << r.krylovIterations << ",\n"
    << "  \"max_krylov_per_newton\": " << r.maxKrylovPerNewton << ",\n"
    << "  \"preconditioner_setups\": " << r.preconditionerSetups << ",\n"
    << "  \"multigrid_nonzeros\": " << integerArray(r.multigridNonzeros) << ",\n"
    << "  \"operator_complexity\": " << (r.operatorComplexity() > 0 ? number(r.operatorComplexity()) : "null") << ",\n"
    << "  \"active_set_finish\": {\"attempts\": " << record.activeSetFinishes().size()
    << ", \"accepted\": " << (record.finishedOnActiveSet() ? "true" : "false")
    << ", \"krylov_iterations\": " << record.activeSetFinishKrylov() << "},\n"
    << "  \"objective\": " << number(r.objective) << ",\n"
    << "  \"active_constraints\": " << r.activeConstraints << ",\n"
    << "  \"kkt\": " << kktJson(r.kkt.stationarity, r.kkt.complementarity, r.kkt.primalFeasibility,
                                  r.kkt.dualFeasibility) << ",\n"
    << "  \"kkt_absolute\": " << kktJson(r.kkt.stationarityAbs, r.kkt.complementarityAbs,
                                           r.kkt.primalFeasibilityAbs, r.kkt.dualFeasibilityAbs) << ",\n"
    << "  \"inner_iterations\": [";
  const std::vector<int>& inner = record.innerIterations();
  for (std::size_t i = 0; i < inner.size(); ++i) j << (i ? ", " : "") << inner[i];
  j << "],\n";
  if (s.contact) {
    j << "  \"contact\": {" << contactJson(*s.contact) << ", \"pairs\": [";
    for (std::size_t p = 0; p < s.contactPairs.size(); ++p) {
      const auto& pair = s.contactPairs[p];
      j << (p ? ", " : "") << "{\"name\": " << quoted(pair.name) << ", \"boundary\": " << quoted(pair.boundary)
        << ", \"master_boundary\": " << quoted(pair.masterBoundary) << ", " << contactJson(pair.statistics) << "}";
    }
    j << "]},\n";
  }
  j << "  \"memory_mib\": {\"max_rank\": " << number(s.peakMemoryMiBMaxRank)
    << ", \"all_ranks\": " << number(s.peakMemoryMiBAllRanks) << "},\n"
    << "  \"huge_pages\": " << (s.hugePages ? "true" : "false") << ",\n"
    << "  \"serial_mesh_mib\": " << number(s.serialMeshMiB) << ",\n"
    << "  \"serial_mesh_peak_rss_mib\": " << number(s.serialMeshPeakMiB) << ",\n"
    << "  \"setup_peak_rss_mib\": [";
  for (std::size_t i = 0; i < s.setupPeakMiBPerRank.size(); ++i) j << (i ? ", " : "") << number(s.setupPeakMiBPerRank[i]);
  j << "],\n  \"notes\": [";
  for (std::size_t i = 0; i < s.notes.size(); ++i) j << (i ? ", " : "") << quoted(s.notes[i]);
  j << "],\n  \"grid_vertices\": " << integerArray(s.gridVertices) << ",\n"
    << "  \"time\": {\"setup\": " << number(s.setupSeconds) << ", \"assembly\": " << number(s.assemblySeconds)
    << ", \"solve\": " << number(s.solveSeconds) << ", \"total\": " << number(s.totalSeconds) << "}\n"
    << "}\n";
  detail::writeFileAtomically(path, j.str());
}

void writeHistoryCsv(const SolveRecorder& record, const std::string& path) {
  std::ostringstream c;
  c << "main_iteration,inner_iteration,mu,objective,stationarity,complementarity,primal_feasibility,"
       "dual_feasibility,step,krylov_iterations,time\n";
  for (const NewtonStepRecord& h : record.history())
    c << h.outer << ',' << h.inner << ',' << number(h.mu) << ',' << number(h.objective) << ','
      << number(h.kkt.stationarity) << ',' << number(h.kkt.complementarity) << ','
      << number(h.kkt.primalFeasibility) << ',' << number(h.kkt.dualFeasibility) << ',' << number(h.step) << ','
      << h.krylovIterations << ',' << number(h.seconds) << '\n';
  detail::writeFileAtomically(path, c.str());
}

}  // namespace signorini
