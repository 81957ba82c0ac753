#include "assembly/MortarConstraints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/ContactMultiplierBasis.hpp"
#include "assembly/SummedRows.hpp"
#include "core/Collectives.hpp"
#include "core/NeighbourExchange.hpp"
#include "fe/SimplexQuadrature.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// A boundary segment (2D, P1 to P3): its nodes' global ids and coordinates, its end
// vertices first, and the outward normal of its body.
struct Segment {
  int count = 0;  // degree + 1 nodes
  GlobalOrdinal nodes[4];
  double x[4][2];
  double normal[2];

  double length() const { return std::hypot(x[1][0] - x[0][0], x[1][1] - x[0][1]); }
  // The position of point p along the segment: 0 at x[0], 1 at x[1] (of its projection).
  double along(const double* p) const {
    const double t[2] = {x[1][0] - x[0][0], x[1][1] - x[0][1]};
    return ((p[0] - x[0][0]) * t[0] + (p[1] - x[0][1]) * t[1]) / (t[0] * t[0] + t[1] * t[1]);
  }
  // The values at position xi of the Lagrange functions of the segment's nodes.
  void shapeValues(double xi, double* values) const {
    for (int i = 0; i < count; ++i) {
      values[i] = 1.0;
      for (int m = 0; m < count; ++m)
        if (m != i) values[i] *= (xi - along(x[m])) / (along(x[i]) - along(x[m]));
    }
  }
};
constexpr int kSegmentDoubles = 15;  // as sent between ranks

void pack(const Segment& s, std::vector<double>& out) {
  out.push_back(s.count);
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<double>(s.nodes[i]));
  for (int i = 0; i < 4; ++i) out.insert(out.end(), {s.x[i][0], s.x[i][1]});
  out.insert(out.end(), {s.normal[0], s.normal[1]});
}

Segment unpack(const double* in) {
  Segment s;
  s.count = static_cast<int>(in[0]);
  for (int i = 0; i < 4; ++i) {
    s.nodes[i] = static_cast<GlobalOrdinal>(in[1 + i]);
    s.x[i][0] = in[5 + 2 * i];
    s.x[i][1] = in[6 + 2 * i];
  }
  s.normal[0] = in[13];
  s.normal[1] = in[14];
  return s;
}

// The boundary segments of this rank's part with the given tag, each with its cell and local facet.
struct LocalSegments {
  std::vector<Segment> segments;
  std::vector<std::pair<long long, int>> facets;
};

LocalSegments boundarySegments(const DistributedSpace& ds, int tag) {
  const LagrangeSpace& space = ds.space();
  LocalSegments result;
  result.facets = space.boundaryFacets(tag);
  for (const auto& [cell, facet] : result.facets) {
    const long long* nodes = space.cellNodes(cell);
    const std::vector<int> onFacet = space.basis().facetNodes(facet);  // the vertices first
    Segment s{};
    s.count = static_cast<int>(onFacet.size());
    for (int i = 0; i < s.count; ++i) {
      s.nodes[i] = ds.globalNode(nodes[onFacet[i]]);
      std::copy_n(&space.nodeCoordinates()[2 * nodes[onFacet[i]]], 2, s.x[i]);
    }
    const double t[2] = {s.x[1][0] - s.x[0][0], s.x[1][1] - s.x[0][1]}, length = s.length();
    s.normal[0] = t[1] / length;
    s.normal[1] = -t[0] / length;
    const double* opposite = &space.nodeCoordinates()[2 * nodes[facet]];  // local facet f is opposite vertex f
    if (s.normal[0] * (opposite[0] - s.x[0][0]) + s.normal[1] * (opposite[1] - s.x[0][1]) > 0) {
      s.normal[0] = -s.normal[0];
      s.normal[1] = -s.normal[1];
    }
    result.segments.push_back(s);
  }
  return result;
}

// Lower and upper corner of the bounding box of segments [begin, end); empty (lower > upper)
// without segments.
std::array<double, 4> boundingBox(const Segment* begin, const Segment* end) {
  std::array<double, 4> box{{1e300, 1e300, -1e300, -1e300}};
  for (const Segment* s = begin; s != end; ++s)
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 2; ++c) {
        box[c] = std::min(box[c], s->x[i][c]);
        box[2 + c] = std::max(box[2 + c], s->x[i][c]);
      }
  return box;
}

std::array<double, 4> boundingBox(const std::vector<Segment>& segments) {
  return boundingBox(segments.data(), segments.data() + segments.size());
}

