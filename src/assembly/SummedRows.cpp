#include "assembly/SummedRows.hpp"

#include <algorithm>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>

namespace signorini {

SummedRows::SummedRows(std::vector<GlobalOrdinal> rowIds) : rowIds_(std::move(rowIds)), rows_(rowIds_.size()) {}

void SummedRows::add(std::size_t row, GlobalOrdinal column, double value) {
  auto& entries = rows_[row];
  const auto at = std::lower_bound(entries.begin(), entries.end(), column,
                                   [](const std::pair<GlobalOrdinal, double>& e, GlobalOrdinal c) { return e.first < c; });
  if (at != entries.end() && at->first == column)
    at->second += value;
  else
    entries.emplace(at, column, value);
}

RCP<const Map> SummedRows::addedRows(const RCP<const Comm>& comm) const {
  std::vector<GlobalOrdinal> ids;
  for (std::size_t i = 0; i < rows_.size(); ++i)
    if (!rows_[i].empty()) ids.push_back(rowIds_[i]);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, comm));
}

RCP<CrsMatrix> SummedRows::onOwners(const RCP<const Map>& rowMap, RCP<const Map> domainMap) const {
  if (domainMap.is_null()) domainMap = rowMap;
  const RCP<const Map> sourceRows = addedRows(rowMap->getComm());
  Teuchos::Array<std::size_t> counts;
  for (const auto& entries : rows_)
    if (!entries.empty()) counts.push_back(entries.size());
  auto source = rcp(new CrsMatrix(sourceRows, counts()));
  std::vector<GlobalOrdinal> columns;
  std::vector<double> values;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (rows_[i].empty()) continue;
    columns.clear();
    values.clear();
    for (const auto& [column, value] : rows_[i]) {
      columns.push_back(column);
      values.push_back(value);
    }
    source->insertGlobalValues(rowIds_[i], Teuchos::ArrayView<const GlobalOrdinal>(columns),
                               Teuchos::ArrayView<const double>(values));
  }
  source->fillComplete(domainMap, rowMap);
  // Tpetra adds the entries that meet in one row of the target.
  return Tpetra::exportAndFillCompleteCrsMatrix<CrsMatrix>(source, Export(sourceRows, rowMap), domainMap, rowMap);
}

RCP<CrsMatrix> SummedRows::onOwners(const RCP<const Comm>& comm) const {
  return onOwners(Tpetra::createOneToOne(addedRows(comm)));
}

}  // namespace signorini
