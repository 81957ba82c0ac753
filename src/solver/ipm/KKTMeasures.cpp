#include "signorini/solver/KKTMeasures.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Vector.hpp>

#include "solver/ipm/InteriorPointMethods.hpp"

namespace signorini {
namespace {

double relative(double value, double scale) { return value / (scale > 0 ? scale : 1.0); }

}  // namespace

double KKTMeasures::worst() const {
  return std::max({stationarity, complementarity, primalFeasibility, dualFeasibility});
}

KKTMeasures kktMeasures(const ContactQP& qp, const Vector& v, const Vector& lambda) {
  Vector Qv(qp.Q->getRangeMap()), Atl(qp.A->getDomainMap());
  qp.Q->apply(v, Qv);
  qp.A->apply(lambda, Atl, Teuchos::TRANS);
  Vector r(Qv, Teuchos::Copy);
  r.update(-1.0, *qp.b, -1.0, Atl, 1.0);

  Vector c(qp.A->getRangeMap());
  qp.A->apply(v, c);
  c.update(-1.0, *qp.d, 1.0);

  double local[3] = {0.0, 0.0, 0.0};  // max |lambda c|, max c, max lambda
  {
    auto cd = c.getData();
    auto ld = lambda.getData();
    for (std::size_t i = 0; i < c.getLocalLength(); ++i) {
      local[0] = std::max(local[0], std::abs(ld[i] * cd[i]));
      local[1] = std::max(local[1], cd[i]);
      local[2] = std::max(local[2], ld[i]);
    }
  }
  double global[3];
  Teuchos::reduceAll(*v.getMap()->getComm(), Teuchos::REDUCE_MAX, 3, local, global);

  KKTMeasures m;
  m.stationarityAbs = r.norm2();
  m.complementarityAbs = global[0];
  m.primalFeasibilityAbs = std::max(0.0, global[1]);
  m.dualFeasibilityAbs = std::max(0.0, global[2]);
  const double energy = std::max(std::abs(qp.b->dot(v)), std::abs(Qv.dot(v)));
  const double displacement = std::max(v.normInf(), qp.d->getGlobalLength() ? qp.d->normInf() : 0.0);
  m.stationarity = relative(m.stationarityAbs, std::max(qp.b->norm2(), Atl.norm2()));
  // m max|lambda_i c_i| bounds the duality gap, hence the error of J: relative to the energy.
  m.complementarity = relative(static_cast<double>(lambda.getGlobalLength()) * m.complementarityAbs, energy);
  m.primalFeasibility = relative(m.primalFeasibilityAbs, displacement);
  m.dualFeasibility = relative(m.dualFeasibilityAbs, lambda.getGlobalLength() ? lambda.normInf() : 0.0);
  return m;
}

}  // namespace signorini

namespace signorini {

ActiveSetCriterion::ActiveSetCriterion(const ContactQP& qp, const Vector& v, const Vector& lambda) {
  const Vector norms = detail::constraintRowNorms(*qp.A);
  auto r = norms.getData();
  rowNorm_.assign(r.begin(), r.end());

  double local[2] = {0, 0}, global[2];  // max |lambda_i r_i|, max |d_i / r_i|
  auto l = lambda.getData();
  auto d = qp.d->getData();
  for (std::size_t i = 0; i < rowNorm_.size(); ++i) {
    local[0] = std::max(local[0], std::abs(l[i] * rowNorm_[i]));
    local[1] = std::max(local[1], std::abs(d[i] / rowNorm_[i]));
  }
  Teuchos::reduceAll(*v.getMap()->getComm(), Teuchos::REDUCE_MAX, 2, local, global);
  forceScale_ = std::max(qp.b->normInf(), global[0]);
  displacementScale_ = std::max(v.normInf(), global[1]);
  if (!(forceScale_ > 0)) forceScale_ = 1;
  if (!(displacementScale_ > 0)) displacementScale_ = 1;
}

RCP<Vector> activeIndicator(const ContactQP& qp, const Vector& v, const Vector& lambda) {
  Vector slack(qp.A->getRangeMap());
  qp.A->apply(v, slack);
  slack.update(1.0, *qp.d, -1.0);
  const ActiveSetCriterion criterion(qp, v, lambda);
  auto active = rcp(new Vector(qp.A->getRangeMap()));
  auto l = lambda.getData();
  auto g = slack.getData();
  auto out = active->getDataNonConst();
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(out.size()); ++i)
    out[i] = criterion.isActive(i, l[i], g[i]) ? 1.0 : 0.0;
  return active;
}

}  // namespace signorini
