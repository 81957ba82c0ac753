// A ContactQP built by another code is checked before the solve: inconsistent maps and a
// node's unknowns split between ranks are refused in one message in the API's terms.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>
#include <TpetraExt_MatrixMatrix.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "solver/ContactQPChecks.hpp"
#include "support/TestProblems.hpp"

namespace signorini {
namespace {

// `qp` checked as a 2D QP (paper/M's unknowns per node) or with another block size.
std::string checkMessage(const ContactQP& qp, int blockSize = 2) {
  MultigridInput multigrid;
  multigrid.blockSize = blockSize;
  try {
    checkContactQP(qp, multigrid);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

ContactQP problemM() { return buildProblem(testing::shippedProblem("paper/M"), Tpetra::getDefaultComm()).qp; }

TEST(ContactQPChecks, AShippedProblemPasses) { EXPECT_EQ(checkMessage(problemM()), ""); }

TEST(ContactQPChecks, MissingAndMisplacedPiecesAreNamed) {
  ContactQP qp = problemM();
  qp.d = Teuchos::null;
  EXPECT_NE(checkMessage(qp).find("Q, b, A and d must all be set"), std::string::npos);
  qp = problemM();
  qp.d = rcp(new Vector(qp.Q->getDomainMap()));
  EXPECT_NE(checkMessage(qp).find("d must live on A's range map"), std::string::npos);
  qp = problemM();
  EXPECT_NE(checkMessage(qp, 0).find("blockSize must be"), std::string::npos);
}

// Q plus a multiple of an asymmetric matrix E (one entry), and a Q with a NaN entry, are
// refused; so is an A with an infinite entry.
TEST(ContactQPChecks, AsymmetricOrNonFiniteEntriesAreRefused) {
  const ContactQP qp = problemM();
  const RCP<const CrsMatrix> Q = Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q, true);
  const auto perturbed = [&](double value, bool symmetric) {
    auto E = rcp(new CrsMatrix(Q->getRowMap(), 2));
    const GlobalOrdinal first = Q->getRowMap()->getMinAllGlobalIndex();
    if (Q->getRowMap()->isNodeGlobalElement(first)) {
      E->insertGlobalValues(first, Teuchos::tuple<GlobalOrdinal>(first + 1), Teuchos::tuple<double>(value));
      if (symmetric) E->insertGlobalValues(first, Teuchos::tuple<GlobalOrdinal>(first), Teuchos::tuple<double>(0.0));
    }
    E->fillComplete(Q->getDomainMap(), Q->getRangeMap());
    ContactQP changed = qp;
    changed.Q = Tpetra::MatrixMatrix::add(1.0, false, *Q, 1.0, false, *E);
    return changed;
  };
  EXPECT_NE(checkMessage(perturbed(0.5 * Q->getFrobeniusNorm(), false)).find("Q is not symmetric"), std::string::npos);
  EXPECT_NE(checkMessage(perturbed(std::nan(""), true)).find("Q has an entry that is not finite"), std::string::npos);
  ContactQP infiniteA = qp;
  auto A = rcp(new CrsMatrix(*qp.A, Teuchos::Copy));
  A->resumeFill();
  auto values = A->getLocalMatrixHost().values;
  if (values.extent(0) > 0) values(0) = std::numeric_limits<double>::infinity();
  A->fillComplete(qp.A->getDomainMap(), qp.A->getRangeMap());
  infiniteA.A = A;
  EXPECT_NE(checkMessage(infiniteA).find("A has an entry that is not finite"), std::string::npos);
}

// The unknowns split evenly, whatever the nodes: with 242 unknowns of 2 per node on 4 ranks,
// 61 or 60 per rank, a node straddles ranks; the same unknowns by whole nodes pass.
TEST(ContactQPChecks, ANodeSplitBetweenRanksIsRefused) {
  auto comm = Tpetra::getDefaultComm();
  const ContactQP qp = problemM();
  const auto n = static_cast<GlobalOrdinal>(qp.b->getGlobalLength());
  const RCP<const Map> even = rcp(new Map(n, 0, comm));
  ContactQP split = qp;
  bool unevenSomewhere = false;
  for (int r = 0; r < comm->getSize(); ++r) unevenSomewhere |= (n / comm->getSize() + (r < n % comm->getSize())) % 2 != 0;
  if (!unevenSomewhere) GTEST_SKIP() << "every rank holds whole nodes of an even split here";
  // Q, b and A on the even split, the way a plain Matrix Market read makes them.
  Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node> toEven(qp.Q->getDomainMap(), even);
  auto Qeven = rcp(new CrsMatrix(even, 0));
  Qeven->doImport(*Teuchos::rcp_dynamic_cast<const CrsMatrix>(qp.Q, true), toEven, Tpetra::INSERT);
  Qeven->fillComplete(even, even);
  auto beven = rcp(new Vector(even));
  beven->doImport(*qp.b, toEven, Tpetra::INSERT);
  auto Aeven = rcp(new CrsMatrix(*qp.A));
  Aeven->resumeFill();
  Aeven->fillComplete(even, qp.A->getRangeMap());
  split.Q = Qeven;
  split.b = beven;
  split.A = Aeven;
  const std::string message = checkMessage(split);
  EXPECT_NE(message.find("splits the 2 unknowns of a node"), std::string::npos) << message;
  EXPECT_NE(message.find("readQP"), std::string::npos) << message;
  MultigridInput twoPerNode;
  twoPerNode.blockSize = 2;
  EXPECT_THROW(InteriorPointSolver(Teuchos::ParameterList()).solve(split, twoPerNode), InputError);
}

}  // namespace
}  // namespace signorini
