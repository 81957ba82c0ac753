#pragma once
// A point's place along a Morton (Z-order) curve through a box: its coordinates scaled to the
// box, quantised to 63 / dim bits each and the bits interleaved. Sorting cells by the code of
// their centroids keeps neighbours near each other in the order, most of the time.
#include <cstdint>

namespace signorini {

inline std::uint64_t mortonCode(const double* x, const double* lower, const double* upper, int dim) {
  const int bits = 63 / dim;
  std::uint64_t code = 0;
  for (int c = 0; c < dim; ++c) {
    const double t = upper[c] > lower[c] ? (x[c] - lower[c]) / (upper[c] - lower[c]) : 0.0;
    const auto q = static_cast<std::uint64_t>(t * static_cast<double>((1ULL << bits) - 1));
    for (int b = 0; b < bits; ++b) code |= ((q >> b) & 1ULL) << (dim * b + c);
  }
  return code;
}

}  // namespace signorini
