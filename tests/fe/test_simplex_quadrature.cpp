#include "fe/SimplexQuadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Integral of x^a y^b z^c over the reference simplex of dimension dim.
double exactMonomialIntegral(int dim, int a, int b, int c) {
  return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + dim);
}

double ruleMonomialIntegral(const QuadratureRule& rule, int a, int b, int c) {
  double sum = 0;
  for (int q = 0; q < rule.size(); ++q) {
    const double* x = &rule.points[q * rule.dim];
    sum += rule.weights[q] * std::pow(x[0], a) * (rule.dim > 1 ? std::pow(x[1], b) : 1.0) *
           (rule.dim > 2 ? std::pow(x[2], c) : 1.0);
  }
  return sum;
}

TEST(SimplexQuadrature, RejectsBadInput) {
  EXPECT_THROW(simplexQuadrature(0, 2), InputError);
  EXPECT_THROW(simplexQuadrature(4, 2), InputError);
  EXPECT_THROW(simplexQuadrature(2, -1), InputError);
}

TEST(SimplexQuadrature, PositiveWeightsInsidePoints) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int degree = 0; degree <= 14; ++degree) {
      const QuadratureRule rule = simplexQuadrature(dim, degree);
      ASSERT_EQ(rule.dim, dim);
      ASSERT_EQ(static_cast<int>(rule.points.size()), dim * rule.size());
      double total = 0;
      for (int q = 0; q < rule.size(); ++q) {
        EXPECT_GT(rule.weights[q], 0.0);
        double sum = 0;
        for (int j = 0; j < dim; ++j) {
          EXPECT_GT(rule.points[q * dim + j], 0.0);
          sum += rule.points[q * dim + j];
        }
        EXPECT_LT(sum, 1.0);
        total += rule.weights[q];
      }
      EXPECT_NEAR(total, 1.0 / factorial(dim), 1e-15);
    }
}

TEST(SimplexQuadrature, ExactForMonomialsUpToItsDegree) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int degree = 0; degree <= 14; ++degree) {
      const QuadratureRule rule = simplexQuadrature(dim, degree);
      for (int a = 0; a <= degree; ++a)
        for (int b = 0; a + b <= degree && (dim > 1 || b == 0); ++b)
          for (int c = 0; a + b + c <= degree && (dim > 2 || c == 0); ++c) {
            const double exact = exactMonomialIntegral(dim, a, b, c);
            EXPECT_NEAR(ruleMonomialIntegral(rule, a, b, c), exact, 1e-13 * exact)
                << "dim " << dim << " degree " << degree << " monomial " << a << " " << b << " " << c;
          }
    }
}

// Loads are integrated with degree 5 on P1 cells and P2 gradient products with degree 2:
// the symmetric rules use far fewer points than the collapsed ones (9 and 27, 4 and 8).
TEST(SimplexQuadrature, SymmetricRulesAreTheSmallOnes) {
  EXPECT_EQ(simplexQuadrature(2, 5).size(), 7);
  EXPECT_EQ(simplexQuadrature(3, 5).size(), 14);
  EXPECT_EQ(simplexQuadrature(3, 4).size(), 14);
  EXPECT_EQ(simplexQuadrature(1, 5).size(), 3);
  EXPECT_EQ(simplexQuadrature(2, 2).size(), 3);
  EXPECT_EQ(simplexQuadrature(3, 2).size(), 4);
}

// Gauss rules are exact to 2n - 1 with n points per direction, and no further: an odd
// degree rule misses the next power.
TEST(SimplexQuadrature, NotExactBeyondItsDegree) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int degree = 1; degree <= 11; degree += 2) {
      const QuadratureRule rule = simplexQuadrature(dim, degree);
      const double exact = exactMonomialIntegral(dim, degree + 1, 0, 0);
      EXPECT_GT(std::fabs(ruleMonomialIntegral(rule, degree + 1, 0, 0) - exact), 1e-10 * exact);
    }
}

}  // namespace
}  // namespace signorini
