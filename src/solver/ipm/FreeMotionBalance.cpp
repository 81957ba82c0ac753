#include "solver/ipm/FreeMotionBalance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/ipm/InteriorPointMethods.hpp"

namespace signorini::detail {
namespace {

// Exponents beyond this would overflow y or lose it to zero: the balance is then out of reach.
constexpr double kLargestExponent = 200.0;

// phi(z) = sum_i y_i exp((G z)_i) - z^T beta with its gradient G^T y(z) - beta and Hessian
// G^T diag(y(z)) G, all summed over the ranks; `magnitude` is sum_i |G_ai| y_i(z), the scale
// of the gradient's round-off.
struct BalanceFunction {
  const MultiVector& G;
  const Vector& y0;
  std::vector<double> beta;

  struct Value {
    double phi = 0;
    std::vector<double> gradient, hessian;  // f, and f x f column-major
    double magnitude = 0;
    bool representable = true;
  };

  int size() const { return static_cast<int>(beta.size()); }

  double exponent(std::size_t i, const std::vector<double>& z, const std::vector<Teuchos::ArrayRCP<const double>>& g) const {
    double e = 0;
    for (int a = 0; a < size(); ++a) e += g[a][i] * z[a];
    return e;
  }

  Value operator()(const std::vector<double>& z) const {
    const int f = size();
    std::vector<Teuchos::ArrayRCP<const double>> g(f);
    for (int a = 0; a < f; ++a) g[a] = G.getData(a);
    auto y = y0.getData();
    // phi, gradient, Hessian and a flag, in one buffer for one reduction.
    std::vector<double> local(2 + 2 * f + f * f, 0.0), global(local.size());
    for (std::size_t i = 0; i < y0.getLocalLength(); ++i) {
      const double e = exponent(i, z, g);
      if (std::abs(e) > kLargestExponent) local[1] = 1;
      const double yi = y[i] * std::exp(std::clamp(e, -kLargestExponent, kLargestExponent));
      local[0] += yi;
      for (int a = 0; a < f; ++a) {
        local[2 + a] += g[a][i] * yi;
        for (int c = 0; c <= a; ++c) local[2 + f + a + f * c] += g[a][i] * g[c][i] * yi;
        local[2 + f + f * f + a] += std::abs(g[a][i]) * yi;
      }
    }
    Teuchos::reduceAll(*y0.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       global.data());
    Value v;
    v.phi = global[0];
    v.representable = global[1] == 0;
    v.gradient.resize(f);
    v.hessian.resize(f * f);
    for (int a = 0; a < f; ++a) {
      v.phi -= z[a] * beta[a];
      v.gradient[a] = global[2 + a] - beta[a];
      for (int c = 0; c <= a; ++c) v.hessian[a + f * c] = v.hessian[c + f * a] = global[2 + f + a + f * c];
      v.magnitude += global[2 + f + f * f + a] * global[2 + f + f * f + a];
    }
    v.magnitude = std::sqrt(v.magnitude);
    return v;
  }
};

double norm(const std::vector<double>& x) {
  double s = 0;
  for (double value : x) s += value * value;
  return std::sqrt(s);
}

// One Newton step on phi from z (value = phi(z)) with Armijo backtracking: z and `next`
// updated, or false if the Hessian is singular (no constraint moves under some free motion)
// or no step decreases phi.
bool newtonStep(const BalanceFunction& phi, const BalanceFunction::Value& value, std::vector<double>& z,
                BalanceFunction::Value& next) {
  const int f = phi.size();
  std::vector<double> factor = value.hessian, step(f), trial(f);
  for (int a = 0; a < f; ++a) step[a] = -value.gradient[a];
  int info = 0;
  Teuchos::LAPACK<int, double>().POSV('L', f, 1, factor.data(), f, step.data(), f, &info);
  if (info != 0) return false;
  double slope = 0;
  for (int a = 0; a < f; ++a) slope += value.gradient[a] * step[a];
  double alpha = 1.0;
  for (int halvings = 0; halvings < 60; ++halvings, alpha *= 0.5) {
    for (int a = 0; a < f; ++a) trial[a] = z[a] + alpha * step[a];
    next = phi(trial);
    if (next.representable && next.phi <= value.phi + 1e-4 * alpha * slope) {
      z = trial;
      return true;
    }
  }
  return false;
}

}  // namespace

bool balanceLoadAlongFreeMotions(const CrsMatrix& A, const Vector& b, const MultiVector& F, Vector& y) {
  const int f = static_cast<int>(F.getNumVectors());
  if (f == 0 || A.getGlobalNumRows() == 0) return false;
  // In units of the rows: G_i = (a_i F) / |a_i| is how far constraint i moves under the free
  // motions, and r_i y_i its force, so that scaling a row (a weighted gap integrates over its
  // node's facets) does not change the balance.
  const Vector r = constraintRowNorms(A);
  MultiVector G(A.getRangeMap(), f);
  A.apply(F, G);
  Vector inverse(r.getMap()), force(r.getMap());
  inverse.reciprocal(r);
  for (int a = 0; a < f; ++a) G.getVectorNonConst(a)->elementWiseMultiply(1.0, inverse, *G.getVector(a), 0.0);
  force.elementWiseMultiply(1.0, r, y, 0.0);
  BalanceFunction phi{G, force, std::vector<double>(f)};
  for (int a = 0; a < f; ++a) phi.beta[a] = F.getVector(a)->dot(b);
  const double betaNorm = norm(phi.beta);
  if (betaNorm == 0) return false;
  std::vector<double> z(f, 0.0);
  BalanceFunction::Value value = phi(z);
  // Newton's method until the gradient reaches round-off (the terms of G^T y may be far larger
  // than their sum, and the exponents lose digits), or stops falling below 1e-8 of its scale.
  const auto scale = [&](const BalanceFunction::Value& v) { return std::max(betaNorm, v.magnitude); };
  for (int iteration = 0; iteration < 100 && norm(value.gradient) > 1e-14 * scale(value); ++iteration) {
    BalanceFunction::Value next;
    if (!newtonStep(phi, value, z, next)) break;
    const bool stalled = norm(next.gradient) > 0.5 * norm(value.gradient);
    value = std::move(next);
    if (stalled && norm(value.gradient) <= 1e-8 * scale(value)) break;
  }
  if (!value.representable || norm(value.gradient) > 1e-8 * scale(value)) return false;
  std::vector<Teuchos::ArrayRCP<const double>> g(f);
  for (int a = 0; a < f; ++a) g[a] = G.getData(a);
  auto yd = y.getDataNonConst();
  for (std::size_t i = 0; i < y.getLocalLength(); ++i) yd[i] *= std::exp(phi.exponent(i, z, g));
  return true;
}

}  // namespace signorini::detail
