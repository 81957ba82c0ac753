#pragma once
// Matrix rows summed from contributions of several ranks, as element-by-element assembly of
// a few rows makes them: each rank adds entries to rows it need not own (a row, with its
// global id, per local index), and the sums meet on the rows' owners. Entries of a row stay
// sorted by column and merged as they come, so a row holds no more than its distinct columns.
#include <utility>
#include <vector>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

class SummedRows {
 public:
  // rowIds[i]: the global id of local row i.
  explicit SummedRows(std::vector<GlobalOrdinal> rowIds);

  void add(std::size_t row, GlobalOrdinal column, double value);

  // The rows summed over the ranks, on `rowMap` (one-to-one), which is also the range map and,
  // unless given, the domain map; rows no rank added to are empty. Collective.
  RCP<CrsMatrix> onOwners(const RCP<const Map>& rowMap, RCP<const Map> domainMap = Teuchos::null) const;
  // The same on the one-to-one map of the rows added on all ranks.
  RCP<CrsMatrix> onOwners(const RCP<const Comm>& comm) const;

 private:
  std::vector<GlobalOrdinal> rowIds_;
  std::vector<std::vector<std::pair<GlobalOrdinal, double>>> rows_;

  RCP<const Map> addedRows(const RCP<const Comm>& comm) const;
};

}  // namespace signorini
