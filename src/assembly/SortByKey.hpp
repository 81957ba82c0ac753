#pragma once
// Sorting by an integer key: Boost's spreadsort, a radix sort, which orders the millions of
// (tag, place) records a mesh reader sorts several times faster than std::sort.
#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

#include <boost/sort/spreadsort/integer_sort.hpp>

namespace signorini::detail {

// Sorts `records` ascending by key(record), an integer; records of one key end in no
// particular order.
template <class T, class Key>
void sortByKey(std::vector<T>& records, const Key& key) {
  boost::sort::spreadsort::integer_sort(
      records.begin(), records.end(), [&key](const T& r, unsigned shift) { return key(r) >> shift; },
      [&key](const T& a, const T& b) { return key(a) < key(b); });
}

// Sorts `records` by `less`, a strict weak order that compares key(record) first: the radix
// sort by the key, then each run of one key by `less`.
template <class T, class Key, class Less>
void sortByKey(std::vector<T>& records, const Key& key, const Less& less) {
  sortByKey(records, key);
  for (auto first = records.begin(), end = first; first != records.end(); first = end) {
    for (end = first + 1; end != records.end() && key(*end) == key(*first);) ++end;
    if (end - first > 1) std::sort(first, end, less);
  }
}

// Sorts pairs of integers ascending: by the first, then the second.
template <class First, class Second>
void sortPairs(std::vector<std::pair<First, Second>>& pairs) {
  sortByKey(pairs, [](const std::pair<First, Second>& p) { return p.first; }, std::less<std::pair<First, Second>>());
}

}  // namespace signorini::detail
