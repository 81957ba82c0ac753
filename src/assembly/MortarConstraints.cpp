#include "assembly/MortarConstraints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/ContactMultiplierBasis.hpp"
#include "assembly/FacetSearch.hpp"
#include "assembly/MeshPieces.hpp"
#include "assembly/MortarFacet.hpp"
#include "assembly/SummedRows.hpp"
#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "fe/SimplexQuadrature.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// The bounding box of facets [begin, end) (lower corner, upper corner); empty (lower > upper)
// without facets.
std::array<double, 6> boundingBox(const MortarFacet* begin, const MortarFacet* end) {
  std::array<double, 6> box{{1e300, 1e300, 1e300, -1e300, -1e300, -1e300}};
  for (const MortarFacet* f = begin; f != end; ++f) {
    const std::array<double, 6> own = f->boundingBox();
    for (int c = 0; c < 3; ++c) {
      box[c] = std::min(box[c], own[c]);
      box[3 + c] = std::max(box[3 + c], own[3 + c]);
    }
  }
  return box;
}

bool boxesMeet(const double* a, const double* b, double reach) {
  for (int c = 0; c < 3; ++c)
    if (a[c] > b[3 + c] + reach || a[3 + c] < b[c] - reach) return false;
  return true;
}

double diagonal(const std::array<double, 6>& box) {
  return std::sqrt(std::pow(box[3] - box[0], 2) + std::pow(box[4] - box[1], 2) + std::pow(box[5] - box[2], 2));
}

// The master facets of every rank that lie within `reach` of this rank's slave facets'
// bounding box: each rank sends every other the master facets in that rank's box.
std::vector<MortarFacet> nearMasterFacets(const Comm& comm, const std::vector<MortarFacet>& slave,
                                          const std::vector<MortarFacet>& master, double reach) {
  const int size = comm.getSize();
  const std::array<double, 6> mine = boundingBox(slave.data(), slave.data() + slave.size());
  std::vector<double> boxes(6 * size);
  Teuchos::gatherAll(comm, 6, mine.data(), 6 * size, boxes.data());
  std::vector<std::array<double, 6>> own;
  for (const MortarFacet& f : master) own.push_back(f.boundingBox());
  std::vector<std::vector<double>> toRank(size);
  for (int r = 0; r < size; ++r)
    for (std::size_t k = 0; k < master.size(); ++k)
      if (boxesMeet(own[k].data(), &boxes[6 * r], reach)) pack(master[k], toRank[r]);
  return unpackFacets(exchangeWithRanks(comm, toRank));
}

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

using Piece = std::array<std::array<double, 3>, 3>;

// A piece of a slave facet and the master facet that covers it.
struct CoveredPiece {
  const MortarFacet* master;
  Piece piece;
};

// The distance along the slave normal from x_s to the plane (line) of master facet m, whose
// normal makes the cosine `facing` with the slave's.
double distanceAlong(const MortarFacet& m, double facing, const double* xs) {
  const double r[3] = {m.x[0][0] - xs[0], m.x[0][1] - xs[1], m.x[0][2] - xs[2]};
  return dot(r, m.normal) / facing;
}

// The master facets near this rank's slave facets, found along each slave facet's normal line.
struct NearMaster {
  std::vector<MortarFacet> facets;
  FacetSearch search;
  double reach;  // how far along a slave normal a master facet may lie
};

// The pieces of slave facet s that the master facets facing it cover. A master facet beyond
// reach at a piece's middle is another part of the surface. The search's boxes, grown by the
// largest facet, meet the slave's normal line through its centroid within reach wherever a
// master facet covers a piece within reach.
std::vector<CoveredPiece> coveredPieces(const MortarFacet& s, const NearMaster& near) {
  std::array<double, 3> centroid{}, from{}, to{};
  for (int v = 0; v < s.dim; ++v)
    for (int a = 0; a < 3; ++a) centroid[a] += s.x[v][a] / s.dim;
  for (int a = 0; a < 3; ++a) {
    from[a] = centroid[a] - near.reach * s.normal[a];
    to[a] = centroid[a] + near.reach * s.normal[a];
  }
  std::vector<CoveredPiece> covered;
  for (const int k : near.search.meeting(from, to)) {
    const MortarFacet& m = near.facets[k];
    const double facing = dot(s.normal, m.normal);
    if (facing > -1e-12) continue;  // not facing the slave side
    const auto pieces = projectedOverlap(s, m);
    if (pieces.empty()) continue;
    double middle[3] = {0, 0, 0}, pieceCentroid[3] = {0, 0, 0};
    for (int v = 0; v < s.dim; ++v)
      for (int a = 0; a < 3; ++a) pieceCentroid[a] += pieces[0][v][a] / s.dim;
    s.point(pieceCentroid, middle);
    if (std::abs(distanceAlong(m, facing, middle)) > near.reach) continue;
    for (const Piece& piece : pieces) covered.push_back({&m, piece});
  }
  return covered;
}

