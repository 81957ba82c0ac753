#include "solver/preconditioner/LocalBlock.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Collectives.hpp"

namespace signorini {

RCP<const Comm> selfComm() { return rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF)); }

namespace {

// Whether importing through `importer` only copies on this rank: the same rows, in the same
// order, none more or fewer.
bool copiesOnly(const Import& importer) {
  const std::size_t rows = importer.getTargetMap()->getNodeNumElements();
  return importer.getNumRemoteIDs() == 0 && importer.getNumPermuteIDs() == 0 && importer.getNumSameIDs() == rows &&
         importer.getSourceMap()->getNodeNumElements() == rows;
}

}  // namespace

RCP<CrsMatrix> importedBlock(const CrsMatrix& M, const RCP<const Map>& blockRows, const Import& importer,
                              const std::function<LocalOrdinal(GlobalOrdinal)>& columnIndex,
                              const RCP<const Map>& localRows, const RCP<const Map>& localColumns) {
  RCP<const CrsMatrix> gathered = Teuchos::rcpFromRef(M);
  // Collective, so every rank decides alike.
  if (!onEveryRank(*M.getComm(), copiesOnly(importer))) {
    // The range map must be one-to-one; blocks may share rows (a constraint in several blocks).
    const RCP<const Map> range = blockRows->isOneToOne() ? blockRows : Tpetra::createOneToOne(blockRows);
    gathered = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(gathered, importer, M.getDomainMap(), range);
  }
  if (localRows.is_null()) return Teuchos::null;

  // The kept entries, renumbered and sorted by column, straight into CSR arrays.
  const auto source = gathered->getLocalMatrixHost();
  const auto columns = gathered->getColMap();
  std::vector<LocalOrdinal> kept(columns->getNodeNumElements());  // gathered column -> local column
  for (std::size_t c = 0; c < kept.size(); ++c) kept[c] = columnIndex(columns->getGlobalElement(c));
  const LocalOrdinal numRows = source.numRows();
  Teuchos::ArrayRCP<std::size_t> rowStart(numRows + 1, 0);
  for (LocalOrdinal i = 0; i < numRows; ++i) {
    rowStart[i + 1] = rowStart[i];
    for (auto k = source.graph.row_map(i); k < source.graph.row_map(i + 1); ++k)
      if (kept[source.graph.entries(k)] >= 0) ++rowStart[i + 1];
  }
  Teuchos::ArrayRCP<LocalOrdinal> cols(rowStart[numRows]);
  Teuchos::ArrayRCP<Scalar> vals(rowStart[numRows]);
  std::vector<std::pair<LocalOrdinal, Scalar>> row;
  for (LocalOrdinal i = 0; i < numRows; ++i) {
    row.clear();
    for (auto k = source.graph.row_map(i); k < source.graph.row_map(i + 1); ++k)
      if (kept[source.graph.entries(k)] >= 0) row.emplace_back(kept[source.graph.entries(k)], source.values(k));
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < row.size(); ++k) {
      cols[rowStart[i] + k] = row[k].first;
      vals[rowStart[i] + k] = row[k].second;
    }
  }
  auto result = rcp(new CrsMatrix(localRows, localColumns, rowStart, cols, vals));
  result->expertStaticFillComplete(localColumns, localRows);
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
