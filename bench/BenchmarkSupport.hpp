#pragma once
// What the benchmark programs share: the input of a clamped box of the family and the median
// time of repeated work.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_Time.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini::bench {

// A P_degree box with nx cells per direction, clamped on its top face (no load, no contact).
inline Teuchos::ParameterList clampedBox(int dim, int degree, int nx) {
  Teuchos::ParameterList problem("Problem");
  problem.set("mesh: dimension", dim);
  problem.set("mesh: cells", Teuchos::Array<int>(1, nx));
  problem.set("element: degree", degree);
  problem.set("stiffness: operator", "assembled");  // the benchmarks measure its matrix
  const char* axes[] = {"x", "y", "z"};
  auto& clamp = problem.sublist("Dirichlet").sublist(dim == 2 ? "ymax" : "zmax");
  for (int c = 0; c < dim; ++c) clamp.set(std::string("displacement: ") + axes[c], "0");
  return problem;
}

// Median over `repeats` of the slowest rank's seconds for `work`. Collective.
inline double medianSeconds(const Comm& comm, int repeats, const std::function<void()>& work) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    comm.barrier();
    Teuchos::Time timer("work");
    timer.start(true);
    work();
    double local = timer.stop(), slowest = 0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local, &slowest);
    times.push_back(slowest);
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace signorini::bench