// Whether the facet's node i lies on one of the (closed) pieces.
bool onPieces(const MortarFacet& s, int i, const std::vector<CoveredPiece>& pieces) {
  constexpr double tolerance = 1e-9;  // in barycentric coordinates
  double lambda[3] = {0, 0, 0};
  for (int v = 0; v < s.dim; ++v) lambda[v] = static_cast<double>(s.lattice[i][v]) / s.degree;
  for (const CoveredPiece& c : pieces) {
    const Piece& p = c.piece;
    if (s.dim == 2) {
      const double lo = std::min(p[0][1], p[1][1]), hi = std::max(p[0][1], p[1][1]);
      if (lambda[1] >= lo - tolerance && lambda[1] <= hi + tolerance) return true;
      continue;
    }
    // lambda = p0 + mu_1 (p1 - p0) + mu_2 (p2 - p0) in the coordinates 1 and 2.
    const double a = p[1][1] - p[0][1], b = p[2][1] - p[0][1], c2 = p[1][2] - p[0][2], d = p[2][2] - p[0][2];
    const double r1 = lambda[1] - p[0][1], r2 = lambda[2] - p[0][2], det = a * d - b * c2;
    const double mu1 = (d * r1 - b * r2) / det, mu2 = (a * r2 - c2 * r1) / det;
    if (mu1 >= -tolerance && mu2 >= -tolerance && mu1 + mu2 <= 1 + tolerance) return true;
  }
  return false;
}

// One slave facet's rows from its covered pieces, integrated by Gauss points. Only the facet
// nodes with `kept` have a row; the multiplier functions of the others are shared out equally
// among them. `add(j, column, value)` takes the entries of the slave facet's node j, `gap(j,
// weight, value)` the integrals of psi_j and psi_j g0.
template <class AddEntry, class AddGap>
void integrateFacet(const MortarFacet& s, const std::vector<CoveredPiece>& pieces, const bool* kept,
                    const ContactMultiplierBasis& psi, int facet, const std::vector<int>& facetNodes,
                    int nodesPerCell, const QuadratureRule& rule, AddEntry&& add, AddGap&& gap) {
  const int dim = s.dim;
  const double* n = s.normal;
  const double measure = s.measure(), referenceMeasure = dim == 2 ? 1.0 : 0.5;
  const int numKept = static_cast<int>(std::count(kept, kept + s.count, true));
  std::vector<double> phi(nodesPerCell, 0.0);
  double slave[MortarFacet::kMaxNodes], masterValues[MortarFacet::kMaxNodes], psiValues[MortarFacet::kMaxNodes];
  for (const auto& [mp, piece] : pieces) {
    const MortarFacet& m = *mp;
    const double facing = dot(n, m.normal);
    // The piece's measure relative to the slave facet's: its barycentric simplex's.
    double e[2][2];
    for (int v = 1; v < dim; ++v)
      for (int a = 1; a < 3; ++a) e[v - 1][a - 1] = piece[v][a] - piece[0][a];
    const double fraction = dim == 2 ? std::abs(e[0][0]) : std::abs(e[0][0] * e[1][1] - e[0][1] * e[1][0]);
    for (int q = 0; q < rule.size(); ++q) {
      double lambda[3], xs[3] = {0, 0, 0}, xm[3], mu[3];
      for (int a = 0; a < 3; ++a) {
        lambda[a] = piece[0][a];
        for (int v = 1; v < dim; ++v) lambda[a] += rule.points[(dim - 1) * q + v - 1] * (piece[v][a] - piece[0][a]);
      }
      const double w = rule.weights[q] / referenceMeasure * fraction * measure;
      s.point(lambda, xs);
      const double g0 = distanceAlong(m, facing, xs);
      for (int c = 0; c < 3; ++c) xm[c] = xs[c] + g0 * n[c];
      m.barycentric(xm, mu);
      s.shapeValues(lambda, slave);
      m.shapeValues(mu, masterValues);
      for (int i = 0; i < s.count; ++i) phi[facetNodes[i]] = slave[i];
      double shared = 0;
      for (int j = 0; j < s.count; ++j) {
        psiValues[j] = psi.value(facet, facetNodes[j], phi.data());
        if (!kept[j]) shared += psiValues[j];
      }
      for (int j = 0; j < s.count; ++j) {
        if (!kept[j]) continue;
        const double psiJ = w * (psiValues[j] + shared / numKept);
        gap(j, psiJ, psiJ * g0);
        for (int c = 0; c < dim; ++c) {
          for (int k = 0; k < s.count; ++k) add(j, dim * s.nodes[k] + c, psiJ * slave[k] * n[c]);
          for (int l = 0; l < m.count; ++l) add(j, dim * m.nodes[l] + c, -psiJ * masterValues[l] * n[c]);
        }
      }
    }
  }
}

