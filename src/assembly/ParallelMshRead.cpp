#include "assembly/ParallelMshRead.hpp"

#include <mpi.h>
#include <ptscotch.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "assembly/SortByKey.hpp"
#include "assembly/SortedVertexKey.hpp"
#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "core/RootTask.hpp"
#include "core/SplitMixHash.hpp"
#include "fe/MortonCode.hpp"
#include "fe/MshFileSlice.hpp"
#include "fe/SimplexOrientation.hpp"
#include "signorini/core/Error.hpp"

namespace signorini::detail {
namespace {

using Key = SortedVertexKey;  // of a face's node tags

// Faces a rank matches in one round: the faces are matched in rounds, by their hashes, so that
// their records take a bounded memory.
constexpr long long kFacesPerRound = 1 << 21;

using Face = std::pair<Key, long long>;  // a face's key and a cell it is a face of

// Sorts faces by key and cell (a radix sort by the key's first tag, then the runs of one).
void sortFaces(std::vector<Face>& faces) {
  sortByKey(faces, [](const Face& f) { return f.first[0]; }, std::less<Face>());
}

// The distinct values of tagAt(0 .. count - 1), ascending, and in `place` each entry's index
// among them: one radix sort of (tag, entry) pairs instead of a search or a hash lookup per
// entry.
template <class TagAt>
std::vector<long long> distinctTags(std::size_t count, TagAt&& tagAt, std::vector<std::size_t>& place) {
  std::vector<std::pair<long long, std::size_t>> byTag(count);
  for (std::size_t i = 0; i < count; ++i) byTag[i] = {tagAt(i), i};
  sortByKey(byTag, [](const std::pair<long long, std::size_t>& r) { return r.first; });
  std::vector<long long> tags;
  place.resize(count);
  for (const auto& [tag, i] : byTag) {
    if (tags.empty() || tags.back() != tag) tags.push_back(tag);
    place[i] = tags.size() - 1;
  }
  return tags;
}

// What the reading ranks know between the steps. Cells are numbered globally, rank r holding
// the range [cellStart_[r], cellStart_[r + 1]): first by their index in the file's sequence of
// cells, then by their place along a Morton curve.
class ParallelRead {
 public:
  ParallelRead(const RCP<const Comm>& comm, const std::string& path, MshFileSlice&& slice)
      : comm_(comm), prefix_("Gmsh mesh file '" + path + "': "), slice_(std::move(slice)),
        d_(slice_.dim), rank_(comm->getRank()), size_(comm->getSize()) {
    for (int r = 0; r <= size_; ++r)
      cellStart_.push_back(MshFileSlice::sliceStart(slice_.numCells, r, size_));
  }

  GmshMeshPart part() {
    if (slice_.numCells < size_)
      throw InputError(prefix_ + "it has " + std::to_string(slice_.numCells) + " cells, fewer than the " +
                       std::to_string(size_) + " ranks");
    step("curve order", [this] { orderCellsAlongCurve(); });
    step("face matching", [this] { faceDirectory(); });
    step("partition", [this] { partition(); });
    step("migration", [this] {
      facetsToParts();
      migrateCells();
    });
    GmshMeshPart result;
    step("part", [&] { result = assemble(); });
    return result;
  }

 private:
  // Runs one step of the reading under its timer in the log's table ("mesh read: <name>").
  template <class Step>
  static void step(const std::string& name, const Step& run) {
    const Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space: mesh read: " + name));
    run();
  }

  int cellOwner(long long cell) const {
    return static_cast<int>(std::upper_bound(cellStart_.begin(), cellStart_.end(), cell) - cellStart_.begin()) - 1;
  }
  long long numLocalCells() const { return cellStart_[rank_ + 1] - cellStart_[rank_]; }

