#pragma once
// How exactly a direct solver inverts A: max |A x - b| / max |b| with x from solver.solve(b, x),
// for two random right-hand sides.
#include <algorithm>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini::testing {

template <class DirectSolver>
double relativeResidual(const CrsMatrix& A, const DirectSolver& solver) {
  MultiVector b(A.getRangeMap(), 2), x(A.getDomainMap(), 2), r(A.getRangeMap(), 2);
  b.randomize();
  solver.solve(b, x);
  A.apply(x, r);
  r.update(-1.0, b, 1.0);
  Teuchos::Array<double> error(2), size(2);
  r.normInf(error());
  b.normInf(size());
  return std::max(error[0] / size[0], error[1] / size[1]);
}

}  // namespace signorini::testing
