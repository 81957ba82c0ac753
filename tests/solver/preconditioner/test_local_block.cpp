// Blocks of a distributed matrix copied onto one-rank communicators: each rank a block of its
// own rows (the import only copies when they lead its rows), and all rows gathered on rank 0.
#include <gtest/gtest.h>

#include <vector>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>

#include "solver/preconditioner/LocalBlock.hpp"

namespace {

using namespace signorini;

constexpr int kRowsPerRank = 6;

// A tridiagonal matrix with entry (i, j) = 10 i + j, kRowsPerRank rows on each rank.
RCP<CrsMatrix> tridiagonal() {
  auto comm = Tpetra::getDefaultComm();
  const GlobalOrdinal n = kRowsPerRank * comm->getSize();
  auto map = rcp(new Map(n, kRowsPerRank, 0, comm));
  auto M = rcp(new CrsMatrix(map, 3));
  for (LocalOrdinal k = 0; k < kRowsPerRank; ++k) {
    const GlobalOrdinal i = map->getGlobalElement(k);
    for (GlobalOrdinal j = i - 1; j <= i + 1; ++j)
      if (j >= 0 && j < n) M->insertGlobalValues(i, 1, std::vector<double>{10.0 * i + j}.data(), &j);
  }
  M->fillComplete();
  return M;
}

// The entries of `block` against M's at the rows and columns `ids` (block index -> global id).
void expectBlockOf(const CrsMatrix& block, const std::vector<GlobalOrdinal>& ids) {
  ASSERT_EQ(block.getNodeNumRows(), ids.size());
  for (std::size_t r = 0; r < ids.size(); ++r) {
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    block.getLocalRowView(static_cast<LocalOrdinal>(r), cols, vals);
    std::size_t expected = 0;
    for (GlobalOrdinal id : ids) expected += id >= ids[r] - 1 && id <= ids[r] + 1;
    EXPECT_EQ(cols.extent(0), expected) << "row " << r;
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      const GlobalOrdinal column = ids[block.getColMap()->getGlobalElement(cols(k))];
      EXPECT_EQ(vals(k), 10.0 * ids[r] + column) << "row " << r;
    }
  }
}

// The first half of each rank's rows: the import copies a prefix of the rows, and the block
// keeps those rows alone.
TEST(LocalBlock, OwnLeadingRowsPerRank) {
  const RCP<CrsMatrix> M = tridiagonal();
  const RCP<const Map> rows = M->getRowMap();
  std::vector<GlobalOrdinal> ids;
  for (LocalOrdinal k = 0; k < kRowsPerRank / 2; ++k) ids.push_back(rows->getGlobalElement(k));
  auto blockRows = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                               Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, rows->getComm()));
  const Import importer(rows, blockRows);
  auto local = rcp(new Map(ids.size(), 0, selfComm()));
  const auto index = [&](GlobalOrdinal gid) {
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (ids[k] == gid) return static_cast<LocalOrdinal>(k);
    return LocalOrdinal(-1);
  };
  const RCP<CrsMatrix> block = importedBlock(*M, blockRows, importer, index, local, local);
  ASSERT_FALSE(block.is_null());
  expectBlockOf(*block, ids);
}

// Every row on rank 0, nothing elsewhere.
TEST(LocalBlock, AllRowsGatheredOnRankZero) {
  const RCP<CrsMatrix> M = tridiagonal();
  auto comm = M->getRowMap()->getComm();
  const GlobalOrdinal n = kRowsPerRank * comm->getSize();
  std::vector<GlobalOrdinal> ids;
  if (comm->getRank() == 0)
    for (GlobalOrdinal i = 0; i < n; ++i) ids.push_back(i);
  auto blockRows = rcp(new Map(n, Teuchos::ArrayView<const GlobalOrdinal>(ids), 0, comm));
  const Import importer(M->getRowMap(), blockRows);
  const RCP<const Map> local = comm->getRank() == 0 ? rcp(new Map(n, 0, selfComm())) : Teuchos::null;
  const auto index = [](GlobalOrdinal gid) { return static_cast<LocalOrdinal>(gid); };
  const RCP<CrsMatrix> block = importedBlock(*M, blockRows, importer, index, local, local);
  if (comm->getRank() != 0) {
    EXPECT_TRUE(block.is_null());
    return;
  }
  ASSERT_FALSE(block.is_null());
  expectBlockOf(*block, ids);
}

}  // namespace
