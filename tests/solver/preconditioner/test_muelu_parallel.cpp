// Pins a MueLu configuration that is correct on every rank count with Debian's Trilinos 13.2
// (whose Amesos2 coarse solvers are wrong on more than one rank): Belos CG preconditioned by
// MueLu on Galeri's 2D and 3D elasticity matrices, with asserted iteration bounds; and the
// reuse of a hierarchy.
#include <gtest/gtest.h>

#include <vector>

#include <Galeri_XpetraMaps.hpp>
#include <Galeri_XpetraProblemFactory.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Xpetra_CrsMatrixWrap.hpp>
#include <Xpetra_MapFactory.hpp>
#include <Xpetra_MatrixMatrix.hpp>
#include <Xpetra_MultiVectorFactory.hpp>
#include <Xpetra_TpetraMultiVector.hpp>

#include "signorini/core/Error.hpp"
#include "solver/linear/KrylovSolver.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"

namespace {

using namespace signorini;
using XMap = Xpetra::Map<LocalOrdinal, GlobalOrdinal, Node>;
using XMatrix = Xpetra::Matrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using XCrsWrap = Xpetra::CrsMatrixWrap<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using XMultiVector = Xpetra::MultiVector<Scalar, LocalOrdinal, GlobalOrdinal, Node>;

struct ElasticityProblem {
  RCP<CrsMatrix> A;
  RCP<MultiVector> nullspace;
};

ElasticityProblem galeriElasticity(int dim, int cellsPerDirection) {
  auto comm = Tpetra::getDefaultComm();
  Teuchos::ParameterList galeri;
  galeri.set("nx", cellsPerDirection);
  galeri.set("ny", cellsPerDirection);
  if (dim == 3) galeri.set("nz", cellsPerDirection);
  galeri.set("E", 1.0);
  galeri.set("nu", 0.3);
  auto nodeMap = Galeri::Xpetra::CreateMap<LocalOrdinal, GlobalOrdinal, Node>(
      Xpetra::UseTpetra, dim == 2 ? "Cartesian2D" : "Cartesian3D", comm, galeri);
  auto dofMap = Xpetra::MapFactory<LocalOrdinal, GlobalOrdinal, Node>::Build(nodeMap, dim);
  auto problem = Galeri::Xpetra::BuildProblem<Scalar, LocalOrdinal, GlobalOrdinal, XMap, XCrsWrap,
                                              XMultiVector>(dim == 2 ? "Elasticity2D" : "Elasticity3D",
                                                            dofMap, galeri);
  RCP<XMatrix> A = problem->BuildMatrix();
  RCP<XMultiVector> nullspace = problem->BuildNullspace();
  ElasticityProblem p;
  p.A = Xpetra::Helpers<Scalar, LocalOrdinal, GlobalOrdinal, Node>::Op2NonConstTpetraCrs(A);
  p.nullspace = rcp(new MultiVector(Xpetra::toTpetra(*nullspace), Teuchos::Copy));
  return p;
}

// CG + MueLu from a zero guess on a random right-hand side; returns the iteration count.
KrylovResult solveWithMueLu(const ElasticityProblem& p, int dim,
                            const Teuchos::ParameterList& mueluOverrides) {
  MueLuPreconditioner amg(mueluOverrides, dim, p.nullspace, Teuchos::null);
  amg.compute(p.A);
  auto b = rcp(new MultiVector(p.A->getRangeMap(), 1));
  b->randomize();
  auto x = rcp(new MultiVector(p.A->getDomainMap(), 1));
  KrylovSolver cg;
  KrylovResult r = cg.solve(p.A, amg.getOperator(), b, x, 1e-8, 500);

  // The residual Belos reports must be the true one.
  MultiVector res(*b, Teuchos::Copy);
  p.A->apply(*x, res, Teuchos::NO_TRANS, -1.0, 1.0);
  Teuchos::Array<double> rn(1), bn(1);
  res.norm2(rn());
  b->norm2(bn());
  EXPECT_LT(rn[0] / bn[0], 1.01e-8);
  return r;
}

TEST(MueLuParallel, Elasticity2DDefaultsConvergeFast) {
  auto p = galeriElasticity(2, 100);
  KrylovResult r = solveWithMueLu(p, 2, Teuchos::ParameterList());
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("2D elasticity, %d ranks: %d CG iterations\n",
                Tpetra::getDefaultComm()->getSize(), r.iterations);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 40);
}

