#include "solver/BoundaryFeatures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>

#include "core/NeighbourExchange.hpp"
#include "core/SplitMixHash.hpp"

namespace signorini {
namespace {

// A facet of a cell: its vertices' global ids, sorted (the last -1 in 2D), and the cell's
// vertex opposite it; with the local vertex indices of both.
struct Facet {
  std::array<long long, 3> key{-1, -1, -1};
  long long opposite = -1;
  std::array<long long, 3> local{-1, -1, -1};
  long long localOpposite = -1;
};

// Sorts the first n of three values (insertion sort: std::sort's bounds warn on arrays this short).
template <class T>
void sortFirst(std::array<T, 3>& values, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && values[j] < values[j - 1]; --j) std::swap(values[j], values[j - 1]);
}

bool keyLess(const Facet& a, const Facet& b) {
  return std::make_pair(a.key, a.opposite) < std::make_pair(b.key, b.opposite);
}

int directoryOf(const long long* first, const long long* last, int size) {
  return static_cast<int>(splitMixHash(first, last) % static_cast<std::uint64_t>(size));
}

// The facets of the local cells that no second local cell shares (a cell held twice counts
// once), sorted by key. A facet is looked for among the cells at its vertex of lowest local
// index, which hold every cell that shares it.
std::vector<Facet> exposedFacets(int dim, const std::vector<long long>& ids, const std::vector<long long>& cells) {
  const int corners = dim + 1;
  std::vector<long long> at, cellsAt;
  cellsAtVertices(dim, ids.size(), cells, at, cellsAt);
  std::vector<Facet> exposed, star;
  for (std::size_t v = 0; v < ids.size(); ++v) {
    star.clear();
    for (long long k = at[v]; k < at[v + 1]; ++k) {
      const long long* cell = &cells[corners * cellsAt[k]];
      for (int f = 0; f < corners; ++f) {  // the facet opposite corner f, if v is its lowest vertex
        Facet facet;
        std::array<std::pair<long long, long long>, 3> corner{};  // (global id, local index)
        bool lowest = cell[f] != static_cast<long long>(v);
        for (int i = 0, n = 0; i < corners && lowest; ++i)
          if (i != f) {
            lowest = cell[i] >= static_cast<long long>(v);
            corner[n++] = {ids[cell[i]], cell[i]};
          }
        if (!lowest) continue;
        sortFirst(corner, dim);  // by global id
        for (int i = 0; i < dim; ++i) std::tie(facet.key[i], facet.local[i]) = corner[i];
        facet.localOpposite = cell[f];
        facet.opposite = ids[cell[f]];
        star.push_back(facet);
      }
    }
    std::sort(star.begin(), star.end(), keyLess);
    for (std::size_t i = 0, end; i < star.size(); i = end) {
      bool single = true;  // one opposite vertex: one cell
      for (end = i + 1; end < star.size() && star[end].key == star[i].key; ++end)
        single = single && star[end].opposite == star[i].opposite;
      if (single) exposed.push_back(star[i]);
    }
  }
  std::sort(exposed.begin(), exposed.end(), keyLess);
  return exposed;
}

// Asks each local vertex's directory rank about it: `answersTo` gets the ids each rank asked
// (questions[r]) and returns one answer per id in that order; the answers come back in the
// order of `ids`. Collective.
template <class AnswersTo>
std::vector<long long> askDirectories(const Comm& comm, const std::vector<long long>& ids, AnswersTo answersTo) {
  const int size = comm.getSize();
  std::vector<std::vector<long long>> asked(size);
  for (long long id : ids) asked[directoryOf(&id, &id + 1, size)].push_back(id);
  const std::vector<std::vector<long long>> replies = exchangeWithRanks(comm, answersTo(exchangeWithRanks(comm, asked)));
  std::vector<std::size_t> next(size, 0);
  std::vector<long long> answers(ids.size());
  for (std::size_t v = 0; v < ids.size(); ++v) {
    const int r = directoryOf(&ids[v], &ids[v] + 1, size);
    answers[v] = replies[r][next[r]++];
  }
  return answers;
}

// Whether each local vertex is a vertex of another rank's cells too: its directory rank
// counts the ranks that name it.
std::vector<char> sharedVertices(const Comm& comm, const std::vector<long long>& ids) {
  const std::vector<long long> ranksNaming = askDirectories(comm, ids, [](const std::vector<std::vector<long long>>& questions) {
    std::vector<long long> all;
    for (const auto& q : questions) all.insert(all.end(), q.begin(), q.end());
    std::sort(all.begin(), all.end());
    std::vector<std::vector<long long>> answers(questions.size());
    for (std::size_t r = 0; r < questions.size(); ++r)
      for (long long id : questions[r])
        answers[r].push_back(std::upper_bound(all.begin(), all.end(), id) - std::lower_bound(all.begin(), all.end(), id));
    return answers;
  });
  std::vector<char> shared(ids.size());
  for (std::size_t v = 0; v < ids.size(); ++v) shared[v] = ranksNaming[v] > 1;
  return shared;
}

// Of the exposed facets, those of one cell over all ranks: each is sent to the directory
// rank of its key with its opposite vertex, and so is every facet of a cell with a vertex
// that other ranks' cells share (such a cell may be held by them too, and a facet exposed on
// one rank be matched on another); the directory answers the keys with one opposite vertex.
std::vector<Facet> boundaryFacets(const Comm& comm, int dim, const std::vector<long long>& ids,
                                  const std::vector<long long>& cells, std::vector<Facet> exposed) {
  const int size = comm.getSize();
  std::vector<std::vector<long long>> toDirectory(size);
  const auto send = [&](const std::array<long long, 3>& key, long long opposite) {
    auto& to = toDirectory[directoryOf(key.data(), key.data() + 3, size)];
    to.insert(to.end(), {key[0], key[1], key[2], opposite});
  };
  for (const Facet& f : exposed) send(f.key, f.opposite);
  const std::vector<char> shared = sharedVertices(comm, ids);
  for (std::size_t c = 0; c < cells.size(); c += dim + 1) {
    if (std::none_of(&cells[c], &cells[c + dim + 1], [&](long long v) { return shared[v] != 0; })) continue;
    for (int f = 0; f <= dim; ++f) {
      std::array<long long, 3> key{-1, -1, -1};
      for (int i = 0, n = 0; i <= dim; ++i)
        if (i != f) key[n++] = ids[cells[c + i]];
      sortFirst(key, dim);
      send(key, ids[cells[c + f]]);
    }
  }
  const std::vector<std::vector<long long>> asked = exchangeWithRanks(comm, toDirectory);
  std::vector<std::array<long long, 5>> records;  // key, opposite, asking rank
  for (int r = 0; r < size; ++r)
    for (std::size_t i = 0; i < asked[r].size(); i += 4)
      records.push_back({asked[r][i], asked[r][i + 1], asked[r][i + 2], asked[r][i + 3], r});
  std::sort(records.begin(), records.end());
  records.erase(std::unique(records.begin(), records.end()), records.end());
  std::vector<std::vector<long long>> answers(size);
  for (std::size_t i = 0, end; i < records.size(); i = end) {
    bool single = true;  // one opposite vertex: one cell
    for (end = i + 1; end < records.size() && std::equal(&records[i][0], &records[i][3], &records[end][0]); ++end)
      single = single && records[end][3] == records[i][3];
    if (single)
      for (std::size_t k = i; k < end; ++k) answers[records[k][4]].insert(answers[records[k][4]].end(), &records[k][0], &records[k][3]);
  }
  const std::vector<long long> onBoundary = exchangeWithRanksJoined(comm, answers);
  std::vector<Facet> result;
  for (std::size_t i = 0; i < onBoundary.size(); i += 3) {
    Facet key;
    std::copy_n(&onBoundary[i], 3, key.key.begin());
    const auto it = std::lower_bound(exposed.begin(), exposed.end(), key, keyLess);
    if (it != exposed.end() && it->key == key.key) result.push_back(*it);  // else this rank holds no cell of it
  }
  return result;
}

// The facet's outward unit normal (away from its opposite vertex), from its vertices in key
// order: the same bits on every rank.
std::array<double, 3> outwardNormal(int dim, const Facet& f, const std::vector<double>& xyz) {
  const auto at = [&](long long v, int c) { return xyz[dim * v + c]; };
  std::array<double, 3> n{0, 0, 0}, e1{0, 0, 0}, e2{0, 0, 0};
  for (int c = 0; c < dim; ++c) e1[c] = at(f.local[1], c) - at(f.local[0], c);
  if (dim == 2) {
    n = {-e1[1], e1[0], 0.0};
  } else {
    for (int c = 0; c < 3; ++c) e2[c] = at(f.local[2], c) - at(f.local[0], c);
    n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  }
  double inward = 0.0, length = 0.0;
  for (int c = 0; c < dim; ++c) {
    inward += n[c] * (at(f.localOpposite, c) - at(f.local[0], c));
    length += n[c] * n[c];
  }
  const double scale = (inward > 0 ? -1.0 : 1.0) / std::sqrt(length);
  for (double& x : n) x *= scale;
  return n;
}

// The feature dimension of a boundary vertex with these normals (sorted).
signed char featureOf(int dim, const std::vector<std::array<double, 3>>& normals) {
  std::vector<std::array<double, 3>> sides;  // the first normal of each group
  const double cosine = std::cos(kFeatureAngle);
  for (const auto& n : normals) {
    const bool near = std::any_of(sides.begin(), sides.end(), [&](const std::array<double, 3>& s) {
      return n[0] * s[0] + n[1] * s[1] + n[2] * s[2] > cosine;
    });
    if (!near) sides.push_back(n);
  }
  return static_cast<signed char>(dim - std::min<int>(static_cast<int>(sides.size()), dim));
}

// At each vertex's directory rank, the feature dimensions of the vertices the boundary facets
// `facets` touch: (id, dimension) pairs by id.
std::vector<std::pair<long long, signed char>> featuresAtDirectory(const Comm& comm, int dim,
                                                                   const std::vector<long long>& ids,
                                                                   const std::vector<double>& xyz,
                                                                   const std::vector<Facet>& facets) {
  const int size = comm.getSize();
  std::vector<std::vector<long long>> vertexTo(size);
  std::vector<std::vector<double>> normalTo(size);
  for (const Facet& f : facets) {
    const std::array<double, 3> n = outwardNormal(dim, f, xyz);
    for (int i = 0; i < dim; ++i) {
      const int r = directoryOf(&ids[f.local[i]], &ids[f.local[i]] + 1, size);
      vertexTo[r].push_back(ids[f.local[i]]);
      normalTo[r].insert(normalTo[r].end(), n.begin(), n.end());
    }
  }
  const std::vector<long long> vertices = exchangeWithRanksJoined(comm, vertexTo);
  const std::vector<double> normals = exchangeWithRanks(comm, normalTo);
  std::vector<std::pair<long long, std::array<double, 3>>> byVertex(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    byVertex[i] = {vertices[i], {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}};
  std::sort(byVertex.begin(), byVertex.end());
  std::vector<std::pair<long long, signed char>> features;
  for (std::size_t i = 0, end; i < byVertex.size(); i = end) {
    std::vector<std::array<double, 3>> at;
    for (end = i; end < byVertex.size() && byVertex[end].first == byVertex[i].first; ++end)
      at.push_back(byVertex[end].second);
    features.emplace_back(byVertex[i].first, featureOf(dim, at));
  }
  return features;
}

}  // namespace

void cellsAtVertices(int dim, std::size_t count, const std::vector<long long>& cells, std::vector<long long>& at,
                     std::vector<long long>& cellsAt) {
  at.assign(count + 1, 0);
  for (long long v : cells) ++at[v + 1];
  std::partial_sum(at.begin(), at.end(), at.begin());
  std::vector<long long> next(at.begin(), at.end() - 1);
  cellsAt.resize(cells.size());
  for (std::size_t e = 0; e < cells.size(); ++e) cellsAt[next[cells[e]]++] = static_cast<long long>(e / (dim + 1));
}

std::vector<signed char> boundaryFeatureDimensions(const Comm& comm, int dim, const std::vector<long long>& ids,
                                                   const std::vector<double>& coordinates,
                                                   const std::vector<long long>& cells) {
  const auto features =
      featuresAtDirectory(comm, dim, ids, coordinates, boundaryFacets(comm, dim, ids, cells, exposedFacets(dim, ids, cells)));
  const std::vector<long long> dimensions = askDirectories(comm, ids, [&](const std::vector<std::vector<long long>>& questions) {
    std::vector<std::vector<long long>> answers(questions.size());
    for (std::size_t r = 0; r < questions.size(); ++r)
      for (long long id : questions[r]) {
        const auto it = std::lower_bound(features.begin(), features.end(), std::make_pair(id, static_cast<signed char>(-1)));
        answers[r].push_back(it != features.end() && it->first == id ? it->second : dim);
      }
    return answers;
  });
  return std::vector<signed char>(dimensions.begin(), dimensions.end());
}

}  // namespace signorini