  // Puts the cells in the order of their centroids along a Morton curve, rank r holding the
  // places [cellStart_[r], cellStart_[r + 1]) of it. A mesher writes cells in an order that
  // scatters them in space; in this one most faces of a slice's cells are shared within the
  // slice, and most edges of the dual graph join cells of one rank.
  void orderCellsAlongCurve() {
    const std::vector<long long> places = placesAlongCurve(centroidCodes());
    const std::size_t width = d_ + 4;  // place, element, body, d + 1 nodes
    const std::vector<long long> cells = sendCells(width, [&](long long c) { return cellOwner(places[c]); },
                                                   [&](long long c, long long* to) {
                                                     to[0] = places[c];
                                                     cellRecord(c, to + 1);
                                                   });
    for (std::size_t at = 0; at < cells.size(); at += width) {
      const long long c = cells[at] - cellStart_[rank_];
      slice_.cellElements[c] = cells[at + 1];
      if (!slice_.cellBodies.empty()) slice_.cellBodies[c] = static_cast<int>(cells[at + 2]);
      std::copy(&cells[at + 3], &cells[at + width], &slice_.cellNodes[(d_ + 1) * c]);
    }
  }

  // Slice cell c's element, body and nodes in `to`.
  void cellRecord(long long c, long long* to) const {
    to[0] = slice_.cellElements[c];
    to[1] = slice_.cellBodies.empty() ? 0 : slice_.cellBodies[c];
    std::copy(&slice_.cellNodes[(d_ + 1) * c], &slice_.cellNodes[(d_ + 1) * (c + 1)], to + 2);
  }

  // Sends rank destination(c) a record of `width` numbers, write(c, record), for each slice
  // cell c; returns the records received, by sending rank. Packed in one array: the cells are
  // the largest data the ranks exchange.
  template <class Destination, class Write>
  std::vector<long long> sendCells(std::size_t width, const Destination& destination, const Write& write) const {
    std::vector<int> count(size_, 0);
    for (long long c = 0; c < numLocalCells(); ++c) count[destination(c)] += static_cast<int>(width);
    std::vector<std::size_t> next(size_, 0);
    std::partial_sum(count.begin(), count.end() - 1, next.begin() + 1);
    std::vector<long long> sent(width * numLocalCells());
    for (long long c = 0; c < numLocalCells(); ++c) {
      write(c, &sent[next[destination(c)]]);
      next[destination(c)] += width;
    }
    return exchangePacked(*comm_, sent, count);
  }

  // The slice cells' (Morton code of the centroid, global cell) pairs, the curve through the
  // box of the file's nodes.
  std::vector<long long> centroidCodes() {
    double lower[3], upper[3];
    for (int c = 0; c < 3; ++c) {
      lower[c] = INFINITY;
      upper[c] = -INFINITY;
      for (std::size_t v = 0; v < slice_.nodeTags.size(); ++v) {
        lower[c] = std::min(lower[c], slice_.nodeCoordinates[3 * v + c]);
        upper[c] = std::max(upper[c], slice_.nodeCoordinates[3 * v + c]);
      }
      lower[c] = minOverRanks(*comm_, lower[c]);
      upper[c] = maxOverRanks(*comm_, upper[c]);
    }
    std::vector<std::size_t> slot;  // of each cell node among the tags
    const std::vector<long long> tags =
        distinctTags(slice_.cellNodes.size(), [&](std::size_t i) { return slice_.cellNodes[i]; }, slot);
    const std::vector<double> xyz = exchangeWithRanks(*comm_, coordinatesFor(exchangeWithRanks(*comm_, byNodeDirectory(tags))));
    std::vector<long long> codes;
    codes.reserve(2 * numLocalCells());
    for (long long c = 0; c < numLocalCells(); ++c) {
      double x[3] = {0, 0, 0};
      for (int i = 0; i <= d_; ++i) {
        const std::size_t at = slot[(d_ + 1) * c + i];
        for (int k = 0; k < d_; ++k) x[k] += xyz[3 * at + k] / (d_ + 1);
      }
      codes.insert(codes.end(), {static_cast<long long>(mortonCode(x, lower, upper, d_)), cellStart_[rank_] + c});
    }
    return codes;
  }

