#pragma once
// The property every GeometricGrid's interpolation must have: at x, weights >= 0 that sum to
// one and reproduce x itself from the simplex's vertices (so every linear function).
#include <gtest/gtest.h>

#include "signorini/core/GeometricGrid.hpp"

namespace signorini::testing {

inline void expectInterpolationReproduces(const GeometricGrid& g, const double* x) {
  const int dim = g.dimension();
  long long vertices[4];
  double weights[4], sum = 0.0, reproduced[3] = {0, 0, 0};
  g.interpolation(x, vertices, weights);
  for (int k = 0; k <= dim; ++k) {
    EXPECT_GE(weights[k], 0.0);
    sum += weights[k];
    double y[3];
    g.vertexCoordinates(vertices[k], y);
    for (int a = 0; a < dim; ++a) reproduced[a] += weights[k] * y[a];
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  for (int a = 0; a < dim; ++a) EXPECT_NEAR(reproduced[a], x[a], 1e-13) << g.description() << ", axis " << a;
}

}  // namespace signorini::testing
