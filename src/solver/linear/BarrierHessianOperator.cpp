#include "solver/linear/BarrierHessianOperator.hpp"

#include <algorithm>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_RowMatrixTransposer.hpp>
#include <Tpetra_Vector.hpp>
#include <Teuchos_CommHelpers.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/StiffnessParts.hpp"

namespace signorini {

BarrierHessianOperator::BarrierHessianOperator(RCP<const Operator> Q, RCP<const CrsMatrix> A,
                                               RCP<const CrsMatrix> Qassembled)
    : Q_(std::move(Q)),
      Qmatrix_(Qassembled.is_null() ? Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q_) : std::move(Qassembled)),
      A_(std::move(A)),
      D_(rcp(new Vector(A_->getRangeMap()))) {
  if (!A_->getDomainMap()->isSameAs(*Q_->getDomainMap()))
    throw Error("BarrierHessianOperator: A's domain map differs from Q's");
}

void BarrierHessianOperator::setWeights(const Vector& D) { D_->assign(D); }

void BarrierHessianOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode,
                                   Scalar alpha, Scalar beta) const {
  const std::size_t numVectors = X.getNumVectors();
  if (AX_.is_null() || AX_->getNumVectors() != numVectors)
    AX_ = rcp(new MultiVector(A_->getRangeMap(), numVectors));
  A_->apply(X, *AX_);
  AX_->elementWiseMultiply(1.0, *D_, *AX_, 0.0);
  // Q is symmetric, its column slice (onContactColumns) is not; a matrix-free Q need not
  // offer a transpose at all.
  Q_->apply(X, Y, Q_->hasTransposeApply() ? mode : Teuchos::NO_TRANS, alpha, beta);
  A_->apply(*AX_, Y, Teuchos::TRANS, alpha, 1.0);
}

void BarrierHessianOperator::applyQ(const MultiVector& X, MultiVector& Y) const { Q_->apply(X, Y); }

void BarrierHessianOperator::applyGivenQX(const MultiVector& X, const MultiVector& QX, MultiVector& Y) const {
  const std::size_t numVectors = X.getNumVectors();
  if (AX_.is_null() || AX_->getNumVectors() != numVectors)
    AX_ = rcp(new MultiVector(A_->getRangeMap(), numVectors));
  A_->apply(X, *AX_);
  AX_->elementWiseMultiply(1.0, *D_, *AX_, 0.0);
  Y.assign(QX);
  A_->apply(*AX_, Y, Teuchos::TRANS, 1.0, 1.0);
}

bool BarrierHessianOperator::findPositionsInQPattern(const CrsMatrix& Q) const {
  contributions_.clear();
  bool found = A_->getRowMap()->isSameAs(*A_->getRangeMap()) && Q.isFillComplete();
  if (found) {
    const auto q = Q.getLocalMatrixHost();
    const auto a = A_->getLocalMatrixHost();
    const auto& aCols = *A_->getColMap();
    const auto& qRows = *Q.getRowMap();
    const auto& qCols = *Q.getColMap();
    const auto invalid = Teuchos::OrdinalTraits<LocalOrdinal>::invalid();
    for (LocalOrdinal r = 0; found && r < static_cast<LocalOrdinal>(a.numRows()); ++r) {
      for (auto i = a.graph.row_map(r); found && i < a.graph.row_map(r + 1); ++i) {
        const LocalOrdinal row = qRows.getLocalElement(aCols.getGlobalElement(a.graph.entries(i)));
        if (row == invalid) { found = false; break; }
        for (auto k = a.graph.row_map(r); k < a.graph.row_map(r + 1); ++k) {
          const LocalOrdinal col = qCols.getLocalElement(aCols.getGlobalElement(a.graph.entries(k)));
          const auto begin = q.graph.row_map(row), end = q.graph.row_map(row + 1);
          auto e = begin;
          while (e < end && q.graph.entries(e) != col) ++e;  // rows are short: a scan will do
          if (col == invalid || e == end) { found = false; break; }
          contributions_.push_back({static_cast<std::size_t>(e), row, r, a.values(i) * a.values(k)});
        }
      }
    }
  }
  std::stable_sort(contributions_.begin(), contributions_.end(),
                   [](const Contribution& a, const Contribution& b) { return a.position < b.position; });
  return onEveryRank(*Q.getComm(), found);
}