  // The place of each slice cell in the order of the (code, global cell) pairs `codes` over
  // all ranks: a sample sort of the pairs, which then go back to their cells' ranks.
  std::vector<long long> placesAlongCurve(std::vector<long long> codes) const {
    using Code = std::pair<long long, long long>;
    std::vector<Code> sorted(codes.size() / 2);
    for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = {codes[2 * i], codes[2 * i + 1]};
    sortPairs(sorted);
    std::vector<long long> sample;
    const std::size_t samples = std::min<std::size_t>(sorted.size(), 64);
    for (std::size_t s = 0; s < samples; ++s) {
      const Code& code = sorted[s * sorted.size() / samples];
      sample.insert(sample.end(), {code.first, code.second});
    }
    const std::vector<long long> all = exchangeWithRanksJoined(*comm_, std::vector<std::vector<long long>>(size_, sample));
    std::vector<Code> splitters(all.size() / 2);
    for (std::size_t k = 0; k < splitters.size(); ++k) splitters[k] = {all[2 * k], all[2 * k + 1]};
    std::sort(splitters.begin(), splitters.end());
    std::vector<std::vector<long long>> toRank(size_);
    for (const Code& code : sorted) {  // to the rank of the range between two splitters it is in
      const std::size_t below = std::upper_bound(splitters.begin(), splitters.end(), code) - splitters.begin();
      auto& to = toRank[below * size_ / (splitters.size() + 1)];
      to.insert(to.end(), {code.first, code.second});
    }
    codes = exchangeWithRanksJoined(*comm_, toRank);
    sorted.resize(codes.size() / 2);
    for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = {codes[2 * i], codes[2 * i + 1]};
    sortPairs(sorted);
    long long end = 0, count = static_cast<long long>(sorted.size());
    Teuchos::scan(*comm_, Teuchos::REDUCE_SUM, 1, &count, &end);
    toRank.assign(size_, {});
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      auto& to = toRank[cellOwner(sorted[i].second)];
      to.insert(to.end(), {sorted[i].second, end - count + static_cast<long long>(i)});
    }
    codes = exchangeWithRanksJoined(*comm_, toRank);
    std::vector<long long> places(numLocalCells());
    for (std::size_t i = 0; i < codes.size(); i += 2) places[codes[i] - cellStart_[rank_]] = codes[i + 1];
    return places;
  }

  // Node tags by the rank whose slice of the file defines them. The slices are ascending
  // ranges of tags, so ascending tags stay ascending when the blocks are joined in rank order.
  std::vector<std::vector<long long>> byNodeDirectory(const std::vector<long long>& tags) const {
    std::vector<std::vector<long long>> asked(size_);
    for (long long tag : tags)
      asked[MshFileSlice::sliceOfNode(tag, slice_.minNodeTag, slice_.maxNodeTag, size_)].push_back(tag);
    return asked;
  }

  // The answers to each rank's questions (node tags this slice defines): x, y, z of each.
  std::vector<std::vector<double>> coordinatesFor(const std::vector<std::vector<long long>>& questions) {
    std::vector<std::vector<double>> coordinates(size_);
    runOnEveryRank(*comm_, [&] {
      for (int r = 0; r < size_; ++r)
        for (long long tag : questions[r]) {
          const double* x = &slice_.nodeCoordinates[3 * heldNode(tag)];
          coordinates[r].insert(coordinates[r].end(), x, x + 3);
        }
    });
    return coordinates;
  }

  // Where the slice holds node `tag`, which its tag range includes; a tag the file does not
  // define is an input error.
  std::size_t heldNode(long long tag) {
    if (heldNodes_.empty()) {
      heldNodes_.resize(slice_.nodeTags.size());
      for (std::size_t i = 0; i < heldNodes_.size(); ++i) heldNodes_[i] = {slice_.nodeTags[i], i};
      sortPairs(heldNodes_);
    }
    const auto it = std::lower_bound(heldNodes_.begin(), heldNodes_.end(), std::make_pair(tag, std::size_t{0}));
    if (it == heldNodes_.end() || it->first != tag)
      throw InputError(prefix_ + "a cell uses node " + std::to_string(tag) + ", which the file does not define");
    return it->second;
  }

