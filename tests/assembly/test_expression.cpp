#include "signorini/assembly/Expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Points inside (0.05, 0.95)^dim (z = 0 in 2D), where every expression below is finite; more than
// one block of the batched evaluation holds.
std::vector<double> samplePoints(int count, int dim) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> coordinate(0.05, 0.95);
  std::vector<double> points(static_cast<std::size_t>(count) * dim);
  for (double& x : points) x = coordinate(random);
  return points;
}

// Evaluation of many points at once against muparser point by point: equal for `exact`,
// within a few units in the last place otherwise (integer powers are products there).
void expectSameAsPointByPoint(const std::string& text, bool exact) {
  const Expression expression(text, "test");
  for (int dim = 2; dim <= 3; ++dim)
    for (int count : {0, 1, 14, 150}) {
      const std::vector<double> points = samplePoints(count, dim);
      std::vector<double> values(count, std::numeric_limits<double>::quiet_NaN());
      expression.evaluate(count, points.data(), dim, values.data());
      for (int i = 0; i < count; ++i) {
        const double one = expression(&points[dim * i], dim);
        if (exact)
          ASSERT_EQ(values[i], one) << text << " dim " << dim << " point " << i;
        else
          ASSERT_NEAR(values[i], one, 8 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(one)))
              << text << " dim " << dim << " point " << i;
      }
    }
}

TEST(Expression, ManyPointsAtOnceGiveMuparsersValues) {
  for (const char* text :
       {"0", "-2.5", "x", "y", "z", "3*x-1", "x^2 + y^3 - z^4", "x^2.5 + y^z", "(x+y)^-2", "(x+y)^20", "(x+y)^0",
        "(x+y)^1", "-(x*y - z/3)", "_pi*x + _e", "sin(x)*cos(y) + exp(-z) + sqrt(x) + log(y) + abs(z-0.5)",
        "atan2(y, x) + tanh(x) + log10(y) + log2(z + 1) + sign(x-0.5) + rint(10*y)",
        "min(x, y, z) + max(x, 0.5) + sum(x, y, z, 1) + avg(x, y)",
        "x < 0.5 ? 1 : 2", "x < 0.3 ? sin(y) : (x < 0.6 ? 2*y : max(x, y, z))", "(x < 0.5 ? x : y) * 2 + 1",
        "x < 0.5 ? 0 : sqrt(x - 0.5)", "x <= y && y >= z || x == 0.5 || x != z", "(x > y) + (y < z)"})
    expectSameAsPointByPoint(text, true);
  for (const char* text : {"-((8*(2*x-1)^4 - 8*(2*x-1)^2 + 1) + (8*(2*y-1)^4 - 8*(2*y-1)^2 + 1))/2",
                           "(x+y)^3 - (y-z)^5 + (2*z)^16 + (x < 0.5 ? (x+1)^7 : 0)"})
    expectSameAsPointByPoint(text, false);
}

// What the batched form does not translate (an assignment, several results: that it does not
// is test_batched_expression.cpp's) is still evaluated, by muparser point by point.
TEST(Expression, ExpressionsOutsideTheBatchedFormAreEvaluatedPointByPoint) {
  for (const char* text : {"x = y + 1", "x, y, 2*z", "sum(x, x, x, x, x, x, x, x, x, x, x, x, x, x, x, x, y)"})
    expectSameAsPointByPoint(text, true);
}

TEST(Expression, ANonFiniteValueAmongManyNamesItsPoint) {
  const Expression expression("1/(x - 0.5)", "Problem/body force: y");
  const double points[] = {0.25, 0.0, 0.5, 1.0, 0.75, 0.0};
  double values[3];
  try {
    expression.evaluate(3, points, 2, values);
    ADD_FAILURE() << "an infinite value was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Problem/body force: y"), std::string::npos) << message;
    EXPECT_NE(message.find("is infinite at (0.5, 1)"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace signorini