RCP<CrsMatrix> BarrierHessianOperator::assemble() const { return assemble(*D_); }

bool BarrierHessianOperator::assemblesOnQGraph() const {
  if (Qmatrix_.is_null()) throw Error("BarrierHessianOperator::assemble needs Q assembled");
  if (inQPattern_ < 0) inQPattern_ = findPositionsInQPattern(*Qmatrix_) ? 1 : 0;
  return inQPattern_ == 1;
}

RCP<CrsMatrix> BarrierHessianOperator::assemble(const Vector& D) const {
  const RCP<const CrsMatrix>& Q = Qmatrix_;
  if (assemblesOnQGraph()) {
    using Values = typename CrsMatrix::local_matrix_device_type::values_type;
    const auto qValues = Q->getLocalMatrixHost().values;
    Values values(Kokkos::view_alloc(Kokkos::WithoutInitializing, "H values"), qValues.extent(0));
    Kokkos::deep_copy(values, qValues);
    const auto d = D.getData(0);
    for (const Contribution& c : contributions_) values(c.position) += d[c.constraint] * c.coefficient;
    auto H = rcp(new CrsMatrix(Q->getCrsGraph(), values));
    H->fillComplete(Q->getDomainMap(), Q->getRangeMap());
    return H;
  }
  return assembleByProduct(*Q, D);
}

RCP<CrsMatrix> BarrierHessianOperator::updateAssembled(CrsMatrix& H, const Vector& D) const {
  if (!assemblesOnQGraph() || H.getCrsGraph() != Qmatrix_->getCrsGraph())
    throw Error("BarrierHessianOperator::updateAssembled needs H assembled on Q's graph");
  // Each position recomputed as assemble(D) computes it, in the same order: the same values.
  const auto q = Qmatrix_->getLocalMatrixHost().values;
  const auto values = H.getLocalMatrixHost().values;
  const auto d = D.getData(0);
  struct Changed {
    LocalOrdinal row;
    std::size_t position;
    double by;
  };
  std::vector<Changed> changed;
  for (std::size_t e = 0; e < contributions_.size();) {
    const std::size_t position = contributions_[e].position;
    double value = q(position);
    for (; e < contributions_.size() && contributions_[e].position == position; ++e)
      value += d[contributions_[e].constraint] * contributions_[e].coefficient;
    if (value != values(position)) {
      changed.push_back({contributions_[e - 1].row, position, value - values(position)});
      values(position) = value;
    }
  }
  // The changes as a matrix: positions ascend, and with them the rows.
  Teuchos::Array<std::size_t> counts(H.getNodeNumRows(), 0);
  for (const Changed& c : changed) ++counts[c.row];
  auto change = rcp(new CrsMatrix(H.getRowMap(), counts()));
  const auto columns = H.getLocalMatrixHost().graph.entries;
  const Map& rowMap = *H.getRowMap();
  const Map& colMap = *H.getColMap();
  std::vector<GlobalOrdinal> cols;
  std::vector<double> vals;
  for (std::size_t k = 0; k < changed.size();) {
    const LocalOrdinal row = changed[k].row;
    cols.clear();
    vals.clear();
    for (; k < changed.size() && changed[k].row == row; ++k) {
      cols.push_back(colMap.getGlobalElement(columns(changed[k].position)));
      vals.push_back(changed[k].by);
    }
    change->insertGlobalValues(rowMap.getGlobalElement(row), Teuchos::ArrayView<const GlobalOrdinal>(cols),
                               Teuchos::ArrayView<const double>(vals));
  }
  change->fillComplete(H.getDomainMap(), H.getRangeMap());
  return change;
}

struct BarrierHessianOperator::ProductPattern {
  RCP<const CrsMatrix> At;       // A^T: rows on Q's row map, columns the constraints that touch them
  RCP<const Import> toAtColumns;  // A's range map -> At's column map
  RCP<CrsMatrix> AtDA;           // its pattern is fixed by the first product
  RCP<const CrsMatrix::crs_graph_type> graph;  // of Q + A^T A
  std::vector<std::size_t> qPosition, productPosition;  // entry of Q, of AtDA -> entry of graph
};