  // The cells' neighbours across faces, and a cell for each boundary facet. Each rank first
  // matches the faces of its own slice (most of them, the cells being in curve order); the
  // faces left with one cell, and the facets not found, go to the directory rank of their
  // key, which matches them across slices; a facet still not found is looked for by every
  // rank (a face inside another slice: an interface facet).
  void faceDirectory() {
    const long long rounds = maxOverRanks(*comm_, numLocalCells() * (d_ + 1)) / kFacesPerRound + 1;
    std::vector<long long> adjacent, across, pending;  // (cell, neighbour) pairs within the slice, across slices; facets not found
    adjacent.reserve(2 * (d_ + 1) * numLocalCells());
    for (long long round = 0; round < rounds; ++round) {
      const auto inRound = [&](const Key& key, int& directory) {
        const std::uint64_t h = splitMixHash(key.begin(), key.end());  // the directory: h modulo the ranks
        directory = static_cast<int>(h % static_cast<std::uint64_t>(size_));
        return static_cast<long long>(h / static_cast<std::uint64_t>(size_) % static_cast<std::uint64_t>(rounds)) == round;
      };
      std::vector<Face> faces = sliceFaces(inRound);
      std::vector<std::vector<long long>> single(size_), unfound(size_);
      runOnEveryRank(*comm_, [&] {
        matchFaces(faces, adjacent, [&](const Face& face) {
          int directory = 0;
          inRound(face.first, directory);
          single[directory].insert(single[directory].end(), face.first.begin(), face.first.end());
          single[directory].push_back(face.second);
        });
        matchFacets(sliceFacets(inRound), faces, [&](const long long* facet) {
          int directory = 0;
          inRound(Key{facet[0], facet[1], facet[2]}, directory);
          unfound[directory].insert(unfound[directory].end(), facet, facet + 5 + d_);
        });
      });
      faces = unpacked(exchangeWithRanksJoined(*comm_, single));
      const std::vector<long long> facets = exchangeWithRanksJoined(*comm_, unfound);
      runOnEveryRank(*comm_, [&] {
        matchFaces(faces, across, [](const Face&) {});
        matchFacets(facets, faces, [&](const long long* facet) { pending.insert(pending.end(), facet, facet + 5 + d_); });
      });
    }
    findPendingFacets(pending);
    const std::vector<long long> received = exchangeWithRanksJoined(*comm_, pairsByOwner(across));
    adjacent.insert(adjacent.end(), received.begin(), received.end());
    adjacencyFrom(adjacent);
  }

  // The slice cells' faces of the round.
  template <class InRound>
  std::vector<Face> sliceFaces(const InRound& inRound) const {
    std::vector<Face> faces;
    int directory = 0;
    for (long long c = 0; c < numLocalCells(); ++c)
      for (int omit = 0; omit <= d_; ++omit) {
        long long tags[3];
        for (int i = 0, k = 0; i <= d_; ++i)
          if (i != omit) tags[k++] = slice_.cellNodes[(d_ + 1) * c + i];
        const Key key = sortedVertexKey(tags, d_);
        if (inRound(key, directory)) faces.emplace_back(key, cellStart_[rank_] + c);
      }
    return faces;
  }

  // The slice's boundary facets of the round: key, element, group, nodes.
  template <class InRound>
  std::vector<long long> sliceFacets(const InRound& inRound) const {
    std::vector<long long> facets;
    int directory = 0;
    for (std::size_t f = 0; f < slice_.facetTags.size(); ++f) {
      const long long* nodes = slice_.facetNodes.data() + d_ * f;
      const Key key = sortedVertexKey(nodes, d_);
      if (!inRound(key, directory)) continue;
      facets.insert(facets.end(), key.begin(), key.end());
      facets.push_back(slice_.facetElements[f]);
      facets.push_back(slice_.facetTags[f]);
      facets.insert(facets.end(), nodes, nodes + d_);
    }
    return facets;
  }

  static std::vector<Face> unpacked(const std::vector<long long>& records) {
    std::vector<Face> faces(records.size() / 4);
    for (std::size_t f = 0; f < faces.size(); ++f)
      faces[f] = {{records[4 * f], records[4 * f + 1], records[4 * f + 2]}, records[4 * f + 3]};
    return faces;
  }

  // Sorts `faces`; two cells on one face are neighbours (the pair and its reverse appended
  // to `adjacent`); a face of one cell goes to `alone`; a face of more than two is an error.
  template <class Alone>
  void matchFaces(std::vector<Face>& faces, std::vector<long long>& adjacent, const Alone& alone) const {
    sortFaces(faces);
    for (std::size_t first = 0, end = 0; first < faces.size(); first = end) {
      for (end = first + 1; end < faces.size() && faces[end].first == faces[first].first;) ++end;
      if (end - first > 2) notConforming(faces[first].first);
      if (end - first == 1) alone(faces[first]);
      if (end - first == 2)
        adjacent.insert(adjacent.end(), {faces[first].second, faces[first + 1].second, faces[first + 1].second,
                                         faces[first].second});
    }
  }

