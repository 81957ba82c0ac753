#include "solver/preconditioner/LocalBlock.hpp"

#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

namespace signorini {

RCP<const Comm> selfComm() { return rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF)); }

RCP<CrsMatrix> importedBlock(const CrsMatrix& M, const RCP<const Map>& blockRows, const Import& importer,
                              const std::function<LocalOrdinal(GlobalOrdinal)>& columnIndex,
                              const RCP<const Map>& localRows, const RCP<const Map>& localColumns) {
  // The range map must be one-to-one; blocks may share rows (a constraint in several blocks).
  const RCP<const Map> range = blockRows->isOneToOne() ? blockRows : Tpetra::createOneToOne(blockRows);
  RCP<CrsMatrix> gathered =
      Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(Teuchos::rcpFromRef(M), importer, M.getDomainMap(), range);
  if (localRows.is_null()) return Teuchos::null;
  const LocalOrdinal numRows = static_cast<LocalOrdinal>(gathered->getNodeNumRows());
  const auto columns = gathered->getColMap();
  std::vector<LocalOrdinal> kept(columns->getNodeNumElements());  // gathered column -> local column
  for (std::size_t c = 0; c < kept.size(); ++c) kept[c] = columnIndex(columns->getGlobalElement(c));
  std::vector<std::vector<GlobalOrdinal>> keptCols(numRows);
  std::vector<std::vector<Scalar>> keptVals(numRows);
  Teuchos::Array<std::size_t> rowLengths(numRows);
  for (LocalOrdinal i = 0; i < numRows; ++i) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    gathered->getLocalRowView(i, cols, vals);
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      if (kept[cols(k)] < 0) continue;
      keptCols[i].push_back(kept[cols(k)]);
      keptVals[i].push_back(vals(k));
    }
    rowLengths[i] = keptCols[i].size();
  }
  auto result = rcp(new CrsMatrix(localRows, rowLengths()));
  for (LocalOrdinal i = 0; i < numRows; ++i)
    result->insertGlobalValues(i, Teuchos::ArrayView<const GlobalOrdinal>(keptCols[i]),
                               Teuchos::ArrayView<const Scalar>(keptVals[i]));
  result->fillComplete(localColumns, localRows);
  return result;
}

void copyLocalRows(const MultiVector& from, MultiVector& to) {
  for (std::size_t j = 0; j < from.getNumVectors(); ++j) {
    auto f = from.getData(j);
    auto t = to.getDataNonConst(j);
    for (std::size_t i = 0; i < from.getLocalLength(); ++i) t[i] = f[i];
  }
}

}  // namespace signorini
