#pragma once
// The machine-readable results of a run: summary.json (the paper's Table 2 counters, KKT
// measures, times) and history.csv (one row per Newton step). Written by rank 0, each to a
// temporary name then renamed, so no half-written file is ever left.
#include <optional>
#include <string>
#include <vector>

#include "signorini/assembly/ContactStatistics.hpp"
#include "signorini/solver/SolveRecorder.hpp"
#include "signorini/solver/SolveResult.hpp"

namespace signorini {

struct RunSummary {
  std::string problem, method;
  int dim = 0, degree = 0, ranks = 1;
  long long nx = 0, n = 0, m = 0;
  const SolveResult* result = nullptr;
  const SolveRecorder* record = nullptr;  // the solve's history, inner iterations, finishes
  double setupSeconds = 0, assemblySeconds = 0, solveSeconds = 0, totalSeconds = 0;  // max over ranks
  double peakMemoryMiBMaxRank = 0, peakMemoryMiBAllRanks = 0;  // peak resident set size
  bool hugePages = false;  // malloc asked for transparent huge pages (see driver/HugePages.hpp)
  // Rank 0's serial mesh phase: global mesh, space and partition arrays (capacities), and
  // the growth of its peak resident set over that phase.
  double serialMeshMiB = 0, serialMeshPeakMiB = 0;
  std::vector<double> setupPeakMiBPerRank;  // every rank's peak growth over mesh and space
  std::vector<std::string> notes;           // on how the problem was built (BuildObserver::onNote)
  std::vector<long long> gridVertices;      // the grids given to the geometric multigrid, finest first
  std::optional<ContactStatistics> contact;  // when the problem has a contact boundary: all pairs'
  struct ContactPairStatistics {
    std::string name, boundary, masterBoundary;
    ContactStatistics statistics;
  };
  std::vector<ContactPairStatistics> contactPairs;  // each pair's, with a mesh
};

void writeSummaryJson(const RunSummary& summary, const std::string& path);
void writeHistoryCsv(const SolveRecorder& record, const std::string& path);

}  // namespace signorini
