#include "solver/ipm/FreeMotionBalance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace signorini::detail {
namespace {

// Exponents beyond this would overflow y or lose it to zero: the balance is then out of reach.
constexpr double kLargestExponent = 200.0;

// phi(z) = sum_i y_i exp((G z)_i) - z^T beta with its gradient G^T y(z) - beta and Hessian
// G^T diag(y(z)) G, all summed over the ranks.
struct BalanceFunction {
  const MultiVector& G;
  const Vector& y0;
  std::vector<double> beta;

  struct Value {
    double phi = 0;
    std::vector<double> gradient, hessian;  // f, and f x f column-major
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
    std::vector<double> local(2 + f + f * f, 0.0), global(local.size());
    for (std::size_t i = 0; i < y0.getLocalLength(); ++i) {
      const double e = exponent(i, z, g);
      if (std::abs(e) > kLargestExponent) local[1] = 1;
      const double yi = y[i] * std::exp(std::clamp(e, -kLargestExponent, kLargestExponent));
      local[0] += yi;
      for (int a = 0; a < f; ++a) {
        local[2 + a] += g[a][i] * yi;
        for (int c = 0; c <= a; ++c) local[2 + f + a + f * c] += g[a][i] * g[c][i] * yi;
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
    }
    return v;
  }
};

double norm(const std::vector<double>& x) {
  double s = 0;
  for (double value : x) s += value * value;
  return std::sqrt(s);
}

}  // namespace

bool balanceLoadAlongFreeMotions(const CrsMatrix& A, const Vector& b, const MultiVector& F, Vector& y) {
  const int f = static_cast<int>(F.getNumVectors());
  if (f == 0 || A.getGlobalNumRows() == 0) return false;
  MultiVector G(A.getRangeMap(), f);
  A.apply(F, G);
  BalanceFunction phi{G, y, std::vector<double>(f)};
  for (int a = 0; a < f; ++a) phi.beta[a] = F.getVector(a)->dot(b);
  const double betaNorm = norm(phi.beta);
  if (betaNorm == 0) return false;
  std::vector<double> z(f, 0.0), step(f), trial(f);
  BalanceFunction::Value value = phi(z);
  Teuchos::LAPACK<int, double> lapack;
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (norm(value.gradient) <= 1e-12 * betaNorm) {
      if (!value.representable) return false;
      auto g = std::vector<Teuchos::ArrayRCP<const double>>(f);
      for (int a = 0; a < f; ++a) g[a] = G.getData(a);
      auto yd = y.getDataNonConst();
      for (std::size_t i = 0; i < y.getLocalLength(); ++i) yd[i] *= std::exp(phi.exponent(i, z, g));
      return true;
    }
    // Newton step: Hessian step = -gradient (Cholesky; the Hessian is positive definite
    // where some constraint moves under every free motion, which the rigid-body check ensures).
    std::vector<double> factor = value.hessian;
    for (int a = 0; a < f; ++a) step[a] = -value.gradient[a];
    int info = 0;
    lapack.POSV('L', f, 1, factor.data(), f, step.data(), f, &info);
    if (info != 0) return false;
    double slope = 0;
    for (int a = 0; a < f; ++a) slope += value.gradient[a] * step[a];
    double alpha = 1.0;
    BalanceFunction::Value next;
    for (int halvings = 0;; ++halvings) {
      if (halvings == 60) return false;
      for (int a = 0; a < f; ++a) trial[a] = z[a] + alpha * step[a];
      next = phi(trial);
      if (next.representable && next.phi <= value.phi + 1e-4 * alpha * slope) break;
      alpha *= 0.5;
    }
    z = trial;
    value = std::move(next);
  }
  return false;
}

}  // namespace signorini::detail