  // Each facet (records of 5 + d) whose face is among the sorted `faces` is held here with the
  // lowest of its cells; the others go to `unfound`.
  template <class Unfound>
  void matchFacets(const std::vector<long long>& facets, const std::vector<Face>& faces, const Unfound& unfound) {
    const std::size_t record = 5 + d_;
    for (std::size_t f = 0; f < facets.size(); f += record) {
      const Key key{facets[f], facets[f + 1], facets[f + 2]};
      const auto it = std::lower_bound(faces.begin(), faces.end(), Face(key, LLONG_MIN));
      if (it == faces.end() || it->first != key) {
        unfound(&facets[f]);
        continue;
      }
      heldFacets_.insert(heldFacets_.end(), facets.begin() + f, facets.begin() + f + record);
      facetCells_.push_back(it->second);
    }
  }

  // The facets no directory found, shown to every rank: the one whose slice has a cell with
  // that face holds the facet; a facet no rank finds is no face of the mesh.
  void findPendingFacets(const std::vector<long long>& pending) {
    if (sumOverRanks(*comm_, static_cast<long long>(pending.size())) == 0) return;
    const std::vector<long long> all = exchangeWithRanksJoined(*comm_, std::vector<std::vector<long long>>(size_, pending));
    const std::size_t record = 5 + d_;
    std::vector<int> found(all.size() / record, 1), foundAnywhere(found.size(), 0);
    std::vector<Face> faces = sliceFaces([](const Key&, int&) { return true; });
    sortFaces(faces);
    matchFacets(all, faces, [&](const long long* facet) { found[(facet - all.data()) / record] = 0; });
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, static_cast<int>(found.size()), found.data(), foundAnywhere.data());
    for (std::size_t f = 0; f < found.size(); ++f)
      if (!foundAnywhere[f]) notAFace(all[record * f + 3], static_cast<int>(all[record * f + 4]));
  }

  // The (cell, neighbour) pairs by the rank whose slice holds the cell.
  std::vector<std::vector<long long>> pairsByOwner(const std::vector<long long>& adjacent) const {
    std::vector<std::vector<long long>> toOwner(size_);
    for (std::size_t i = 0; i < adjacent.size(); i += 2) {
      auto& to = toOwner[cellOwner(adjacent[i])];
      to.push_back(adjacent[i]);
      to.push_back(adjacent[i + 1]);
    }
    return toOwner;
  }

  // The slice cells' neighbours (CSR) from their (cell, neighbour) pairs.
  void adjacencyFrom(const std::vector<long long>& adjacent) {
    adjacencyStart_.assign(numLocalCells() + 1, 0);
    for (std::size_t i = 0; i < adjacent.size(); i += 2) ++adjacencyStart_[adjacent[i] - cellStart_[rank_] + 1];
    std::partial_sum(adjacencyStart_.begin(), adjacencyStart_.end(), adjacencyStart_.begin());
    adjacency_.resize(adjacent.size() / 2);
    std::vector<long long> next(adjacencyStart_.begin(), adjacencyStart_.end() - 1);
    for (std::size_t i = 0; i < adjacent.size(); i += 2)
      adjacency_[next[adjacent[i] - cellStart_[rank_]]++] = adjacent[i + 1];
  }

  [[noreturn]] void notConforming(const Key& key) const {
    std::string nodes;
    for (int i = 0; i < d_; ++i) nodes += (i ? ", " : "") + std::to_string(key[i]);
    throw InputError(prefix_ + "the " + (d_ == 2 ? "edge" : "face") + " of nodes " + nodes +
                     " is a side of more than two cells: the mesh is not conforming or repeats a cell");
  }

  [[noreturn]] void notAFace(long long element, int group) const {
    std::string name = "physical" + std::to_string(group);
    for (const auto& [n, tag] : slice_.boundaryTags)
      if (tag == group) name = n;
    throw InputError(prefix_ + "boundary element " + std::to_string(element) + " of the group \"" + name +
                     "\" is not " + (d_ == 2 ? "an edge" : "a face") + " of any cell of the mesh");
  }

