// Sorting by an integer key: the order std::sort gives where the key and the comparison
// decide it, on records with many equal keys, negative keys and keys of every size.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "assembly/SortByKey.hpp"

namespace {

using signorini::detail::sortByKey;

// `count` records (key, payload), the keys drawn from [low, low + range).
std::vector<std::pair<long long, int>> records(std::size_t count, long long low, unsigned long long range,
                                               std::mt19937_64& random) {
  std::vector<std::pair<long long, int>> r(count);
  for (auto& [key, payload] : r) {
    key = low + static_cast<long long>(random() % range);
    payload = static_cast<int>(random() % 1000);
  }
  return r;
}

TEST(SortByKey, OrdersByTheKeyAlone) {
  std::mt19937_64 random(7);
  for (const auto& [low, range] : {std::pair<long long, unsigned long long>{0, 40}, {-1000, 2000},
                                   {-(1LL << 40), 1ULL << 41}, {1, 1ULL << 62}}) {
    auto r = records(200000, low, range, random);
    auto expected = r;
    sortByKey(r, [](const std::pair<long long, int>& x) { return x.first; });
    EXPECT_TRUE(std::is_sorted(r.begin(), r.end(), [](const auto& a, const auto& b) { return a.first < b.first; }));
    std::sort(expected.begin(), expected.end());
    std::sort(r.begin(), r.end());
    EXPECT_EQ(r, expected) << "the records are not a permutation of the input";
  }
}

TEST(SortByKey, WithAComparisonGivesItsOrderAmongEqualKeys) {
  std::mt19937_64 random(11);
  for (const unsigned long long range : {3ULL, 50ULL, 1ULL << 50}) {
    auto r = records(100000, -7, range, random);
    auto expected = r;
    std::sort(expected.begin(), expected.end());
    sortByKey(r, [](const std::pair<long long, int>& x) { return x.first; }, std::less<std::pair<long long, int>>());
    EXPECT_EQ(r, expected) << "keys in [-7, -7 + " << range << ")";
  }
}

TEST(SortByKey, SortsRecordsByTheirFirstFieldAndTheRest) {
  // Faces' keys of three sorted tags with a cell: a radix sort by the first tag, ties after.
  std::mt19937_64 random(13);
  std::vector<std::pair<std::array<long long, 3>, long long>> faces(50000);
  for (auto& [key, cell] : faces) {
    for (long long& tag : key) tag = 1 + static_cast<long long>(random() % 300);
    std::sort(key.begin(), key.end());
    cell = static_cast<long long>(random() % 4);
  }
  auto expected = faces;
  std::sort(expected.begin(), expected.end());
  sortByKey(faces, [](const auto& f) { return f.first[0]; }, std::less<std::pair<std::array<long long, 3>, long long>>());
  EXPECT_EQ(faces, expected);
}

TEST(SortByKey, SortsPairsOfUnsignedAndSignedIntegers) {
  // (Morton code, cell) pairs as the mesh code sorts them, with codes over all 64 bits.
  std::mt19937_64 random(17);
  std::vector<std::pair<std::uint64_t, long long>> codes(100000);
  for (auto& [code, cell] : codes) {
    code = random() >> (random() % 2 ? 0 : 56);
    cell = static_cast<long long>(random() % 100) - 50;
  }
  auto expected = codes;
  std::sort(expected.begin(), expected.end());
  signorini::detail::sortPairs(codes);
  EXPECT_EQ(codes, expected);
}

TEST(SortByKey, TakesEmptyAndSingleRecords) {
  std::vector<std::pair<long long, int>> none, one{{5, 1}};
  sortByKey(none, [](const auto& x) { return x.first; }, std::less<std::pair<long long, int>>());
  sortByKey(one, [](const auto& x) { return x.first; }, std::less<std::pair<long long, int>>());
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(one, (std::vector<std::pair<long long, int>>{{5, 1}}));
}

}  // namespace
