// Benchmark: nanoseconds per point of evaluating a user expression, point by point (muparser
// through Expression::operator()) and a cell's points at once (Expression::evaluate), as the
// assembly calls it.
// Usage: build/bin/signorini_bench_expression DIM [POINTS_PER_CALL]
// Prints one JSON object: the family's load for DIM (doc/benchmark-family.md), the number of
// points, the seconds of each way and their ratio. One process: run it without mpirun or
// with one rank.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "signorini/assembly/Expression.hpp"

namespace {

double secondsOf(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: signorini_bench_expression DIM [POINTS_PER_CALL]\n";
    return 2;
  }
  const int dim = std::atoi(argv[1]), perCall = argc > 2 ? std::atoi(argv[2]) : (dim == 2 ? 7 : 14);
  const std::string t4x = "(8*(2*x-1)^4 - 8*(2*x-1)^2 + 1)", t4y = "(8*(2*y-1)^4 - 8*(2*y-1)^2 + 1)";
  const std::string text = dim == 2 ? "-" + t4x : "-(" + t4x + " + " + t4y + ")/2";
  const signorini::Expression load(text, "body force");

  const int points = (1 << 22) / perCall * perCall;
  std::vector<double> x(static_cast<std::size_t>(points) * dim), one(points), all(points);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  for (double& xi : x) xi = coordinate(random);

  auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < points; ++i) one[i] = load(&x[static_cast<std::size_t>(dim) * i], dim);
  const double pointwise = secondsOf(start);
  start = std::chrono::steady_clock::now();
  for (int i = 0; i < points; i += perCall)
    load.evaluate(perCall, &x[static_cast<std::size_t>(dim) * i], dim, &all[i]);
  const double batched = secondsOf(start);

  double largestDifference = 0;
  for (int i = 0; i < points; ++i) largestDifference = std::max(largestDifference, std::abs(one[i] - all[i]));
  std::cout << "{\"dim\": " << dim << ", \"expression\": \"" << text << "\", \"points\": " << points
            << ", \"points_per_call\": " << perCall << ", \"pointwise_ns_per_point\": " << 1e9 * pointwise / points
            << ", \"batched_ns_per_point\": " << 1e9 * batched / points
            << ", \"speedup\": " << pointwise / batched << ", \"largest_difference\": " << largestDifference << "}"
            << std::endl;
  return 0;
}
