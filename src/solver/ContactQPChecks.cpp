#include "solver/ContactQPChecks.hpp"

#include <cmath>
#include <string>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

void refuse(const std::string& what) { throw InputError("ContactQP: " + what); }

// The first rank-local DOF whose block is not a whole node (blockSize consecutive global
// indices from a multiple of blockSize), or -1. Collective: the same answer on every rank.
long long firstSplitNode(const Map& map, int blockSize) {
  const auto count = static_cast<LocalOrdinal>(map.getNodeNumElements());
  const auto id = [&](LocalOrdinal i) { return static_cast<long long>(map.getGlobalElement(i)); };
  long long local = count % blockSize != 0 ? id(count - 1) : -1;
  for (LocalOrdinal i = 0; i < count && local < 0; ++i) {
    const long long first = id(i - i % blockSize);  // the first unknown of i's block on this rank
    if (first % blockSize != 0 || id(i) != first + i % blockSize) local = id(i);
  }
  return maxOverRanks(*map.getComm(), local);
}

// Q on a random pair x, y: its entries finite (Q x is), and symmetric to round-off of
// ||Q x|| ||y|| (x^T Q y = y^T Q x). Two products of Q. Collective.
void checkStiffness(const Operator& Q) {
  Vector x(Q.getDomainMap()), y(Q.getDomainMap()), Qx(Q.getRangeMap()), Qy(Q.getRangeMap());
  x.randomize();
  y.randomize();
  Q.apply(x, Qx);
  Q.apply(y, Qy);
  if (!std::isfinite(Qx.norm1()) || !std::isfinite(Qy.norm1())) refuse("Q has an entry that is not finite");
  const double asymmetry = std::abs(x.dot(Qy) - y.dot(Qx)), scale = Qx.norm2() * y.norm2() + Qy.norm2() * x.norm2();
  if (asymmetry > 1e-10 * scale)
    refuse("Q is not symmetric (x^T Q y - y^T Q x is " + std::to_string(asymmetry / scale) +
           " of its scale for random x, y); eliminate Dirichlet conditions symmetrically: zero the row and the "
           "column, unit diagonal (doc/qp-format.md)");
}

}  // namespace

void checkContactQP(const ContactQP& qp, const MultigridInput& multigrid) {
  if (qp.Q.is_null() || qp.b.is_null() || qp.A.is_null() || qp.d.is_null()) refuse("Q, b, A and d must all be set");
  if (multigrid.blockSize < 1 || multigrid.blockSize > 3) refuse("MultigridInput::blockSize must be 1, 2 or 3 (unknowns per node)");
  const Map& domain = *qp.Q->getDomainMap();
  if (!qp.b->getMap()->isSameAs(domain)) refuse("b must live on Q's domain map");
  if (!qp.A->getDomainMap()->isSameAs(domain)) refuse("A's domain map must be Q's domain map");
  if (!qp.d->getMap()->isSameAs(*qp.A->getRangeMap())) refuse("d must live on A's range map");
  if (!std::isfinite(qp.b->norm1())) refuse("b has an entry that is not finite");
  if (!std::isfinite(qp.d->norm1())) refuse("d has an entry that is not finite");
  {
    Vector ones(qp.A->getDomainMap()), Aones(qp.A->getRangeMap());
    ones.putScalar(1.0);
    qp.A->apply(ones, Aones);
    if (!std::isfinite(Aones.norm1())) refuse("A has an entry that is not finite");
  }
  const long long split = firstSplitNode(domain, multigrid.blockSize);
  if (split >= 0)
    refuse("Q's domain map splits the " + std::to_string(multigrid.blockSize) + " unknowns of a node (at global index " +
           std::to_string(split) + "): every rank must hold whole nodes, unknown blockSize * node + component; "
           "build the map by nodes (signorini::readQP does) rather than by an even split of the unknowns");
  checkStiffness(*qp.Q);
}

}  // namespace signorini
