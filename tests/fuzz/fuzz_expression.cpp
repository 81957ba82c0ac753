// libFuzzer target: any bytes as an expression of x, y, z (loads, gaps, displacements),
// parsed and evaluated at a few points of the unit cube, point by point and all at once.
// Both must agree: the same values, or the same refusal. Where the text has a power the
// values may differ in rounding (integer powers are products in the batched form), and a
// cancellation can make that any size (even 1/0 on one side), so such texts are only run.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/FuzzInput.hpp"
#include "signorini/assembly/Expression.hpp"

namespace {

// The values at the three points, or false if the expression is refused at one of them.
template <class Evaluate>
bool valuesOrRefusal(Evaluate&& evaluate) {
  try {
    evaluate();
    return true;
  } catch (const signorini::InputError&) {
    return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = signorini::fuzz::text(data, size);
  signorini::fuzz::expectInputErrorOrNothing([&] {
    const signorini::Expression expression(text, "Problem/body force: x");
    const double points[3][3] = {{0, 0, 0}, {0.5, 0.25, 1}, {1, 1, 0.5}};
    for (int dim = 2; dim <= 3; ++dim) {
      double flat[9], one[3], all[3];
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < dim; ++c) flat[dim * i + c] = points[i][c];
      const bool pointwise = valuesOrRefusal([&] {
        for (int i = 0; i < 3; ++i) one[i] = expression(points[i], dim);
      });
      const bool batched = valuesOrRefusal([&] { expression.evaluate(3, flat, dim, all); });
      if (text.find('^') != std::string::npos) continue;
      if (pointwise != batched) std::abort();
      for (int i = 0; pointwise && i < 3; ++i)
        if (one[i] != all[i]) std::abort();
    }
    expression.isConstantZero();
  });
  return 0;
}
