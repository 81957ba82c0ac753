#pragma once
// Algebraic multigrid for elasticity-type matrices through MueLu, built from a "MueLu"
// parameter list that is passed through unchanged, with the rigid body modes as nullspace.
#include <vector>

#include <MueLu_HierarchyManager_fwd.hpp>
#include <Teuchos_ParameterList.hpp>

#include "signorini/core/TpetraTypes.hpp"
#include "solver/preconditioner/MultilevelPreconditioner.hpp"

namespace signorini {

class MueLuPreconditioner : public MultilevelPreconditioner {
 public:
  // Defaults for vector problems with `blockSize` unknowns per node. They are correct on
  // any rank count with Debian's Trilinos 13.2, whose Amesos2 coarse solvers give wrong
  // answers on more than one rank: the coarse level is smoothed, not factored, and kept
  // small enough for that to be exact in practice (see tests/solver/test_muelu_parallel).
  static Teuchos::ParameterList defaultParameters(int blockSize);

  // The aggregation's defaults, where the user's list does not set them. WholeHierarchy, for
  // MueLu as the whole hierarchy of a fine unstructured mesh:
  // - "aggregation: min agg size" at the 99th percentile of the nodal row sizes (a node and
  //   its neighbours) of the first matrix, so that aggregation starts only from the
  //   best-connected nodes and grows around them: fewer, larger aggregates and a sparser
  //   coarse level, which is otherwise a tenth of the fine one and dense;
  // - "aggregation: drop tol" 0.01: the weakest couplings of the mesher's cells, and those
  //   across a contact between bodies, stay out of the aggregates (fewer CG iterations on
  //   Gmsh meshes, bench/results/algebraic-drop-tol; 0.02 is already too many in 2D).
  enum class Aggregation { MueLuDefaults, WholeHierarchy };

  // `params` is the user's "MueLu" list; entries it lacks are taken from defaultParameters.
  // `nullspace` lives on the DOF map, `coordinates` on the node map (either may be null).
  MueLuPreconditioner(const Teuchos::ParameterList& params, int blockSize,
                      RCP<const MultiVector> nullspace, RCP<const MultiVector> coordinates,
                      Aggregation aggregation = Aggregation::MueLuDefaults);

  // Builds the hierarchy for A. With `reuse`, a hierarchy built before for a matrix of the
  // same pattern is refreshed according to the list's "reuse: type" instead of rebuilt; for a
  // matrix of another pattern it is rebuilt. Collective.
  void compute(const RCP<CrsMatrix>& A, bool reuse = false) override;

  RCP<Operator> getOperator() const override;
  std::vector<long long> levelNonzeros() const override;
  const Teuchos::ParameterList& parameters() const { return params_; }
  // The coarse levels of the last hierarchy built, finest first: each one's matrix and the
  // prolongator from it to the level above (the first: to the matrix given to compute()).
  // Empty for a hierarchy of one level.
  struct CoarseLevel {
    RCP<CrsMatrix> P, A;
  };
  std::vector<CoarseLevel> coarseLevels() const;

 private:
  Teuchos::ParameterList params_;
  RCP<const MultiVector> nullspace_, coordinates_;
  bool highValenceRoots_;  // set aggregation: min agg size from the first matrix
  RCP<Operator> op_;
  RCP<const CrsMatrix> built_;  // the matrix of the last compute()
  // MueLu's factories, made from params_ at the first compute() and kept for the next ones.
  RCP<MueLu::HierarchyManager<Scalar, LocalOrdinal, GlobalOrdinal, Node>> factory_;
};

}  // namespace signorini