// levelNonzeros counts the matrix given to compute() and each coarse level's, fewer at each
// level; nothing before a build.
TEST(MueLuParallel, LevelNonzerosCountEveryLevelsMatrix) {
  const ElasticityProblem p = galeriElasticity(3, 16);
  MueLuPreconditioner amg(Teuchos::ParameterList(), 3, p.nullspace, Teuchos::null);
  EXPECT_TRUE(amg.levelNonzeros().empty());
  amg.compute(p.A);
  const std::vector<long long> nonzeros = amg.levelNonzeros();
  const std::vector<MueLuPreconditioner::CoarseLevel> coarse = amg.coarseLevels();
  ASSERT_GE(coarse.size(), 1u);
  ASSERT_EQ(nonzeros.size(), coarse.size() + 1);
  EXPECT_EQ(nonzeros[0], static_cast<long long>(p.A->getGlobalNumEntries()));
  for (std::size_t l = 0; l < coarse.size(); ++l) {
    EXPECT_EQ(nonzeros[l + 1], static_cast<long long>(coarse[l].A->getGlobalNumEntries()));
    EXPECT_LT(nonzeros[l + 1], nonzeros[l]);
  }
}

TEST(MueLuParallel, Elasticity3DDefaultsConvergeFast) {
  auto p = galeriElasticity(3, 16);
  KrylovResult r = solveWithMueLu(p, 3, Teuchos::ParameterList());
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("3D elasticity, %d ranks: %d CG iterations\n",
                Tpetra::getDefaultComm()->getSize(), r.iterations);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 40);
}

// As the whole hierarchy, aggregation starts only at nodes whose row in the nodal graph is
// at least the 99th percentile of the row sizes: on a brick mesh of 16^3 cells two thirds of
// the nodes are interior with all 26 neighbours (27 nodes in the row), the rest have fewer;
// and it drops couplings below 0.01. A user's own min agg size and drop tol win; MueLu's own
// defaults elsewhere; either way CG converges fast.
TEST(MueLuParallel, WholeHierarchyAggregationTakesThe99thPercentileOfTheNodalRowSizes) {
  const ElasticityProblem p = galeriElasticity(3, 16);
  using Choice = MueLuPreconditioner::Aggregation;
  MueLuPreconditioner chosen(Teuchos::ParameterList(), 3, p.nullspace, Teuchos::null, Choice::WholeHierarchy);
  chosen.compute(p.A);
  EXPECT_EQ(chosen.parameters().get<int>("aggregation: min agg size"), 27);
  EXPECT_EQ(chosen.parameters().get<double>("aggregation: drop tol"), 0.01);

  Teuchos::ParameterList user;
  user.set("aggregation: min agg size", 4);
  user.set("aggregation: drop tol", 0.0);
  MueLuPreconditioner users(user, 3, p.nullspace, Teuchos::null, Choice::WholeHierarchy);
  users.compute(p.A);
  EXPECT_EQ(users.parameters().get<int>("aggregation: min agg size"), 4);
  EXPECT_EQ(users.parameters().get<double>("aggregation: drop tol"), 0.0);
  const MueLuPreconditioner below(Teuchos::ParameterList(), 3, p.nullspace, Teuchos::null, Choice::MueLuDefaults);
  EXPECT_FALSE(below.parameters().isParameter("aggregation: drop tol"));
  EXPECT_FALSE(below.parameters().isParameter("aggregation: min agg size"));

  auto b = rcp(new MultiVector(p.A->getRangeMap(), 1));
  b->randomize();
  auto x = rcp(new MultiVector(p.A->getDomainMap(), 1));
  const KrylovResult r = KrylovSolver().solve(p.A, chosen.getOperator(), b, x, 1e-8, 500);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 40);
}

