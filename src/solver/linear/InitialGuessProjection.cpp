#include "solver/linear/InitialGuessProjection.hpp"

#include <cmath>

#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

InitialGuessProjection::InitialGuessProjection(int capacity) : capacity_(capacity) {
  if (capacity < 0) throw InputError("InitialGuessProjection: the capacity must not be negative");
}

int InitialGuessProjection::project(const Operator& H, const Vector& r, Vector& x, bool withX) const {
  // x is read here and only overwritten after the basis is built: no copy needed.
  std::vector<RCP<const Vector>> candidates;
  if (withX) candidates.push_back(Teuchos::rcpFromRef<const Vector>(x));
  for (auto it = solutions_.rbegin(); it != solutions_.rend(); ++it) candidates.push_back(*it);

  // Modified Gram-Schmidt in the H inner product, carrying H q along so that each vector
  // costs one application of H.
  std::vector<RCP<Vector>> q, Hq;
  for (const auto& u : candidates) {
    auto w = rcp(new Vector(*u, Teuchos::Copy));
    auto Hw = rcp(new Vector(H.getRangeMap()));
    H.apply(*w, *Hw);
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
  for (const auto& qj : q) x.update(qj->dot(r), *qj, 1.0);
  return static_cast<int>(q.size());
}

void InitialGuessProjection::remember(const Vector& x) {
  if (capacity_ == 0) return;
  if (static_cast<int>(solutions_.size()) == capacity_) solutions_.erase(solutions_.begin());
  solutions_.push_back(rcp(new Vector(x, Teuchos::Copy)));
}

}  // namespace signorini