// The master segments of every rank that lie within `reach` of this rank's slave segments'
// bounding box: each rank sends every other the master segments in that rank's box.
std::vector<Segment> nearMasterSegments(const Comm& comm, const std::vector<Segment>& slave,
                                        const std::vector<Segment>& master, double reach) {
  const int size = comm.getSize();
  const std::array<double, 4> mine = boundingBox(slave);
  std::vector<double> boxes(4 * size);
  Teuchos::gatherAll(comm, 4, mine.data(), 4 * size, boxes.data());
  std::vector<std::array<double, 4>> own;
  for (const Segment& s : master) own.push_back(boundingBox(&s, &s + 1));
  std::vector<std::vector<double>> toRank(size);
  for (int r = 0; r < size; ++r) {
    const double* box = &boxes[4 * r];
    for (std::size_t k = 0; k < master.size(); ++k) {
      const std::array<double, 4>& b = own[k];
      if (b[0] <= box[2] + reach && b[2] >= box[0] - reach && b[1] <= box[3] + reach && b[3] >= box[1] - reach)
        pack(master[k], toRank[r]);
    }
  }
  const std::vector<double> received = exchangeWithRanks(comm, toRank);
  std::vector<Segment> near;
  for (std::size_t i = 0; i + kSegmentDoubles <= received.size(); i += kSegmentDoubles) near.push_back(unpack(&received[i]));
  return near;
}

double cross(const double* a, const double* b) { return a[0] * b[1] - a[1] * b[0]; }

// One slave segment's rows: per master segment facing it, the piece of the slave segment
// its projection covers, integrated by Gauss points. `add(j, column, value)` and
// `gap(j, value)` take the entries of the slave segment's node j; returns the covered
// fraction of the slave segment.
template <class AddEntry, class AddGap>
double integrateSegment(const Segment& s, const std::vector<Segment>& master, double reach,
                        const ContactMultiplierBasis& psi, int facet, const std::vector<int>& facetNodes,
                        int nodesPerCell, const QuadratureRule& rule, AddEntry&& add, AddGap&& gap) {
  const double* n = s.normal;
  const double t[2] = {s.x[1][0] - s.x[0][0], s.x[1][1] - s.x[0][1]}, length = s.length();
  double covered = 0;
  std::vector<double> phi(nodesPerCell, 0.0);
  double slave[4], masterValues[4];
  for (const Segment& m : master) {
    if (n[0] * m.normal[0] + n[1] * m.normal[1] >= 0) continue;  // not facing the slave side
    const double a = s.along(m.x[0]), b = s.along(m.x[1]);
    const double lo = std::max(0.0, std::min(a, b)), hi = std::min(1.0, std::max(a, b));
    if (hi - lo <= 1e-12) continue;
    const double e[2] = {m.x[1][0] - m.x[0][0], m.x[1][1] - m.x[0][1]};
    const double facing = cross(e, n);
    if (std::abs(facing) < 1e-12 * m.length()) continue;
    // The point of m along n from x_s (x_s + alpha n = x_m(eta)) and the distance alpha.
    const auto onMaster = [&](const double* xs, double& eta) {
      const double d[2] = {xs[0] - m.x[0][0], xs[1] - m.x[0][1]};
      eta = cross(d, n) / facing;
      return (m.x[0][0] + eta * e[0] - xs[0]) * n[0] + (m.x[0][1] + eta * e[1] - xs[1]) * n[1];
    };
    // A master segment beyond reach at the piece's middle is another part of the surface.
    double eta = 0;
    const double middle[2] = {s.x[0][0] + 0.5 * (lo + hi) * t[0], s.x[0][1] + 0.5 * (lo + hi) * t[1]};
    if (std::abs(onMaster(middle, eta)) > reach) continue;
    covered += hi - lo;
    for (int q = 0; q < rule.size(); ++q) {
      const double xi = lo + (hi - lo) * rule.points[q], w = rule.weights[q] * (hi - lo) * length;
      const double xs[2] = {s.x[0][0] + xi * t[0], s.x[0][1] + xi * t[1]};
      const double g0 = onMaster(xs, eta);
      s.shapeValues(xi, slave);
      m.shapeValues(eta, masterValues);
      for (int i = 0; i < s.count; ++i) phi[facetNodes[i]] = slave[i];
      for (int j = 0; j < s.count; ++j) {
        const double psiJ = w * psi.value(facet, facetNodes[j], phi.data());
        gap(j, psiJ * g0);
        for (int c = 0; c < 2; ++c) {
          for (int k = 0; k < s.count; ++k) add(j, 2 * s.nodes[k] + c, psiJ * slave[k] * n[c]);
          for (int l = 0; l < m.count; ++l) add(j, 2 * m.nodes[l] + c, -psiJ * masterValues[l] * n[c]);
        }
      }
    }
  }
  return covered;
}

