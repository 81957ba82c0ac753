#include "solver/linear/InitialGuessProjection.hpp"

#include <cmath>

#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"

namespace signorini {

InitialGuessProjection::InitialGuessProjection(int capacity) : capacity_(capacity) {
  if (capacity < 0) throw InputError("InitialGuessProjection: the capacity must not be negative");
}

namespace {

// Whether a and b hold the same values on every rank. Collective.
bool sameValues(const Vector& a, const Vector& b) {
  const auto ad = a.getData(), bd = b.getData();
  bool same = ad.size() == bd.size();
  for (long i = 0; same && i < ad.size(); ++i) same = ad[i] == bd[i];
  return onEveryRank(*a.getMap()->getComm(), same);
}

}  // namespace

int InitialGuessProjection::project(const BarrierHessianOperator& H, const Vector& r, Vector& x, bool withX,
                                    Vector* Hx) const {
  // x is read here and only overwritten after the basis is built: no copy needed. A start
  // that is the last solution kept (the corrector's, from the predictor's step) adds nothing.
  std::vector<Kept> candidates;
  if (withX && (kept_.empty() || !sameValues(x, *kept_.back().u)))
    candidates.push_back({Teuchos::rcpFromRef<const Vector>(x), Teuchos::null});
  for (auto it = kept_.rbegin(); it != kept_.rend(); ++it) candidates.push_back(*it);

  // Modified Gram-Schmidt in the H inner product, carrying H q along.
  std::vector<RCP<Vector>> q, Hq;
  for (const Kept& candidate : candidates) {
    auto w = rcp(new Vector(*candidate.u, Teuchos::Copy));
    auto Hw = rcp(new Vector(H.getRangeMap()));
    if (candidate.Qu.is_null())
      H.apply(*w, *Hw);
    else
      H.applyGivenQX(*w, *candidate.Qu, *Hw);
    const double original = w->dot(*Hw);
    for (std::size_t j = 0; j < q.size(); ++j) {
      const double c = q[j]->dot(*Hw);
      w->update(-c, *q[j], 1.0);
      Hw->update(-c, *Hq[j], 1.0);
    }
    const double remaining = w->dot(*Hw);
    // What is left of a vector in the span of the others is round-off: skip it.
    if (!(original > 0.0) || !(remaining > 1e-10 * original)) continue;
    w->scale(1.0 / std::sqrt(remaining));
    Hw->scale(1.0 / std::sqrt(remaining));
    q.push_back(w);
    Hq.push_back(Hw);
  }
  x.putScalar(0.0);
  if (Hx != nullptr) Hx->putScalar(0.0);
  for (std::size_t j = 0; j < q.size(); ++j) {
    const double c = q[j]->dot(r);
    x.update(c, *q[j], 1.0);
    if (Hx != nullptr) Hx->update(c, *Hq[j], 1.0);
  }
  return static_cast<int>(q.size());
}

void InitialGuessProjection::remember(const BarrierHessianOperator& H, const Vector& x) {
  if (capacity_ == 0) return;
  if (static_cast<int>(kept_.size()) == capacity_) kept_.erase(kept_.begin());
  auto Qx = rcp(new Vector(H.getRangeMap()));
  H.applyQ(x, *Qx);
  kept_.push_back({rcp(new Vector(x, Teuchos::Copy)), Qx});
}

}  // namespace signorini