  // PT-Scotch's partition of the cells' dual graph into one part per rank.
  void partition() {
    part_.assign(numLocalCells(), 0);
    if (size_ == 1) return;
    if (slice_.numCells > INT_MAX) throw InputError(prefix_ + "more cells than PT-Scotch's 32-bit numbers can hold");
    std::vector<SCOTCH_Num> vertices(adjacencyStart_.begin(), adjacencyStart_.end());
    std::vector<SCOTCH_Num> edges(adjacency_.begin(), adjacency_.end());
    std::vector<SCOTCH_Num> parts(part_.size());
    const MPI_Comm raw = *dynamic_cast<const Teuchos::MpiComm<int>&>(*comm_).getRawMpiComm();
    // A context that makes PT-Scotch deterministic: the same partition at every run.
    SCOTCH_Context context;
    SCOTCH_Dgraph graph, bound;
    SCOTCH_Strat strategy;
    SCOTCH_contextInit(&context);
    SCOTCH_stratInit(&strategy);
    SCOTCH_stratDgraphMapBuild(&strategy, SCOTCH_STRATSPEED, size_, size_, 0.03);  // parts within 3% of the mean
    // One thread: PT-Scotch's threads call MPI, which this program initialises single-threaded.
    bool ok = SCOTCH_contextThreadSpawn(&context, 1, nullptr) == 0 &&
              SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMDETERMINISTIC, 1) == 0 &&
              SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMRANDOMFIXEDSEED, 1) == 0 &&
              SCOTCH_dgraphInit(&graph, raw) == 0;
    ok = ok && SCOTCH_dgraphBuild(&graph, 0, static_cast<SCOTCH_Num>(numLocalCells()),
                                  static_cast<SCOTCH_Num>(numLocalCells()), vertices.data(), vertices.data() + 1,
                                  nullptr, nullptr, static_cast<SCOTCH_Num>(edges.size()),
                                  static_cast<SCOTCH_Num>(edges.size()), edges.data(), nullptr, nullptr) == 0;
    ok = ok && SCOTCH_dgraphInit(&bound, raw) == 0 && SCOTCH_contextBindDgraph(&context, &graph, &bound) == 0;
    ok = ok && SCOTCH_dgraphPart(&bound, static_cast<SCOTCH_Num>(size_), &strategy, parts.data()) == 0;
    SCOTCH_dgraphExit(&bound);
    SCOTCH_dgraphExit(&graph);
    SCOTCH_stratExit(&strategy);
    SCOTCH_contextExit(&context);
    if (!onEveryRank(*comm_, ok)) throw Error(prefix_ + "PT-Scotch could not partition the mesh's cells");
    std::copy(parts.begin(), parts.end(), part_.begin());
    adjacency_ = {};
    adjacencyStart_ = {};
  }

  // The directory asks the slice owners of its facets' cells for their parts and sends each
  // facet (element, group, nodes) to its cell's part.
  void facetsToParts() {
    std::vector<std::vector<long long>> asked(size_);
    for (long long cell : facetCells_) asked[cellOwner(cell)].push_back(cell);
    const std::vector<std::vector<long long>> questions = exchangeWithRanks(*comm_, asked);
    std::vector<std::vector<long long>> answers(size_);
    for (int r = 0; r < size_; ++r)
      for (long long cell : questions[r]) answers[r].push_back(part_[cell - cellStart_[rank_]]);
    const std::vector<std::vector<long long>> parts = exchangeWithRanks(*comm_, answers);
    std::vector<std::size_t> next(size_, 0);
    std::vector<std::vector<long long>> toPart(size_);
    const std::size_t record = 5 + d_;
    for (std::size_t f = 0; f < facetCells_.size(); ++f) {
      const int owner = cellOwner(facetCells_[f]);
      auto& to = toPart[parts[owner][next[owner]++]];
      to.insert(to.end(), heldFacets_.begin() + record * f + 3, heldFacets_.begin() + record * (f + 1));
    }
    heldFacets_ = exchangeWithRanksJoined(*comm_, toPart);  // (element, group, d nodes) per facet
    facetCells_ = {};
  }

  // Each slice cell (element, body, nodes) to its part.
  void migrateCells() {
    cells_ = sendCells(d_ + 3, [&](long long c) { return part_[c]; }, [&](long long c, long long* to) { cellRecord(c, to); });
    slice_.cellElements = {};
    slice_.cellNodes = {};
    slice_.cellBodies = {};
  }

  GmshMeshPart assemble();
  void vertexData(GmshMeshPart& part);
  void cellsAndFacets(GmshMeshPart& part) const;

  RCP<const Comm> comm_;
  std::string prefix_;
  MshFileSlice slice_;
  int d_, rank_, size_;
  std::vector<long long> cellStart_;                  // global cells of rank r: [cellStart_[r], cellStart_[r + 1])
  std::vector<long long> adjacencyStart_, adjacency_;  // the slice cells' neighbours (CSR)
  std::vector<long long> heldFacets_;                  // where found, then at the part
  std::vector<long long> facetCells_;                  // the cell of each held facet, where found
  std::vector<int> part_;                              // the part of each slice cell
  std::vector<std::pair<long long, std::size_t>> heldNodes_;  // (tag, index in slice_), sorted
  std::vector<long long> cells_;                       // the part's cells: element, body, d + 1 nodes
  std::vector<std::size_t> cellVertices_;              // the part's vertex of each node of cells_
};