void checkPair(const DistributedSpace& ds, const ContactPair& pair) {
  if (pair.masterBoundary == pair.boundary)
    throw InputError("Problem/Contact: the master boundary \"" + pair.masterBoundary +
                     "\" is the contact boundary itself; name the other body's surface");
  ds.mesh().tag(pair.masterBoundary);  // throws naming the known boundaries
  if (ds.dim() != 2)
    throw InputError("Problem/Contact/master boundary: contact between two bodies is available in 2D so far");
  if (!isWeightedGap(pair.formulation))
    throw InputError("Problem/Contact/formulation: contact between two bodies needs weighted constraints "
                     "(\"dual mortar\" or \"weighted gap\"), not nodal ones");
}

}  // namespace

MortarRows mortarConstraints(const DistributedSpace& ds, const ProblemDefinition& problem,
                             const std::vector<long long>& constraintOf, const RCP<const Map>& constraintMap) {
  const ContactPair& pair = *problem.contact;
  checkPair(ds, pair);
  const LocalSegments slave = boundarySegments(ds, ds.mesh().tag(pair.boundary));
  const LocalSegments master = boundarySegments(ds, ds.mesh().tag(pair.masterBoundary));
  // How far a master facet may be from the slave facets it faces: twice the longest facet of
  // either side, or the size of the whole slave boundary (its bounding box's diagonal).
  double longest = 0;
  for (const auto* side : {&slave, &master})
    for (const Segment& s : side->segments) longest = std::max(longest, s.length());
  std::array<double, 4> box = boundingBox(slave.segments);
  for (int c = 0; c < 2; ++c) {
    box[c] = minOverRanks(*ds.comm(), box[c]);
    box[2 + c] = maxOverRanks(*ds.comm(), box[2 + c]);
  }
  const double reach = std::max(2.0 * maxOverRanks(*ds.comm(), longest), std::hypot(box[2] - box[0], box[3] - box[1]));
  const std::vector<Segment> near = nearMasterSegments(*ds.comm(), slave.segments, master.segments, reach);

  std::vector<long long> rowOfOverlapNode(ds.space().numNodes(), -1);
  for (std::size_t i = 0; i < constraintOf.size(); ++i) rowOfOverlapNode[ds.overlapSpaceNodes()[i]] = constraintOf[i];
  std::map<GlobalOrdinal, std::size_t> localRow;
  std::vector<GlobalOrdinal> rowIds;
  std::vector<double> gaps;
  std::vector<std::vector<std::pair<GlobalOrdinal, double>>> entries;
  const ContactMultiplierBasis psi(ds.space().basis(), pair.formulation);
  const QuadratureRule rule = simplexQuadrature(1, 2 * ds.space().degree());  // psi_j N_l exactly
  long long uncovered = 0;
  for (std::size_t f = 0; f < slave.segments.size(); ++f) {
    const auto [cell, facet] = slave.facets[f];
    const std::vector<int> facetNodes = ds.space().basis().facetNodes(facet);
    std::size_t rows[4];
    for (std::size_t j = 0; j < facetNodes.size(); ++j) {
      const long long row = rowOfOverlapNode[ds.space().cellNodes(cell)[facetNodes[j]]];
      if (row < 0) throw Error("mortar constraints: a slave node has no constraint");
      const auto [it, fresh] = localRow.emplace(row, rowIds.size());
      if (fresh) {
        rowIds.push_back(row);
        gaps.push_back(0.0);
        entries.emplace_back();
      }
      rows[j] = it->second;
    }
    const double covered = integrateSegment(
        slave.segments[f], near, reach, psi, facet, facetNodes, ds.space().nodesPerCell(), rule,
        [&](int j, GlobalOrdinal column, double value) { entries[rows[j]].emplace_back(column, value); },
        [&](int j, double value) { gaps[rows[j]] += value; });
    if (covered < 1.0 - 1e-9) ++uncovered;
  }
  if (const long long total = sumOverRanks(*ds.comm(), uncovered); total > 0)
    throw InputError("Problem/Contact: " + std::to_string(total) + " facet(s) of the contact boundary \"" + pair.boundary +
                     "\" are not covered by the master boundary \"" + pair.masterBoundary +
                     "\" facing them; make the slave boundary the part that lies within the master's reach");

  SummedRows summed(rowIds);
  for (std::size_t i = 0; i < entries.size(); ++i)
    for (const auto& [column, value] : entries[i]) summed.add(i, column, value);
  MortarRows result;
  result.A = summed.onOwners(constraintMap, ds.ownedDofMap());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto touched = rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(rowIds), 0, ds.comm()));
  Vector local(touched);
  {
    auto data = local.getDataNonConst();
    for (std::size_t i = 0; i < gaps.size(); ++i) data[i] = gaps[i];
  }
  result.d = rcp(new Vector(constraintMap));
  result.d->doExport(local, Tpetra::Export<LocalOrdinal, GlobalOrdinal, Node>(touched, constraintMap), Tpetra::ADD);
  return result;
}

}  // namespace signorini
