#include "signorini/assembly/ContactStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/solver/KKTMeasures.hpp"

namespace signorini {
namespace {

// A^T lambda summed per component, DOF dim * node + component, over the DOFs where `only` is
// nonzero if given. Collective.
std::array<double, 3> forceResultant(const CrsMatrix& A, const Vector& lambda, int dim, const Vector* only = nullptr) {
  Vector force(A.getDomainMap());
  A.apply(lambda, force, Teuchos::TRANS);
  if (only) force.elementWiseMultiply(1.0, *only, force, 0.0);
  const auto map = A.getDomainMap();
  auto f = force.getData();
  std::array<double, 3> local{{0, 0, 0}}, total{{0, 0, 0}};
  for (LocalOrdinal i = 0; i < static_cast<LocalOrdinal>(f.size()); ++i) local[map->getGlobalElement(i) % dim] += f[i];
  Teuchos::reduceAll(*A.getRangeMap()->getComm(), Teuchos::REDUCE_SUM, 3, local.data(), total.data());
  return total;
}

}  // namespace

ContactStatistics contactStatistics(const ContactPressure& recovery, const Vector& pressure, const CrsMatrix& A,
                                    const Vector& lambda, const Vector& active,
                                    const std::array<double, 3>& obstacleDirection) {
  ContactStatistics s;
  s.dim = recovery.dim();
  Vector pairLambda(lambda.getMap()), pairActive(active.getMap());  // this pair's rows only
  pairLambda.elementWiseMultiply(1.0, recovery.pairConstraints(), lambda, 0.0);
  pairActive.elementWiseMultiply(1.0, recovery.pairConstraints(), active, 0.0);
  const RCP<Vector> slaveDofs = recovery.contactBoundaryDofs();
  s.force = forceResultant(A, pairLambda, s.dim, slaveDofs.get());
  if (recovery.betweenBodies()) {
    Vector masterDofs(slaveDofs->getMap());
    masterDofs.putScalar(1.0);
    masterDofs.update(-1.0, *slaveDofs, 1.0);
    s.masterForce = forceResultant(A, pairLambda, s.dim, &masterDofs);
  }
  for (int c = 0; c < 3; ++c) s.normalForce += s.force[c] * obstacleDirection[c];
  double peak = -std::numeric_limits<double>::infinity();
  for (double p : pressure.getData()) peak = std::max(peak, p);
  Teuchos::reduceAll(*A.getRangeMap()->getComm(), Teuchos::REDUCE_MAX, 1, &peak, &s.peakPressure);
  if (!std::isfinite(s.peakPressure)) s.peakPressure = 0;
  s.area = recovery.activeMeasure(pairActive);
  s.activeNodes = std::llround(pairActive.norm1());
  return s;
}

ContactStatistics combinedStatistics(const std::vector<ContactStatistics>& pairs) {
  ContactStatistics all;
  for (const ContactStatistics& s : pairs) {
    all.dim = s.dim;
    for (int c = 0; c < 3; ++c) all.force[c] += s.force[c];
    if (s.masterForce) {
      if (!all.masterForce) all.masterForce.emplace();
      for (int c = 0; c < 3; ++c) (*all.masterForce)[c] += (*s.masterForce)[c];
    }
    all.normalForce += s.normalForce;
    all.area += s.area;
    all.peakPressure = std::max(all.peakPressure, s.peakPressure);
    all.activeNodes += s.activeNodes;
  }
  return all;
}

ContactStatistics contactStatistics(const ContactQP& qp, const MultigridInput& multigrid, const Vector& v,
                                    const Vector& lambda) {
  ContactStatistics s;
  s.dim = multigrid.blockSize;
  s.force = forceResultant(*qp.A, lambda, s.dim);
  s.normalForce = std::sqrt(s.force[0] * s.force[0] + s.force[1] * s.force[1] + s.force[2] * s.force[2]);
  s.area = s.peakPressure = std::numeric_limits<double>::quiet_NaN();
  s.activeNodes = std::llround(activeIndicator(qp, v, lambda)->norm1());
  return s;
}

}  // namespace signorini