// Per constraint row, the integrals of psi_j g0 and psi_j, psi_j's integral times the size
// of the facets (their bounding box's diagonal), and the node's coordinates summed over the
// row's contributions with their count.
constexpr int kRowSums = 7;

// The sums of this rank's rows (ids rowIds), added up on the rows' owners.
RCP<const MultiVector> onOwners(const std::vector<GlobalOrdinal>& rowIds,
                                const std::vector<std::array<double, kRowSums>>& sums, const RCP<const Map>& rowMap) {
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto touched = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(rowIds), 0, rowMap->getComm()));
  MultiVector local(touched, kRowSums);
  for (int c = 0; c < kRowSums; ++c) {
    auto data = local.getDataNonConst(c);
    for (std::size_t i = 0; i < sums.size(); ++i) data[i] = sums[i][c];
  }
  auto owned = rcp(new MultiVector(rowMap, kRowSums));
  owned->doExport(local, Tpetra::Export<LocalOrdinal, GlobalOrdinal, Node>(touched, rowMap), Tpetra::ADD);
  return owned;
}

// The entries of the rank whose first entry is the largest.
template <std::size_t N>
std::array<double, N> largestOnAnyRank(const Comm& comm, const std::array<double, N>& local) {
  std::vector<double> all(N * comm.getSize());
  Teuchos::gatherAll(comm, static_cast<int>(N), local.data(), static_cast<int>(all.size()), all.data());
  std::array<double, N> largest = local;
  for (int r = 0; r < comm.getSize(); ++r)
    if (all[N * r] > largest[0]) std::copy_n(&all[N * r], N, largest.data());
  return largest;
}

// Refuses a constraint whose multiplier function has no positive integral over the covered
// pieces (its node would carry no pressure): the multiplier functions of degree 2 and 3 are
// negative in places, and a node whose covered part lies there has none.
void checkPositiveWeights(const MultiVector& rowSums, const ContactPair& pair) {
  std::array<double, 4> worst{{-1e300, 0, 0, 0}};  // minus the smallest weight, where it is
  auto weight = rowSums.getData(1), count = rowSums.getData(6);
  const std::array<Teuchos::ArrayRCP<const double>, 3> x{{rowSums.getData(3), rowSums.getData(4), rowSums.getData(5)}};
  for (std::size_t i = 0; i < rowSums.getLocalLength(); ++i)
    if (count[i] > 0 && -weight[i] > worst[0])
      worst = {-weight[i], x[0][i] / count[i], x[1][i] / count[i], x[2][i] / count[i]};
  worst = largestOnAnyRank(*rowSums.getMap()->getComm(), worst);
  if (worst[0] < 0) return;
  std::ostringstream message;
  message.precision(3);
  message << pair.path() << ": the multiplier function of the contact boundary's node at (" << worst[1] << ", "
          << worst[2] << ", " << worst[3] << ") has no positive integral over the part of \"" << pair.boundary
          << "\" that the master boundary \"" << pair.masterBoundary
          << "\" covers; make the slave boundary the part that the master covers, or use degree 1 there";
  throw InputError(message.str());
}

