// libFuzzer target: any bytes as an expression of x, y, z (loads, gaps, displacements),
// parsed and evaluated at a few points of the unit cube.
#include <cstddef>
#include <cstdint>

#include "fuzz/FuzzInput.hpp"
#include "signorini/assembly/Expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  signorini::fuzz::expectInputErrorOrNothing([&] {
    const signorini::Expression expression(signorini::fuzz::text(data, size), "Problem/body force: x");
    const double points[3][3] = {{0, 0, 0}, {0.5, 0.25, 1}, {1, 1, 0.5}};
    for (const double* x : points) {
      expression(x, 2);
      expression(x, 3);
    }
    expression.isConstantZero();
  });
  return 0;
}
