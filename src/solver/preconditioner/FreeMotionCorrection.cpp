#include "solver/preconditioner/FreeMotionCorrection.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/linear/BarrierHessianOperator.hpp"

namespace signorini {
namespace {

// The columns of V as a vector of single vectors, each an own copy.
std::vector<RCP<Vector>> columnsOf(const MultiVector& V) {
  std::vector<RCP<Vector>> columns;
  for (std::size_t j = 0; j < V.getNumVectors(); ++j) columns.push_back(rcp(new Vector(*V.getVector(j), Teuchos::Copy)));
  return columns;
}

// Removes from w its components along `basis` (orthonormal; twice, for round-off) and
// normalises it; false if little of w is left: w was (nearly) in span(basis) already.
bool orthonormaliseAgainst(const std::vector<RCP<Vector>>& basis, Vector& w) {
  const double before = w.norm2();
  if (!(before > 0)) return false;
  for (int pass = 0; pass < 2; ++pass)
    for (const RCP<Vector>& u : basis) w.update(-u->dot(w), *u, 1.0);
  const double after = w.norm2();
  if (!(after > 1e-10 * before)) return false;
  w.scale(1.0 / after);
  return true;
}

}  // namespace

FreeMotionCorrection::FreeMotionCorrection(RCP<const BarrierHessianOperator> H, RCP<const MultiVector> F, int depth)
    : H_(std::move(H)), F_(std::move(F)), depth_(depth), QF_(rcp(new MultiVector(F_->getMap(), F_->getNumVectors()))) {
  H_->applyQ(*F_, *QF_);
}

RCP<const Map> FreeMotionCorrection::getDomainMap() const { return H_->getDomainMap(); }
RCP<const Map> FreeMotionCorrection::getRangeMap() const { return H_->getRangeMap(); }

// U = F, then per level the previous level's columns u replaced by u - B H u, made
// orthonormal to all of U so far.
void FreeMotionCorrection::buildCoarseSpace() const {
  std::vector<RCP<Vector>> U = columnsOf(*F_), HU;
  auto level = rcp(new MultiVector(*F_, Teuchos::Copy));
  auto Hlevel = rcp(new MultiVector(F_->getMap(), F_->getNumVectors()));
  H_->applyGivenQX(*F_, *QF_, *Hlevel);
  HU = columnsOf(*Hlevel);
  for (int depth = 0; depth < depth_; ++depth) {
    MultiVector W(level->getMap(), level->getNumVectors());
    B_->apply(*Hlevel, W);
    W.update(1.0, *level, -1.0);
    std::vector<RCP<Vector>> next;
    for (std::size_t j = 0; j < W.getNumVectors(); ++j) {
      auto w = rcp(new Vector(*W.getVector(j), Teuchos::Copy));
      if (!orthonormaliseAgainst(U, *w)) continue;
      U.push_back(w);
      next.push_back(w);
    }
    if (next.empty()) break;
    level = rcp(new MultiVector(F_->getMap(), next.size()));
    for (std::size_t j = 0; j < next.size(); ++j) level->getVectorNonConst(j)->assign(*next[j]);
    Hlevel = rcp(new MultiVector(F_->getMap(), next.size()));
    H_->apply(*level, *Hlevel);
    for (const RCP<Vector>& Hw : columnsOf(*Hlevel)) HU.push_back(Hw);
  }
  const int k = static_cast<int>(U.size());
  U_ = rcp(new MultiVector(F_->getMap(), k));
  HU_ = rcp(new MultiVector(F_->getMap(), k));
  for (int j = 0; j < k; ++j) {
    U_->getVectorNonConst(j)->assign(*U[j]);
    HU_->getVectorNonConst(j)->assign(*HU[j]);
  }
}

// (U^T H U)^+ from its eigenvalues, of which those below 1e-12 of the largest count as zero
// (with zero weights all do: B alone).
void FreeMotionCorrection::factorCoarseMatrix() const {
  const int k = static_cast<int>(U_->getNumVectors());
  std::vector<double> G(k * k), eigenvalues(k), work(3 * k);
  for (int b = 0; b < k; ++b) {
    const std::vector<double> column = innerProducts(*U_, *HU_->getVector(b));
    for (int a = 0; a < k; ++a) G[a + k * b] = column[a];
  }
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('V', 'U', k, G.data(), k, eigenvalues.data(), work.data(), 3 * k, &info);
  inverse_.assign(k * k, 0.0);
  for (int e = 0; e < k && info == 0; ++e) {
    if (!(eigenvalues[e] > 1e-12 * eigenvalues[k - 1])) continue;
    for (int b = 0; b < k; ++b)
      for (int a = 0; a < k; ++a) inverse_[a + k * b] += G[a + k * e] * G[b + k * e] / eigenvalues[e];
  }
}

std::vector<double> FreeMotionCorrection::innerProducts(const MultiVector& U, const Vector& x) const {
  const int k = static_cast<int>(U.getNumVectors());
  std::vector<double> local(k, 0.0), global(k);
  auto xd = x.getData();
  for (int a = 0; a < k; ++a) {
    auto u = U.getData(a);
    for (std::size_t i = 0; i < x.getLocalLength(); ++i) local[a] += u[i] * xd[i];
  }
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, k, local.data(), global.data());
  return global;
}

std::vector<double> FreeMotionCorrection::solveCoarse(const std::vector<double>& c) const {
  const std::size_t k = c.size();
  std::vector<double> x(k, 0.0);
  for (std::size_t b = 0; b < k; ++b)
    for (std::size_t a = 0; a < k; ++a) x[a] += inverse_[a + k * b] * c[b];
  return x;
}

void FreeMotionCorrection::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                 Scalar beta) const {
  if (z_.is_null()) {
    z_ = rcp(new Vector(getDomainMap()));
    residual_ = rcp(new Vector(getRangeMap()));
    correction_ = rcp(new Vector(getDomainMap()));
  }
  if (stale_) {
    Teuchos::TimeMonitor t(*Teuchos::TimeMonitor::getNewTimer("Signorini: solve: free motion coarse space"));
    buildCoarseSpace();
    factorCoarseMatrix();
    stale_ = false;
  }
  const int k = static_cast<int>(U_->getNumVectors());
  for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
    const RCP<const Vector> r = X.getVector(j);
    // x = C r, and r - H x = r - HU c
    const std::vector<double> Utr = innerProducts(*U_, *r);
    std::vector<double> c = solveCoarse(Utr);
    z_->putScalar(0.0);
    residual_->assign(*r);
    for (int a = 0; a < k; ++a) {
      z_->update(c[a], *U_->getVector(a), 1.0);
      residual_->update(-c[a], *HU_->getVector(a), 1.0);
    }
    // Corrections go through a scratch vector: not every preconditioner honours beta.
    B_->apply(*residual_, *correction_);
    z_->update(1.0, *correction_, 1.0);
    // x += C (r - H x), with U^T H x = (H U)^T x
    const std::vector<double> HUtz = innerProducts(*HU_, *z_);
    std::vector<double> remaining(k);
    for (int a = 0; a < k; ++a) remaining[a] = Utr[a] - HUtz[a];
    c = solveCoarse(remaining);
    for (int a = 0; a < k; ++a) z_->update(c[a], *U_->getVector(a), 1.0);
    Y.getVectorNonConst(j)->update(alpha, *z_, beta);
  }
}

}  // namespace signorini