// Refuses bodies that overlap at the start: a weighted gap d_j / integral of psi_j below
// -tolerance times the size of the slave facets at node j.
void checkInitialOverlap(const MultiVector& rowSums, const ContactPair& pair) {
  std::array<double, 5> worst{{-1e300, 0, 0, 0, 0}};  // overlap / size, overlap, x
  std::array<Teuchos::ArrayRCP<const double>, kRowSums> sums;
  for (int c = 0; c < kRowSums; ++c) sums[c] = rowSums.getData(c);
  for (std::size_t i = 0; i < rowSums.getLocalLength(); ++i) {
    if (sums[6][i] == 0) continue;  // another pair's row
    const double weight = sums[1][i], overlap = -sums[0][i] / weight, relative = overlap / (sums[2][i] / weight);
    if (relative > worst[0])
      worst = {relative, overlap, sums[3][i] / sums[6][i], sums[4][i] / sums[6][i], sums[5][i] / sums[6][i]};
  }
  worst = largestOnAnyRank(*rowSums.getMap()->getComm(), worst);
  if (worst[0] <= pair.initialOverlapTolerance) return;
  std::ostringstream message;
  message.precision(3);
  message << pair.path() << ": the bodies overlap by " << worst[1] << " at the start, at (" << worst[2] << ", "
          << worst[3] << ", " << worst[4] << ") on the contact boundary \"" << pair.boundary << "\" ("
          << worst[0] << " of its facets' size there, more than initial overlap: tolerance "
          << pair.initialOverlapTolerance << "): move them apart";
  throw InputError(message.str());
}

// The master boundary must lie on other bodies than the slave side: the connected pieces of
// the mesh that hold their facets' nodes do not meet.
void checkDifferentBodies(const DistributedSpace& ds, const LocalFacets& slave, const LocalFacets& master,
                          const ContactPair& pair) {
  const MeshPieces& pieces = meshPieces(ds);
  std::vector<int> onSide[2] = {std::vector<int>(pieces.count, 0), std::vector<int>(pieces.count, 0)};
  for (int side = 0; side < 2; ++side)
    for (const auto& [cell, facet] : (side == 0 ? slave : master).cellFacets)
      onSide[side][pieces.ofSpaceNode[ds.space().cellNodes(cell)[facet == 0 ? 1 : 0]]] = 1;
  for (int side = 0; side < 2; ++side) {
    std::vector<int> all(pieces.count);
    Teuchos::reduceAll(*ds.comm(), Teuchos::REDUCE_MAX, pieces.count, onSide[side].data(), all.data());
    onSide[side] = all;
  }
  for (int p = 0; p < pieces.count; ++p)
    if (onSide[0][p] && onSide[1][p])
      throw InputError(pair.path() + ": the master boundary \"" + pair.masterBoundary +
                       "\" lies on the same body as the contact boundary \"" + pair.boundary +
                       "\"; name a surface of the other body (a body meshed apart from it)");
}

void checkPair(const DistributedSpace& ds, const ContactPair& pair) {
  if (pair.masterBoundary == pair.boundary)
    throw InputError(pair.path() + ": the master boundary \"" + pair.masterBoundary +
                     "\" is the contact boundary itself; name the other body's surface");
  ds.mesh().tag(pair.masterBoundary);  // throws naming the known boundaries
  if (!isWeightedGap(pair.formulation))
    throw InputError(pair.path() + "/formulation: contact between two bodies needs weighted constraints "
                     "(\"dual mortar\" or \"weighted gap\"), not nodal ones");
}

// The two sides of a pair as this rank sees them: its slave facets, the master facets near
// them on any rank, and how far a master facet may be from the slave facets it faces: twice
// the largest facet of either side, or the size of the whole slave boundary (its bounding
// box's diagonal). Collective.
struct MortarSides {
  LocalFacets slave, master;
  NearMaster near;
};

MortarSides mortarSides(const DistributedSpace& ds, const ContactPair& pair) {
  checkPair(ds, pair);
  LocalFacets slave = boundaryFacets(ds, ds.mesh().tag(pair.boundary));
  LocalFacets master = boundaryFacets(ds, ds.mesh().tag(pair.masterBoundary));
  double largest = 0;
  for (const auto* side : {&slave, &master})
    for (const MortarFacet& f : side->facets) largest = std::max(largest, diagonal(f.boundingBox()));
  largest = maxOverRanks(*ds.comm(), largest);
  std::array<double, 6> box = boundingBox(slave.facets.data(), slave.facets.data() + slave.facets.size());
  for (int c = 0; c < 3; ++c) {
    box[c] = minOverRanks(*ds.comm(), box[c]);
    box[3 + c] = maxOverRanks(*ds.comm(), box[3 + c]);
  }
  const double reach = std::max(2.0 * largest, diagonal(box));
  std::vector<MortarFacet> near = nearMasterFacets(*ds.comm(), slave.facets, master.facets, reach);
  FacetSearch search(near, largest);
  return {std::move(slave), std::move(master), {std::move(near), std::move(search), reach}};
}

}  // namespace