namespace {

using Graph = CrsMatrix::crs_graph_type;

// The union of the patterns of Q and M, both with rows on Q's row map.
RCP<const Graph> unionPattern(const CrsMatrix& Q, const CrsMatrix& M) {
  const auto rowMap = Q.getRowMap();
  const LocalOrdinal rows = static_cast<LocalOrdinal>(rowMap->getNodeNumElements());
  std::vector<std::vector<GlobalOrdinal>> columns(rows);
  for (const CrsMatrix* matrix : {&Q, &M}) {
    const auto m = matrix->getLocalMatrixHost();
    const auto& mRows = *matrix->getRowMap();
    const auto& mCols = *matrix->getColMap();
    for (LocalOrdinal r = 0; r < static_cast<LocalOrdinal>(m.numRows()); ++r) {
      auto& row = columns[rowMap->getLocalElement(mRows.getGlobalElement(r))];
      for (auto e = m.graph.row_map(r); e < m.graph.row_map(r + 1); ++e)
        row.push_back(mCols.getGlobalElement(m.graph.entries(e)));
    }
  }
  Teuchos::Array<std::size_t> counts(rows);
  for (LocalOrdinal r = 0; r < rows; ++r) {
    std::sort(columns[r].begin(), columns[r].end());
    columns[r].erase(std::unique(columns[r].begin(), columns[r].end()), columns[r].end());
    counts[r] = columns[r].size();
  }
  auto graph = rcp(new Graph(rowMap, counts()));
  for (LocalOrdinal r = 0; r < rows; ++r)
    graph->insertGlobalIndices(rowMap->getGlobalElement(r), Teuchos::ArrayView<const GlobalOrdinal>(columns[r]));
  graph->fillComplete(Q.getDomainMap(), Q.getRangeMap());
  return graph;
}

// For each local entry of M, its position in the local entries of `pattern`, which holds
// every entry of M in a row this rank owns (fill complete: rows sorted).
std::vector<std::size_t> positionsIn(const Graph& pattern, const CrsMatrix& M) {
  const auto p = pattern.getLocalGraphHost();
  const auto m = M.getLocalMatrixHost();
  const auto& pRows = *pattern.getRowMap();
  const auto& pCols = *pattern.getColMap();
  const auto& mRows = *M.getRowMap();
  const auto& mCols = *M.getColMap();
  std::vector<std::size_t> position(m.values.extent(0));
  for (LocalOrdinal r = 0; r < static_cast<LocalOrdinal>(m.numRows()); ++r) {
    const LocalOrdinal row = pRows.getLocalElement(mRows.getGlobalElement(r));
    const auto begin = &p.entries(p.row_map(row));
    const auto end = begin + (p.row_map(row + 1) - p.row_map(row));
    for (auto e = m.graph.row_map(r); e < m.graph.row_map(r + 1); ++e) {
      const LocalOrdinal col = pCols.getLocalElement(mCols.getGlobalElement(m.graph.entries(e)));
      const auto at = std::lower_bound(begin, end, col);
      if (at == end || *at != col) throw Error("BarrierHessianOperator: an entry is missing from the pattern of Q + A^T A");
      position[e] = p.row_map(row) + (at - begin);
    }
  }
  return position;
}

}  // namespace

