#include "signorini/solver/MultigridInput.hpp"

#include <algorithm>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "solver/preconditioner/RigidBodyModes.hpp"

namespace signorini {

RCP<const CrsMatrix> assembledStiffness(const ContactQP& qp, const MultigridInput& multigrid) {
  return multigrid.assembledQ.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q) : multigrid.assembledQ;
}

RCP<const MultiVector> MultigridInput::nearNullspace(const ContactQP& qp) const {
  if (!nullspace.is_null() || coordinates.is_null()) return nullspace;
  // The modes need the coordinates' rows to be the nodes of Q's DOFs, blockSize each, on
  // every rank; coordinates laid out otherwise give none.
  const bool aligned = static_cast<int>(coordinates->getNumVectors()) == blockSize &&
                       qp.Q->getDomainMap()->getNodeNumElements() == blockSize * coordinates->getLocalLength();
  if (!onEveryRank(*qp.Q->getDomainMap()->getComm(), aligned)) return Teuchos::null;
  return rigidBodyModes(qp.Q->getDomainMap(), *coordinates);
}

RCP<const MultiVector> MultigridInput::bodyMotions(const ContactQP& qp) const {
  const RCP<const MultiVector> modes = nearNullspace(qp);
  const Comm& comm = *qp.Q->getDomainMap()->getComm();
  const int bodies = maxOverRanks(comm, nodeBodies.empty() ? 1 : 1 + *std::max_element(nodeBodies.begin(), nodeBodies.end()));
  if (modes.is_null() || bodies == 1) return modes;
  if (!onEveryRank(comm, nodeBodies.size() * blockSize == modes->getLocalLength()))
    throw Error("MultigridInput::nodeBodies: one body per node of the coordinates expected");
  const int k = static_cast<int>(modes->getNumVectors());
  auto motions = rcp(new MultiVector(modes->getMap(), bodies * k));
  for (int j = 0; j < k; ++j) {
    auto mode = modes->getData(j);
    for (int b = 0; b < bodies; ++b) {
      auto copy = motions->getDataNonConst(b * k + j);
      for (std::size_t i = 0; i < modes->getLocalLength(); ++i)
        if (nodeBodies[i / blockSize] == b) copy[i] = mode[i];
    }
  }
  return motions;
}

}  // namespace signorini