std::vector<char> coveredSlaveNodes(const DistributedSpace& ds, const ContactPair& pair) {
  const MortarSides sides = mortarSides(ds, pair);
  Vector here(ds.overlapNodeMap()), owned(ds.ownedNodeMap());
  for (const MortarFacet& facet : sides.slave.facets) {
    const std::vector<CoveredPiece> pieces = coveredPieces(facet, sides.near);
    for (int i = 0; i < facet.count; ++i)
      if (onPieces(facet, i, pieces)) here.replaceGlobalValue(facet.nodes[i], 1.0);
  }
  // A node is covered if it is on any rank's facets; the owners tell their ghosts.
  owned.doExport(here, Export(ds.overlapNodeMap(), ds.ownedNodeMap()), Tpetra::ADD);
  here.doImport(owned, Import(ds.ownedNodeMap(), ds.overlapNodeMap()), Tpetra::INSERT);
  auto data = here.getData();
  std::vector<char> covered(data.size());
  for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = data[i] > 0;
  return covered;
}

MortarRows mortarConstraints(const DistributedSpace& ds, const ContactPair& pair,
                             const std::vector<long long>& constraintOf, const RCP<const Map>& constraintMap) {
  const MortarSides sides = mortarSides(ds, pair);
  checkDifferentBodies(ds, sides.slave, sides.master, pair);
  std::vector<long long> rowOfOverlapNode(ds.space().numNodes(), -1);
  for (std::size_t i = 0; i < constraintOf.size(); ++i) rowOfOverlapNode[ds.overlapSpaceNodes()[i]] = constraintOf[i];
  std::map<GlobalOrdinal, std::size_t> localRow;
  std::vector<GlobalOrdinal> rowIds;
  std::vector<std::array<double, kRowSums>> sums;
  std::vector<std::vector<std::pair<GlobalOrdinal, double>>> entries;
  const ContactMultiplierBasis psi(ds.space().basis(), pair.formulation);
  const QuadratureRule rule = simplexQuadrature(ds.dim() - 1, 2 * ds.space().degree());  // psi_j N_l exactly
  for (std::size_t f = 0; f < sides.slave.facets.size(); ++f) {
    const MortarFacet& facet = sides.slave.facets[f];
    const auto [cell, local] = sides.slave.cellFacets[f];
    const std::vector<int> facetNodes = ds.space().basis().facetNodes(local);
    std::size_t rows[MortarFacet::kMaxNodes];
    bool kept[MortarFacet::kMaxNodes] = {};
    for (std::size_t j = 0; j < facetNodes.size(); ++j) {
      const long long row = rowOfOverlapNode[ds.space().cellNodes(cell)[facetNodes[j]]];
      if (row < 0) continue;  // a node that the master boundary does not cover
      kept[j] = true;
      const auto [it, fresh] = localRow.emplace(row, rowIds.size());
      if (fresh) {
        rowIds.push_back(row);
        sums.push_back({});
        entries.emplace_back();
      }
      rows[j] = it->second;
    }
    if (std::none_of(kept, kept + facet.count, [](bool k) { return k; })) continue;
    const double size = diagonal(facet.boundingBox());
    integrateFacet(
        facet, coveredPieces(facet, sides.near), kept, psi, local, facetNodes,
        ds.space().nodesPerCell(), rule,
        [&](int j, GlobalOrdinal column, double value) { entries[rows[j]].emplace_back(column, value); },
        [&](int j, double weight, double value) {
          std::array<double, kRowSums>& row = sums[rows[j]];
          row[0] += value;
          row[1] += weight;
          row[2] += weight * size;
          for (int c = 0; c < 3; ++c) row[3 + c] += facet.x[j][c];
          row[6] += 1;
        });
  }

  SummedRows summed(rowIds);
  for (std::size_t i = 0; i < entries.size(); ++i)
    for (const auto& [column, value] : entries[i]) summed.add(i, column, value);
  MortarRows result;
  result.A = summed.onOwners(constraintMap, ds.ownedDofMap());
  const RCP<const MultiVector> rowSums = onOwners(rowIds, sums, constraintMap);
  checkPositiveWeights(*rowSums, pair);
  checkInitialOverlap(*rowSums, pair);
  result.d = rcp(new Vector(*rowSums->getVector(0)));
  result.weights = rcp(new Vector(*rowSums->getVector(1)));
  return result;
}

}  // namespace signorini