RCP<const CrsMatrix> BarrierHessianOperator::contactTerm(const Vector& D) const {
  using Values = typename CrsMatrix::local_matrix_device_type::values_type;
  if (!product_) {
    product_ = std::make_shared<ProductPattern>();
    product_->At = Tpetra::RowMatrixTransposer<Scalar, LocalOrdinal, GlobalOrdinal, Node>(A_).createTranspose();
    product_->toAtColumns = rcp(new Import(A_->getRangeMap(), product_->At->getColMap()));
    product_->AtDA = rcp(new CrsMatrix(product_->At->getRowMap(), 0));
    // The pattern of A^T A (the product skips zero weights: none here).
    Tpetra::MatrixMatrix::Multiply(*product_->At, false, *A_, false, *product_->AtDA);
  }
  ProductPattern& pp = *product_;
  // A^T D: A^T's values scaled by the weight of their column.
  Vector weights(pp.At->getColMap());
  weights.doImport(D, *pp.toAtColumns, Tpetra::INSERT);
  const auto at = pp.At->getLocalMatrixHost();
  Values scaled(Kokkos::view_alloc(Kokkos::WithoutInitializing, "A^T D values"), at.values.extent(0));
  const auto w = weights.getData();
  for (std::size_t e = 0; e < scaled.extent(0); ++e) scaled(e) = at.values(e) * w[at.graph.entries(e)];
  CrsMatrix AtD(pp.At->getCrsGraph(), scaled);
  AtD.fillComplete(pp.At->getDomainMap(), pp.At->getRangeMap());
  pp.AtDA->resumeFill();  // a filled result: the product reuses its pattern
  Tpetra::MatrixMatrix::Multiply(AtD, false, *A_, false, *pp.AtDA);
  return pp.AtDA;
}

RCP<CrsMatrix> BarrierHessianOperator::assembleByProduct(const CrsMatrix& Q, const Vector& D) const {
  using Values = typename CrsMatrix::local_matrix_device_type::values_type;
  const RCP<const CrsMatrix> AtDA = contactTerm(D);
  ProductPattern& pp = *product_;
  if (pp.graph.is_null()) {  // the pattern of Q + A^T A
    pp.graph = unionPattern(Q, *AtDA);
    pp.qPosition = positionsIn(*pp.graph, Q);
    pp.productPosition = positionsIn(*pp.graph, *AtDA);
  }
  Values values("H values", pp.graph->getNodeNumEntries());
  const auto q = Q.getLocalMatrixHost().values;
  const auto product = AtDA->getLocalMatrixHost().values;
  for (std::size_t e = 0; e < pp.qPosition.size(); ++e) values(pp.qPosition[e]) += q(e);
  for (std::size_t e = 0; e < pp.productPosition.size(); ++e) values(pp.productPosition[e]) += product(e);
  auto H = rcp(new CrsMatrix(pp.graph, values));
  H->fillComplete(Q.getDomainMap(), Q.getRangeMap());
  return H;
}

RCP<BarrierHessianOperator> BarrierHessianOperator::onContactColumns(const CrsMatrix& contactRows) const {
  const RCP<const Vector> contact = contactDofIndicator(*A_);
  if (!contactRows.getRowMap()->isSameAs(*contact->getMap()))
    throw Error("BarrierHessianOperator::onContactColumns: the contact rows are not on Q's row map");
  const auto onContact = contact->getData();
  // Q's rows at the contact DOFs, then their transpose: Q's columns there.
  const auto q = contactRows.getLocalMatrixHost();
  const LocalOrdinal rows = static_cast<LocalOrdinal>(q.numRows());
  Teuchos::Array<std::size_t> counts(rows, 0);
  for (LocalOrdinal r = 0; r < rows; ++r)
    if (onContact[r] != 0.0) counts[r] = q.graph.row_map(r + 1) - q.graph.row_map(r);
  auto Qr = rcp(new CrsMatrix(contactRows.getRowMap(), contactRows.getColMap(), counts()));
  for (LocalOrdinal r = 0; r < rows; ++r) {
    if (counts[r] == 0) continue;
    const auto begin = q.graph.row_map(r);
    Qr->insertLocalValues(r, Teuchos::ArrayView<const LocalOrdinal>(&q.graph.entries(begin), counts[r]),
                          Teuchos::ArrayView<const Scalar>(&q.values(begin), counts[r]));
  }
  Qr->fillComplete(contactRows.getDomainMap(), contactRows.getRangeMap());
  const RCP<CrsMatrix> Qc = Tpetra::RowMatrixTransposer<Scalar, LocalOrdinal, GlobalOrdinal, Node>(Qr).createTranspose();
  auto sliced = rcp(new BarrierHessianOperator(Qc, A_));
  sliced->setWeights(*D_);
  return sliced;
}

}  // namespace signorini
