#include "solver/preconditioner/RigidBodyModes.hpp"

#include <algorithm>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {

RCP<MultiVector> rigidBodyModes(const RCP<const Map>& dofMap, const MultiVector& nodeCoordinates) {
  const int dim = static_cast<int>(nodeCoordinates.getNumVectors());
  if (dim != 2 && dim != 3) throw Error("rigidBodyModes: coordinates must have 2 or 3 columns");
  const std::size_t numNodes = nodeCoordinates.getLocalLength();
  if (dofMap->getNodeNumElements() != dim * numNodes)
    throw Error("rigidBodyModes: the DOF map does not hold dim DOFs per coordinate row");
  const int numModes = dim == 2 ? 3 : 6;
  auto modes = rcp(new MultiVector(dofMap, numModes));
  Teuchos::ArrayRCP<const double> coords[3];
  for (int c = 0; c < dim; ++c) coords[c] = nodeCoordinates.getData(c);
  // Rotations about a centre c outside the mesh's bounding box in every coordinate, so that
  // no node lies on a rotation axis: a small aggregate of such nodes would give MueLu's
  // tentative prolongator a zero nullspace column (seen on 4 ranks with axes through c = 0).
  double lower[3], upper[3], minimum[3], maximum[3], centre[3];
  for (int c = 0; c < dim; ++c) {
    lower[c] = std::numeric_limits<double>::max();
    upper[c] = -std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < numNodes; ++i) {
      lower[c] = std::min(lower[c], coords[c][i]);
      upper[c] = std::max(upper[c], coords[c][i]);
    }
  }
  const Comm& comm = *dofMap->getComm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, dim, lower, minimum);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, dim, upper, maximum);
  for (int c = 0; c < dim; ++c) centre[c] = minimum[c] - std::max(maximum[c] - minimum[c], 1.0);
  for (int k = 0; k < numModes; ++k) {
    auto data = modes->getDataNonConst(k);
    for (std::size_t i = 0; i < numNodes; ++i) {
      double x[3];
      for (int c = 0; c < dim; ++c) x[c] = coords[c][i] - centre[c];
      double* u = &data[dim * i];
      if (k < dim) {
        u[k] = 1.0;  // translation
      } else if (dim == 2) {
        u[0] = -x[1];
        u[1] = x[0];
      } else {
        // rotation about the axis through the centre along e_a, a = k - 3: u = e_a x x
        const int a = k - 3, p = (a + 1) % 3, q = (a + 2) % 3;
        u[p] = -x[q];
        u[q] = x[p];
      }
    }
  }
  return modes;
}

}  // namespace signorini
