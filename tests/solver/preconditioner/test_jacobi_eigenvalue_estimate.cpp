// The Lanczos estimate of the largest eigenvalue of D^-1 A: exact once the Krylov space is
// the whole space, the same on every rank count, and a few update steps after a change of
// some rows as good as a fresh estimate. Gershgorin's bound for diag(C)^-1 C: exact for
// constraints on one node, above the largest eigenvalue for coupled ones.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>
#include <TpetraExt_MatrixMatrix.hpp>

#include "solver/preconditioner/JacobiEigenvalueEstimate.hpp"

namespace {

using namespace signorini;

double scale(GlobalOrdinal g) { return 1.0 + 0.5 * std::sin(0.1 * static_cast<double>(g)); }

// S L S + c (the rows in [firstStiff, lastStiff) only), with L the 1D Laplacian of n rows and
// S a varying diagonal. Without c, D^-1 A is similar to L / 2: its largest eigenvalue is
// 1 + cos(pi / (n + 1)).
RCP<CrsMatrix> matrix(const RCP<const Comm>& comm, long long n, double c = 0.0, GlobalOrdinal firstStiff = 0,
                      GlobalOrdinal lastStiff = 0) {
  auto map = rcp(new Map(n, 0, comm));
  auto A = rcp(new CrsMatrix(map, 3));
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i);
    for (GlobalOrdinal j : {g - 1, g, g + 1}) {
      if (j < 0 || j >= n) continue;
      double value = scale(g) * scale(j) * (j == g ? 2.0 : -1.0);
      if (j == g && g >= firstStiff && g < lastStiff) value += c;
      A->insertGlobalValues(g, Teuchos::tuple(j), Teuchos::tuple(value));
    }
  }
  A->fillComplete();
  return A;
}

TEST(JacobiEigenvalueEstimate, ExactOnAFullKrylovSpace) {
  const long long n = 40;
  const auto A = matrix(Tpetra::getDefaultComm(), n);
  JacobiEigenvalueEstimate estimate;
  estimate.setMatrix(*A);
  EXPECT_NEAR(estimate.estimate(*A, n), 1.0 + std::cos(M_PI / (n + 1)), 1e-10);

  // The inverse diagonal handed to the smoother.
  Vector diagonal(A->getRowMap());
  A->getLocalDiagCopy(diagonal);
  diagonal.elementWiseMultiply(1.0, diagonal, *estimate.inverseDiagonal(), 0.0);
  for (double one : diagonal.getData()) EXPECT_DOUBLE_EQ(one, 1.0);
}

TEST(JacobiEigenvalueEstimate, TheSameOnEveryRankCount) {
  const long long n = 500;
  const auto distributed = matrix(Tpetra::getDefaultComm(), n);
  const auto serial = matrix(rcp(new Teuchos::SerialComm<int>()), n);
  JacobiEigenvalueEstimate onRanks, onOne;
  onRanks.setMatrix(*distributed);
  onOne.setMatrix(*serial);
  const double value = onRanks.estimate(*distributed, 10);
  EXPECT_NEAR(value, onOne.estimate(*serial, 10), 1e-12);
  // Ten steps: close to, and below, the largest eigenvalue.
  EXPECT_LT(value, 1.0 + std::cos(M_PI / (n + 1)));
  EXPECT_GT(value, 0.99 * (1.0 + std::cos(M_PI / (n + 1))));
}

TEST(JacobiEigenvalueEstimate, UpdateStepsAfterAChangeMatchAFreshEstimate) {
  const long long n = 400;
  const auto comm = Tpetra::getDefaultComm();
  const auto A = matrix(comm, n);
  JacobiEigenvalueEstimate estimate;
  estimate.setMatrix(*A);
  estimate.estimate(*A, 15);
  ASSERT_TRUE(estimate.hasRitzVector());

  // Rows 100-139 get 1000 times their diagonal: there D^-1 A is nearly the identity, and
  // the largest eigenvalue lives on the other rows.
  const auto B = matrix(comm, n, 2000.0, 100, 140);
  const auto change = matrix(comm, n, 2000.0, 100, 140);
  change->resumeFill();
  change->setAllToScalar(0.0);
  for (GlobalOrdinal g = 100; g < 140; ++g)
    if (change->getRowMap()->isNodeGlobalElement(g))
      change->replaceGlobalValues(g, Teuchos::tuple(g), Teuchos::tuple(2000.0));
  change->fillComplete();

  JacobiEigenvalueEstimate fresh;
  fresh.setMatrix(*B);
  const double reference = fresh.estimate(*B, 60);
  estimate.setMatrix(*B);
  estimate.startFromLast(*change);
  const double updated = estimate.estimate(*B, 5);
  EXPECT_LE(updated, reference * (1 + 1e-12));
  EXPECT_GT(updated, 0.98 * reference);
  // Five steps from scratch do worse than five from the last Ritz vector.
  JacobiEigenvalueEstimate short_;
  short_.setMatrix(*B);
  EXPECT_LT(short_.estimate(*B, 5), updated);
}

// C = sum of w_k a_k a_k^T over nodes k of three DOFs, a_k on node k's DOFs with components
// of ratio up to 20, every fourth node without a constraint (rows of zeros): each block's
// diag^-1 (a a^T) has the eigenvalue 3 (a's nonzero count), where Gershgorin's bound for
// diag(C)^-1 C alone would be the ratio's sum, about 25.
TEST(JacobiGershgorinBound, ExactForConstraintsOnOneNode) {
  const long long nodes = 60;
  auto map = rcp(new Map(3 * nodes, 0, Tpetra::getDefaultComm()));
  auto C = rcp(new CrsMatrix(map, 3));
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i), node = g / 3;
    if (node % 4 == 0) continue;
    const double a[3] = {1.0, 0.2 + 0.1 * static_cast<double>(node % 3), 0.05};
    const double weight = scale(node);
    for (int j = 0; j < 3; ++j)
      C->insertGlobalValues(g, Teuchos::tuple<GlobalOrdinal>(3 * node + j), Teuchos::tuple(weight * a[g % 3] * a[j]));
  }
  C->fillComplete();
  EXPECT_NEAR(jacobiGershgorinBound(*C), 3.0, 1e-12);
}

// C = B^T B with B the rows (1/6, 2/3, 1/6) of a weighted gap on a line of n nodes (a P1
// mass matrix's), rows scaled by S: coupled constraints. The bound is at or above the
// largest eigenvalue of diag(C)^-1 C (the Lanczos estimate on the whole Krylov space), and
// within 1% of it.
TEST(JacobiGershgorinBound, BoundsTheLargestEigenvalueOfCoupledConstraints) {
  const long long n = 40;
  auto map = rcp(new Map(n, 0, Tpetra::getDefaultComm()));
  auto B = rcp(new CrsMatrix(map, 3));
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i);
    for (GlobalOrdinal j : {g - 1, g, g + 1})
      if (j >= 0 && j < n)
        B->insertGlobalValues(g, Teuchos::tuple(j), Teuchos::tuple(scale(g) * (j == g ? 2.0 / 3.0 : 1.0 / 6.0)));
  }
  B->fillComplete();
  auto C = rcp(new CrsMatrix(map, 5));
  Tpetra::MatrixMatrix::Multiply(*B, true, *B, false, *C);
  JacobiEigenvalueEstimate estimate;
  estimate.setMatrix(*C);
  const double largest = estimate.estimate(*C, n), bound = jacobiGershgorinBound(*C);
  EXPECT_GE(bound, largest * (1 - 1e-12));
  EXPECT_LE(bound, 1.01 * largest);
}

}  // namespace