// A smoother other than ours starts from the package's defaults plus the user's params,
// with or without a params sublist; the same smoother merges the user's params into ours.
TEST(MueLuParallel, UserSmootherTypeDropsOurSmootherParams) {
  Teuchos::ParameterList user;
  user.set("smoother: type", "RELAXATION");
  user.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  MueLuPreconditioner other(user, 2, Teuchos::null, Teuchos::null);
  const auto& sp = other.parameters().sublist("smoother: params");
  EXPECT_FALSE(sp.isParameter("chebyshev: degree"));
  EXPECT_EQ(sp.get<std::string>("relaxation: type"), "Symmetric Gauss-Seidel");
  EXPECT_TRUE(other.parameters().sublist("coarse: params").isParameter("chebyshev: degree"));

  Teuchos::ParameterList same;
  same.set("smoother: type", "CHEBYSHEV");
  same.sublist("smoother: params").set("chebyshev: degree", 3);
  MueLuPreconditioner merged(same, 2, Teuchos::null, Teuchos::null);
  const auto& mp = merged.parameters().sublist("smoother: params");
  EXPECT_EQ(mp.get<int>("chebyshev: degree"), 3);
  EXPECT_DOUBLE_EQ(mp.get<double>("chebyshev: ratio eigenvalue"), 7.0);
}

// Reuse types whose matrix products fail inside Trilinos 13.2 on contact Hessians are input
// errors, named with the ones that work, and so is "full", which never refreshes the hierarchy.
TEST(MueLuParallel, BrokenReuseTypesAreInputErrors) {
  for (const char* type : {"tP", "RP", "full"}) {
    Teuchos::ParameterList user;
    user.set("reuse: type", type);
    EXPECT_THROW(MueLuPreconditioner(user, 2, Teuchos::null, Teuchos::null), InputError) << type;
  }
  Teuchos::ParameterList smoothers;
  smoothers.set("reuse: type", "S");
  EXPECT_NO_THROW(MueLuPreconditioner(smoothers, 2, Teuchos::null, Teuchos::null));
}

// A reuse asked for a matrix of another pattern (A^2 after A) builds a new hierarchy: CG on
// A^2 takes as many iterations as with a hierarchy built for A^2 alone, where "RAP" reuse
// (A's prolongators and coarse matrices kept, the fine smoother refreshed) takes another
// number.
TEST(MueLuParallel, AReuseForAnotherPatternRebuilds) {
  const ElasticityProblem p = galeriElasticity(2, 24);
  ElasticityProblem squared = p;
  squared.A = rcp(new CrsMatrix(p.A->getRowMap(), 0));
  Tpetra::MatrixMatrix::Multiply(*p.A, false, *p.A, false, *squared.A);
  Teuchos::ParameterList user;
  user.set("reuse: type", "RAP");
  const auto iterations = [&](MueLuPreconditioner& amg) {
    auto b = rcp(new MultiVector(squared.A->getRangeMap(), 1));
    b->putScalar(1.0);
    auto x = rcp(new MultiVector(squared.A->getDomainMap(), 1));
    const KrylovResult r = KrylovSolver().solve(squared.A, amg.getOperator(), b, x, 1e-8, 1000);
    EXPECT_TRUE(r.converged);
    return r.iterations;
  };
  MueLuPreconditioner fresh(user, 2, p.nullspace, Teuchos::null), reused(user, 2, p.nullspace, Teuchos::null);
  fresh.compute(squared.A);
  reused.compute(p.A);
  reused.compute(squared.A, true);
  EXPECT_EQ(iterations(reused), iterations(fresh));
}

}  // namespace