// The part's vertices (the node tags of its cells, ascending) with their coordinates and the
// parts that share them, from the directory that holds each node tag's slice.
void ParallelRead::vertexData(GmshMeshPart& part) {
  const std::size_t record = d_ + 3, nodes = d_ + 1;
  std::vector<long long>& tags = part.vertexTags;
  tags = distinctTags(cells_.size() / record * nodes,
                      [&](std::size_t i) { return cells_[record * (i / nodes) + 2 + i % nodes]; }, cellVertices_);
  const std::vector<std::vector<long long>> questions = exchangeWithRanks(*comm_, byNodeDirectory(tags));
  std::vector<std::vector<long long>> sharers(size_);
  runOnEveryRank(*comm_, [&] {
    std::vector<std::pair<long long, int>> users;  // (tag, asking rank), sorted
    for (int r = 0; r < size_; ++r)
      for (long long tag : questions[r]) users.emplace_back(tag, r);
    sortPairs(users);
    for (int r = 0; r < size_; ++r) {  // each rank's tags ascending: one walk through the users
      auto first = users.begin();
      for (long long tag : questions[r]) {
        while (first->first < tag) ++first;
        auto end = first;
        while (end != users.end() && end->first == tag) ++end;
        sharers[r].push_back(end - first);
        for (auto u = first; u != end; ++u) sharers[r].push_back(u->second);
      }
    }
  });
  const std::vector<double> xyz = exchangeWithRanks(*comm_, coordinatesFor(questions));
  const std::vector<long long> shared = exchangeWithRanksJoined(*comm_, sharers);
  slice_.nodeTags = {};
  slice_.nodeCoordinates = {};
  heldNodes_ = {};
  // The answers come in the order asked, which is the tags' order.
  std::vector<double> z(tags.size());
  part.mesh.vertices.resize(d_ * tags.size());
  std::vector<std::vector<int>> by(tags.size());
  for (std::size_t v = 0, at = 0; v < tags.size(); ++v) {
    for (int c = 0; c < d_; ++c) part.mesh.vertices[d_ * v + c] = xyz[3 * v + c];
    z[v] = xyz[3 * v + 2];
    const long long count = shared[at++];
    for (long long s = 0; s < count; ++s) by[v].push_back(static_cast<int>(shared[at++]));
  }
  part.sharerStart.assign(1, 0);
  for (const std::vector<int>& ranks : by) {
    part.sharers.insert(part.sharers.end(), ranks.begin(), ranks.end());
    part.sharerStart.push_back(static_cast<long long>(part.sharers.size()));
  }
  if (d_ == 2) {  // a 2D mesh lies in the plane z = 0, to round-off relative to its extent
    double extent = 0;
    for (int c = 0; c < 2; ++c) {
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t v = 0; v < tags.size(); ++v) {
        lo = std::min(lo, part.mesh.vertices[2 * v + c]);
        hi = std::max(hi, part.mesh.vertices[2 * v + c]);
      }
      extent = std::max(extent, maxOverRanks(*comm_, hi) - minOverRanks(*comm_, lo));
    }
    runOnEveryRank(*comm_, [&] {
      for (std::size_t v = 0; v < tags.size(); ++v)
        if (std::abs(z[v]) > 1e-12 * extent)
          throw InputError(prefix_ + "it is a 2D mesh (triangles) but node " + std::to_string(tags[v]) + " has z = " +
                           std::to_string(z[v]) + "; a 2D mesh must lie in the plane z = 0");
    });
  }
}

