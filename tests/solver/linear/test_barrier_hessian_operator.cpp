// H = Q + A^T D A applied matrix-free agrees with the assembled matrix, with the full
// Y = alpha H X + beta Y contract, on every rank count.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/linear/BarrierHessianOperator.hpp"
#include "support/TestProblems.hpp"

namespace {

using namespace signorini;
using namespace signorini::testing;

TEST(BarrierHessianOperator, MatchesTheAssembledMatrix) {
  for (const char* name : {"M", "B", "H"}) {
    AssembledProblem p = buildProblem(assembledShippedProblem(std::string("paper/") + name), Tpetra::getDefaultComm());
    BarrierHessianOperator H(p.qp.Q, p.qp.A);
    Vector D(p.qp.A->getRangeMap());
    D.randomize(1.0, 1e6);  // spans the range of y/s met near a solution
    H.setWeights(D);
    const RCP<CrsMatrix> assembled = H.assemble();

    MultiVector X(H.getDomainMap(), 3), Y(H.getRangeMap(), 3), Z(H.getRangeMap(), 3);
    X.randomize();
    Y.randomize();
    Z.assign(Y);
    const double alpha = 0.7, beta = -1.3;
    H.apply(X, Y, Teuchos::NO_TRANS, alpha, beta);
    assembled->apply(X, Z, Teuchos::NO_TRANS, alpha, beta);

    Teuchos::Array<double> diff(3), scale(3);
    Z.norm2(scale());
    Z.update(-1.0, Y, 1.0);
    Z.norm2(diff());
    for (int k = 0; k < 3; ++k) EXPECT_LT(diff[k], 1e-13 * scale[k]) << name << " column " << k;

    // beta = 0 must ignore whatever Y held, even NaN.
    Y.putScalar(std::numeric_limits<double>::quiet_NaN());
    H.apply(X, Y);
    assembled->apply(X, Z);
    Z.update(-1.0, Y, 1.0);
    Z.norm2(diff());
    for (int k = 0; k < 3; ++k) EXPECT_LT(diff[k], 1e-13 * scale[k] / alpha) << name << " column " << k;
  }
}

// max |H x - assembled x| / max |H x| for a random x.
double relativeMismatch(const BarrierHessianOperator& H, const CrsMatrix& assembled) {
  Vector x(H.getDomainMap()), y(H.getRangeMap()), z(H.getRangeMap());
  x.randomize();
  H.apply(x, y);
  assembled.apply(x, z);
  z.update(-1.0, y, 1.0);
  return z.normInf() / y.normInf();
}

// Contact constraints couple the DOFs of one node, so H shares Q's graph and every
// assembly after the first reuses the positions found by the first.
TEST(BarrierHessianOperator, AssemblySharesQsGraphAndFollowsNewWeights) {
  AssembledProblem p = buildProblem(assembledShippedProblem("paper/H"), Tpetra::getDefaultComm());
  BarrierHessianOperator H(p.qp.Q, p.qp.A);
  Vector D(p.qp.A->getRangeMap());
  for (int round = 0; round < 3; ++round) {
    D.randomize(1.0, 1e6);
    H.setWeights(D);
    const RCP<CrsMatrix> assembled = H.assemble();
    EXPECT_EQ(assembled->getCrsGraph().get(),
              Teuchos::rcp_dynamic_cast<const CrsMatrix>(p.qp.Q, true)->getCrsGraph().get());
    EXPECT_LT(relativeMismatch(H, *assembled), 1e-13) << "round " << round;
  }
}

// Between Newton steps the preconditioner's H is updated in place: the same values as a
// fresh assembly, and the change it reports is the difference, on the contact rows alone.
TEST(BarrierHessianOperator, UpdateInPlaceEqualsAFreshAssembly) {
  AssembledProblem p = buildProblem(assembledShippedProblem("paper/H"), Tpetra::getDefaultComm());
  BarrierHessianOperator H(p.qp.Q, p.qp.A);
  ASSERT_TRUE(H.assemblesOnQGraph());
  Vector D0(p.qp.A->getRangeMap()), D1(p.qp.A->getRangeMap());
  D0.randomize(1.0, 1e6);
  D1.randomize(1.0, 1e6);
  {  // one constraint keeps its weight
    auto d0 = D0.getDataNonConst();
    auto d1 = D1.getDataNonConst();
    if (d0.size() > 0) d1[0] = d0[0];
  }
  const RCP<CrsMatrix> updated = H.assemble(D0);
  const RCP<CrsMatrix> before = H.assemble(D0);
  const RCP<CrsMatrix> change = H.updateAssembled(*updated, D1);
  const RCP<CrsMatrix> fresh = H.assemble(D1);

  const auto u = updated->getLocalMatrixHost().values, f = fresh->getLocalMatrixHost().values;
  ASSERT_EQ(u.extent(0), f.extent(0));
  std::size_t differing = 0;
  for (std::size_t e = 0; e < u.extent(0); ++e) differing += u(e) != f(e);
  EXPECT_EQ(differing, 0u);

  // before + change acts as the updated matrix.
  MultiVector x(updated->getDomainMap(), 1), y(updated->getRangeMap(), 1), z(updated->getRangeMap(), 1);
  x.randomize();
  before->apply(x, y);
  change->apply(x, y, Teuchos::NO_TRANS, 1.0, 1.0);
  updated->apply(x, z);
  z.update(-1.0, y, 1.0);
  EXPECT_LT(z.getVector(0)->normInf(), 1e-12 * y.getVector(0)->normInf());
  // Only the contact DOFs' entries: at most the 3 x 3 block of each constraint's node.
  EXPECT_GT(change->getGlobalNumEntries(), 0u);
  EXPECT_LE(change->getGlobalNumEntries(), 9 * p.qp.A->getGlobalNumRows());

  // A matrix on another graph than Q's cannot be updated.
  EXPECT_THROW(H.updateAssembled(*Tpetra::MatrixMatrix::add(1.0, false, *before, 0.0, false, *before), D1), Error);
}

// A constraint that couples DOFs far apart (as a mortar or multi-point constraint would)
// falls outside Q's graph: the assembly must still be exact.
TEST(BarrierHessianOperator, AssemblesConstraintsOutsideQsPattern) {
  AssembledProblem p = buildProblem(assembledShippedProblem("paper/G"), Tpetra::getDefaultComm());
  const auto& A0 = *p.qp.A;
  const GlobalOrdinal n = static_cast<GlobalOrdinal>(A0.getDomainMap()->getGlobalNumElements());
  auto A = rcp(new CrsMatrix(A0.getRowMap(), 4));
  for (LocalOrdinal r = 0; r < static_cast<LocalOrdinal>(A0.getNodeNumRows()); ++r) {
    const GlobalOrdinal row = A0.getRowMap()->getGlobalElement(r);
    std::size_t count = A0.getNumEntriesInGlobalRow(row);
    Teuchos::Array<GlobalOrdinal> cols(count);
    Teuchos::Array<double> vals(count);
    A0.getGlobalRowCopy(row, cols(), vals(), count);
    cols.push_back((cols[0] + n / 2) % n);  // a DOF on the far side of the body
    vals.push_back(0.5);
    A->insertGlobalValues(row, cols(), vals());
  }
  A->fillComplete(A0.getDomainMap(), A0.getRangeMap());

  BarrierHessianOperator H(p.qp.Q, A);
  Vector D(A->getRangeMap());
  D.randomize(1.0, 1e6);
  H.setWeights(D);
  const RCP<CrsMatrix> assembled = H.assemble();
  EXPECT_NE(assembled->getCrsGraph().get(),
            Teuchos::rcp_dynamic_cast<const CrsMatrix>(p.qp.Q, true)->getCrsGraph().get());
  EXPECT_LT(relativeMismatch(H, *assembled), 1e-13);
}

// Weighted gaps couple the nodes around a contact vertex, beyond Q's graph: the assembly
// keeps the pattern of its first call and follows new weights exactly (P2 in 2D and 3D).
TEST(BarrierHessianOperator, AssemblesWeightedGapsInAFixedPattern) {
  for (const char* name : {"H", "C"}) {
    Teuchos::ParameterList problem = assembledShippedProblem(std::string("paper/") + name);
    problem.sublist("Contact").set("formulation", "weighted gap");
    AssembledProblem p = buildProblem(problem, Tpetra::getDefaultComm());
    BarrierHessianOperator H(p.qp.Q, p.qp.A);
    Vector D(p.qp.A->getRangeMap());
    const void* firstGraph = nullptr;
    for (int round = 0; round < 3; ++round) {
      D.randomize(0.0, 1e6);
      H.setWeights(D);
      const RCP<CrsMatrix> assembled = H.assemble();
      if (round == 0) firstGraph = assembled->getCrsGraph().get();
      EXPECT_EQ(assembled->getCrsGraph().get(), firstGraph) << name << " round " << round;
      EXPECT_LT(relativeMismatch(H, *assembled), 1e-13) << name << " round " << round;
    }
  }
}

TEST(BarrierHessianOperator, ZeroWeightsGiveQ) {
  AssembledProblem p = buildProblem(assembledShippedProblem("paper/G"), Tpetra::getDefaultComm());
  BarrierHessianOperator H(p.qp.Q, p.qp.A);
  Vector x(H.getDomainMap()), y(H.getRangeMap()), z(H.getRangeMap());
  x.randomize();
  H.apply(x, y);
  p.qp.Q->apply(x, z);
  z.update(-1.0, y, 1.0);
  EXPECT_EQ(z.normInf(), 0.0);
}

}  // namespace
