// Which expressions the batched form translates and which it leaves to muparser point by
// point (its values are compared with muparser's in test_expression.cpp).
#include "assembly/BatchedExpression.hpp"

#include <gtest/gtest.h>

#include <muParser.h>

namespace signorini::detail {
namespace {

// Whether BatchedExpression translates `text` over the variables x, y, z.
bool translates(const char* text) {
  double x[3] = {0.5, 0.5, 0.5};
  mu::Parser parser;
  parser.DefineVar("x", &x[0]);
  parser.DefineVar("y", &x[1]);
  parser.DefineVar("z", &x[2]);
  parser.SetExpr(text);
  parser.Eval();  // muparser makes its bytecode at the first evaluation
  return BatchedExpression::translate(parser, x) != nullptr;
}

TEST(BatchedExpression, TranslatesArithmeticFunctionsAndConditionals) {
  for (const char* text : {"0", "x", "-((8*(2*x-1)^4 - 8*(2*x-1)^2 + 1) + (8*(2*y-1)^4 - 8*(2*y-1)^2 + 1))/2",
                           "sin(x)*cos(y) + exp(-z)", "min(x, y, z) + sum(x, y, z, 1)", "x < 0.5 ? 1 : 2*y"})
    EXPECT_TRUE(translates(text)) << text;
}

TEST(BatchedExpression, LeavesAssignmentsAndSeveralResultsToMuparser) {
  for (const char* text : {"x = y + 1", "x, y, 2*z", "sum(x, x, x, x, x, x, x, x, x, x, x, x, x, x, x, x, y)"})
    EXPECT_FALSE(translates(text)) << text;
}

}  // namespace
}  // namespace signorini::detail