// The part's cells by element tag, as vertex ids, positively oriented, with their bodies; its
// facets by (element, group).
void ParallelRead::cellsAndFacets(GmshMeshPart& part) const {
  SimplexMesh& mesh = part.mesh;
  const std::size_t record = d_ + 3;
  const auto vertex = [&part](long long tag) {
    return std::lower_bound(part.vertexTags.begin(), part.vertexTags.end(), tag) - part.vertexTags.begin();
  };
  std::vector<std::pair<long long, std::size_t>> byElement(cells_.size() / record);  // (element tag, cell)
  for (std::size_t c = 0; c < byElement.size(); ++c) byElement[c] = {cells_[record * c], c};
  sortPairs(byElement);
  mesh.cells.reserve((d_ + 1) * byElement.size());
  std::vector<double> x(d_ * (d_ + 1));
  for (const auto& [element, c] : byElement) {
    const long long* cell = &cells_[record * c];
    long long ids[4];
    for (int i = 0; i <= d_; ++i) {
      ids[i] = static_cast<long long>(cellVertices_[(d_ + 1) * c + i]);
      std::copy(&mesh.vertices[d_ * ids[i]], &mesh.vertices[d_ * ids[i]] + d_, &x[d_ * i]);
    }
    const int orientation = simplexOrientation(d_, x.data());
    if (orientation == 0)
      throw InputError(prefix_ + "element " + std::to_string(cell[0]) + " is degenerate (zero " +
                       (d_ == 2 ? "area" : "volume") + ")");
    if (orientation < 0) std::swap(ids[1], ids[2]);
    mesh.cells.insert(mesh.cells.end(), ids, ids + d_ + 1);
    if (!slice_.bodyTags.empty()) mesh.cellTags.push_back(static_cast<int>(cell[1]));
  }
  const std::size_t facetRecord = d_ + 2;
  std::vector<std::size_t> order(heldFacets_.size() / facetRecord);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_pair(heldFacets_[facetRecord * a], heldFacets_[facetRecord * a + 1]) <
           std::make_pair(heldFacets_[facetRecord * b], heldFacets_[facetRecord * b + 1]);
  });
  for (std::size_t f : order) {
    for (int i = 0; i < d_; ++i) mesh.facets.push_back(vertex(heldFacets_[facetRecord * f + 2 + i]));
    mesh.facetTags.push_back(static_cast<int>(heldFacets_[facetRecord * f + 1]));
  }
}

GmshMeshPart ParallelRead::assemble() {
  GmshMeshPart part;
  part.part = rank_;
  part.mesh.dim = d_;
  part.mesh.boundaryTags = slice_.boundaryTags;
  part.mesh.bodyTags = slice_.bodyTags;
  vertexData(part);
  runOnEveryRank(*comm_, [&] { cellsAndFacets(part); });
  cells_ = {};
  cellVertices_ = {};
  heldFacets_ = {};
  return part;
}

}  // namespace

GmshMeshPart readMshInParallel(const RCP<const Comm>& comm, const std::string& path, std::string& unsupported) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!onEveryRank(*comm, file != nullptr)) {  // on a disk that only some ranks see, say
    unsupported = "not every rank can open it";
    return {};
  }
  MshFileSlice slice;
  {
    const Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("Signorini: mesh and space: mesh read: slices"));
    runOnEveryRank(*comm, [&] { slice = readMshSlice(path, comm->getRank(), comm->getSize(), unsupported); });
  }
  if (!onEveryRank(*comm, unsupported.empty())) {
    if (unsupported.empty()) unsupported = "another rank found it outside what the parallel reader reads";
    return {};
  }
  return ParallelRead(comm, path, std::move(slice)).part();
}

}  // namespace signorini::detail
