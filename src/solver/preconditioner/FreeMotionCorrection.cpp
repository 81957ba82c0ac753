#include "solver/preconditioner/FreeMotionCorrection.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/linear/BarrierHessianOperator.hpp"

namespace signorini {

FreeMotionCorrection::FreeMotionCorrection(RCP<const BarrierHessianOperator> H, RCP<const MultiVector> F)
    : H_(std::move(H)),
      F_(std::move(F)),
      QF_(rcp(new MultiVector(F_->getMap(), F_->getNumVectors()))),
      HF_(rcp(new MultiVector(F_->getMap(), F_->getNumVectors()))) {
  H_->applyQ(*F_, *QF_);
  refresh();
}

RCP<const Map> FreeMotionCorrection::getDomainMap() const { return H_->getDomainMap(); }
RCP<const Map> FreeMotionCorrection::getRangeMap() const { return H_->getRangeMap(); }

void FreeMotionCorrection::refresh() {
  H_->applyGivenQX(*F_, *QF_, *HF_);
  const int f = static_cast<int>(F_->getNumVectors());
  factor_.assign(f * f, 0.0);
  for (int b = 0; b < f; ++b) {
    const std::vector<double> column = innerProducts(*F_, *HF_->getVector(b));
    for (int a = 0; a < f; ++a) factor_[a + f * b] = column[a];
  }
  int info = 0;
  Teuchos::LAPACK<int, double>().POTRF('L', f, factor_.data(), f, &info);
  active_ = info == 0;  // not with zero weights, where H = Q is singular along F
}

std::vector<double> FreeMotionCorrection::innerProducts(const MultiVector& U, const Vector& x) const {
  const int f = static_cast<int>(U.getNumVectors());
  std::vector<double> local(f, 0.0), global(f);
  auto xd = x.getData();
  for (int a = 0; a < f; ++a) {
    auto u = U.getData(a);
    for (std::size_t i = 0; i < x.getLocalLength(); ++i) local[a] += u[i] * xd[i];
  }
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, f, local.data(), global.data());
  return global;
}

void FreeMotionCorrection::solveCoarse(std::vector<double>& c) const {
  const int f = static_cast<int>(c.size());
  int info = 0;
  Teuchos::LAPACK<int, double>().POTRS('L', f, 1, factor_.data(), f, c.data(), f, &info);
}

void FreeMotionCorrection::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Scalar alpha,
                                 Scalar beta) const {
  if (z_.is_null()) {
    z_ = rcp(new Vector(getDomainMap()));
    residual_ = rcp(new Vector(getRangeMap()));
    correction_ = rcp(new Vector(getDomainMap()));
  }
  const int f = static_cast<int>(F_->getNumVectors());
  for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
    const RCP<const Vector> r = X.getVector(j);
    // Corrections go through a scratch vector: not every preconditioner honours beta.
    if (!active_) {
      B_->apply(*r, *correction_);
      Y.getVectorNonConst(j)->update(alpha, *correction_, beta);
      continue;
    }
    const std::vector<double> Ftr = innerProducts(*F_, *r);
    // x = C r, and r - H x = r - HF c
    std::vector<double> c = Ftr;
    solveCoarse(c);
    z_->putScalar(0.0);
    residual_->assign(*r);
    for (int a = 0; a < f; ++a) {
      z_->update(c[a], *F_->getVector(a), 1.0);
      residual_->update(-c[a], *HF_->getVector(a), 1.0);
    }
    B_->apply(*residual_, *correction_);
    z_->update(1.0, *correction_, 1.0);
    // x += C (r - H x), with F^T H x = (H F)^T x
    const std::vector<double> HFtz = innerProducts(*HF_, *z_);
    for (int a = 0; a < f; ++a) c[a] = Ftr[a] - HFtz[a];
    solveCoarse(c);
    for (int a = 0; a < f; ++a) z_->update(c[a], *F_->getVector(a), 1.0);
    Y.getVectorNonConst(j)->update(alpha, *z_, beta);
  }
}

}  // namespace signorini
