#pragma once
/// \file
/// The distributed finite element space a problem is assembled on, as a library user sees it:
/// its sizes, the order of the values of fields on it, and the handle that ContactPressure and
/// writeVtu take. buildProblem makes it (AssembledProblem::space); the mesh, its partition and
/// the numbering behind it stay inside the library.
#include <cstddef>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class FiniteElementSpace {
 public:
  virtual ~FiniteElementSpace() = default;

  /// The ranks the space is distributed over.
  virtual const RCP<const Comm>& comm() const = 0;
  virtual int dim() const = 0;
  /// The degree k of the Lagrange P_k elements.
  virtual int degree() const = 0;
  virtual long long numGlobalNodes() const = 0;
  virtual long long numGlobalCells() const = 0;
  /// The unknowns this rank owns, dim() * node + component: the map of Q's rows and of b.
  virtual const RCP<const Map>& ownedDofMap() const = 0;
  /// The nodes of this rank's cells, the owned ones first, then the ghosts: a NodeField of
  /// writeVtu holds its values in this order.
  virtual std::size_t numOverlapNodes() const = 0;
  /// The dim() coordinates of overlap node i, 0 <= i < numOverlapNodes().
  virtual void overlapNodeCoordinates(std::size_t i, double* x) const = 0;
  /// The cells of this rank: a CellField of writeVtu holds its values in this order.
  virtual long long numLocalCells() const = 0;
};

}  // namespace signorini
