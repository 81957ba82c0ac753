#include "signorini/BarrierHessianOperator.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_Vector.hpp>
#include <Teuchos_CommHelpers.hpp>

#include "signorini/Error.hpp"

namespace signorini {

BarrierHessianOperator::BarrierHessianOperator(RCP<const Operator> Q, RCP<const CrsMatrix> A)
    : Q_(std::move(Q)), A_(std::move(A)), D_(rcp(new Vector(A_->getRangeMap()))) {
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

bool BarrierHessianOperator::findPositionsInQPattern(const CrsMatrix& Q) const {
  position_.clear();
  constraint_.clear();
  coefficient_.clear();
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
          position_.push_back(e);
          constraint_.push_back(r);
          coefficient_.push_back(a.values(i) * a.values(k));
        }
      }
    }
  }
  int local = found ? 1 : 0, global = 0;
  Teuchos::reduceAll(*Q.getComm(), Teuchos::REDUCE_MIN, local, Teuchos::outArg(global));
  return global == 1;
}

RCP<CrsMatrix> BarrierHessianOperator::assemble() const { return assemble(*D_); }

RCP<CrsMatrix> BarrierHessianOperator::assemble(const Vector& D) const {
  auto Q = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q_);
  if (Q.is_null()) throw Error("BarrierHessianOperator::assemble needs Q as a CrsMatrix");
  if (inQPattern_ < 0) inQPattern_ = findPositionsInQPattern(*Q) ? 1 : 0;
  if (inQPattern_ == 1) {
    using Values = typename CrsMatrix::local_matrix_device_type::values_type;
    const auto qValues = Q->getLocalMatrixHost().values;
    Values values(Kokkos::view_alloc(Kokkos::WithoutInitializing, "H values"), qValues.extent(0));
    Kokkos::deep_copy(values, qValues);
    const auto d = D.getData(0);
    for (std::size_t e = 0; e < position_.size(); ++e)
      values(position_[e]) += d[constraint_[e]] * coefficient_[e];
    auto H = rcp(new CrsMatrix(Q->getCrsGraph(), values));
    H->fillComplete(Q->getDomainMap(), Q->getRangeMap());
    return H;
  }
  CrsMatrix DA(*A_, Teuchos::Copy);
  DA.leftScale(D);
  auto AtDA = rcp(new CrsMatrix(A_->getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(*A_, true, DA, false, *AtDA);
  return Tpetra::MatrixMatrix::add(1.0, false, *Q, 1.0, false, *AtDA);
}

RCP<BarrierHessianOperator> BarrierHessianOperator::onContactColumns() const {
  auto Q = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Q_);
  if (Q.is_null()) throw Error("BarrierHessianOperator::onContactColumns needs Q as a CrsMatrix");
  // 1 on the DOFs that appear in A, seen from Q's column map.
  Vector onDomain(A_->getDomainMap());
  {
    Vector onColumns(A_->getColMap());
    const auto a = A_->getLocalMatrixHost();
    auto c = onColumns.getDataNonConst();
    for (std::size_t e = 0; e < a.graph.entries.extent(0); ++e) c[a.graph.entries(e)] = 1.0;
    onDomain.doExport(onColumns, Export(A_->getColMap(), A_->getDomainMap()), Tpetra::ADD);
  }
  Vector onQColumns(Q->getColMap());
  onQColumns.doImport(onDomain, Import(Q->getDomainMap(), Q->getColMap()), Tpetra::INSERT);
  const auto contact = onQColumns.getData();

  const auto q = Q->getLocalMatrixHost();
  const LocalOrdinal rows = static_cast<LocalOrdinal>(q.numRows());
  Teuchos::Array<std::size_t> counts(rows, 0);
  for (LocalOrdinal r = 0; r < rows; ++r)
    for (auto e = q.graph.row_map(r); e < q.graph.row_map(r + 1); ++e)
      if (contact[q.graph.entries(e)] != 0.0) ++counts[r];
  auto Qc = rcp(new CrsMatrix(Q->getRowMap(), Q->getColMap(), counts()));
  Teuchos::Array<LocalOrdinal> cols;
  Teuchos::Array<Scalar> vals;
  for (LocalOrdinal r = 0; r < rows; ++r) {
    if (counts[r] == 0) continue;
    cols.clear();
    vals.clear();
    for (auto e = q.graph.row_map(r); e < q.graph.row_map(r + 1); ++e)
      if (contact[q.graph.entries(e)] != 0.0) {
        cols.push_back(q.graph.entries(e));
        vals.push_back(q.values(e));
      }
    Qc->insertLocalValues(r, cols(), vals());
  }
  Qc->fillComplete(Q->getDomainMap(), Q->getRangeMap());
  auto sliced = rcp(new BarrierHessianOperator(Qc, A_));
  sliced->setWeights(*D_);
  return sliced;
}

}  // namespace signorini
