#include "assembly/MortarFacet.hpp"

#include <algorithm>
#include <cmath>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

constexpr int kFacetDoubles = 3 + MortarFacet::kMaxNodes * 7 + 3;  // as packed

double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void cross3(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// A convex polygon in the slave's barycentric coordinates (lambda_1, lambda_2): a triangle
// clipped by the three sides of the reference triangle has at most six vertices.
struct Polygon {
  std::array<std::array<double, 2>, 8> p;
  int n = 0;
};

// The polygon cut by the half plane c0 + c1 lambda_1 + c2 lambda_2 >= 0 (Sutherland and Hodgman).
Polygon clip(const Polygon& polygon, double c0, double c1, double c2) {
  Polygon kept;
  for (int i = 0; i < polygon.n; ++i) {
    const auto& p = polygon.p[i];
    const auto& q = polygon.p[(i + 1) % polygon.n];
    const double fp = c0 + c1 * p[0] + c2 * p[1], fq = c0 + c1 * q[0] + c2 * q[1];
    if (fp >= 0) kept.p[kept.n++] = p;
    if ((fp >= 0) != (fq >= 0)) {
      const double t = fp / (fp - fq);
      kept.p[kept.n++] = {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
    }
  }
  return kept;
}

using Piece = std::array<std::array<double, 3>, 3>;

std::vector<Piece> overlapOfSegments(const MortarFacet& slave, const MortarFacet& master) {
  double a[3], b[3];
  slave.barycentric(master.x[0], a);
  slave.barycentric(master.x[1], b);
  const double lo = std::max(0.0, std::min(a[1], b[1])), hi = std::min(1.0, std::max(a[1], b[1]));
  if (hi - lo <= 1e-12) return {};
  return {Piece{{{1 - lo, lo, 0}, {1 - hi, hi, 0}, {0, 0, 0}}}};
}

// The master triangle projected onto the slave's plane, clipped to the slave triangle, and
// cut into a fan of triangles (the clipped polygon is convex).
std::vector<Piece> overlapOfTriangles(const MortarFacet& slave, const MortarFacet& master) {
  Polygon polygon;
  polygon.n = 3;
  for (int i = 0; i < 3; ++i) {
    double lambda[3];
    slave.barycentric(master.x[i], lambda);
    polygon.p[i] = {lambda[1], lambda[2]};
  }
  // The sides of the slave triangle, lambda_1 >= 0, lambda_2 >= 0, 1 - lambda_1 - lambda_2 >= 0.
  static constexpr double kSides[3][3] = {{0, 1, 0}, {0, 0, 1}, {1, -1, -1}};
  for (const auto& side : kSides) {  // wholly beyond one side: no overlap (the common case, cheaply)
    const auto beyond = [&](const std::array<double, 2>& q) { return side[0] + side[1] * q[0] + side[2] * q[1] < 0; };
    if (std::all_of(polygon.p.begin(), polygon.p.begin() + 3, beyond)) return {};
  }
  for (const auto& side : kSides) polygon = clip(polygon, side[0], side[1], side[2]);
  std::vector<Piece> pieces;
  for (int i = 1; i + 1 < polygon.n; ++i) {
    const auto &p = polygon.p[0], &q = polygon.p[i], &r = polygon.p[i + 1];
    const double area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    if (area <= 1e-12) continue;  // of the reference triangle's 1/2
    Piece piece;
    for (int v = 0; v < 3; ++v) {
      const auto& c = v == 0 ? p : v == 1 ? q : r;
      piece[v] = {1 - c[0] - c[1], c[0], c[1]};
    }
    pieces.push_back(piece);
  }
  return pieces;
}

}  // namespace

double MortarFacet::measure() const {
  double e1[3], e2[3], n[3];
  for (int c = 0; c < 3; ++c) {
    e1[c] = x[1][c] - x[0][c];
    e2[c] = dim == 3 ? x[2][c] - x[0][c] : 0.0;
  }
  if (dim == 2) return std::sqrt(dot3(e1, e1));
  cross3(e1, e2, n);
  return 0.5 * std::sqrt(dot3(n, n));
}

void MortarFacet::barycentric(const double* p, double* lambda) const {
  double e1[3], e2[3], r[3];
  for (int c = 0; c < 3; ++c) {
    e1[c] = x[1][c] - x[0][c];
    e2[c] = dim == 3 ? x[2][c] - x[0][c] : 0.0;
    r[c] = (c < dim ? p[c] : 0.0) - x[0][c];
  }
  if (dim == 2) {
    lambda[1] = dot3(r, e1) / dot3(e1, e1);
    lambda[0] = 1 - lambda[1];
    lambda[2] = 0;
    return;
  }
  // The normal equations of min |x0 + l1 e1 + l2 e2 - p|.
  const double g11 = dot3(e1, e1), g12 = dot3(e1, e2), g22 = dot3(e2, e2), r1 = dot3(r, e1), r2 = dot3(r, e2);
  const double det = g11 * g22 - g12 * g12;
  lambda[1] = (g22 * r1 - g12 * r2) / det;
  lambda[2] = (g11 * r2 - g12 * r1) / det;
  lambda[0] = 1 - lambda[1] - lambda[2];
}

void MortarFacet::point(const double* lambda, double* p) const {
  for (int c = 0; c < dim; ++c) {
    p[c] = 0;
    for (int v = 0; v < dim; ++v) p[c] += lambda[v] * x[v][c];
  }
}

// The Lagrange function of the lattice point alpha (|alpha| = k) is the product over the
// vertices a of prod_{m < alpha_a} (k lambda_a - m) / (m + 1).
void MortarFacet::shapeValues(const double* lambda, double* values) const {
  for (int i = 0; i < count; ++i) {
    double value = 1.0;
    for (int a = 0; a < dim; ++a)
      for (int m = 0; m < lattice[i][a]; ++m) value *= (degree * lambda[a] - m) / (m + 1);
    values[i] = value;
  }
}

std::array<double, 6> MortarFacet::boundingBox() const {
  std::array<double, 6> box{{1e300, 1e300, 1e300, -1e300, -1e300, -1e300}};
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) {
      box[c] = std::min(box[c], x[i][c]);
      box[3 + c] = std::max(box[3 + c], x[i][c]);
    }
  return box;
}

LocalFacets boundaryFacets(const DistributedSpace& ds, int tag) {
  const LagrangeSpace& space = ds.space();
  const int dim = ds.dim();
  const auto& cellLattice = space.basis().latticeIndices();
  LocalFacets result;
  result.cellFacets = space.boundaryFacets(tag);
  for (const auto& [cell, facet] : result.cellFacets) {
    const long long* nodes = space.cellNodes(cell);
    const std::vector<int> onFacet = space.basis().facetNodes(facet);  // the vertices first
    MortarFacet f;
    f.dim = dim;
    f.degree = space.degree();
    f.count = static_cast<int>(onFacet.size());
    std::vector<int> vertices;  // the facet's vertices among the cell's
    for (int v = 0; v <= dim; ++v)
      if (v != facet) vertices.push_back(v);
    for (int i = 0; i < f.count; ++i) {
      f.nodes[i] = ds.globalNode(nodes[onFacet[i]]);
      std::copy_n(&space.nodeCoordinates()[dim * nodes[onFacet[i]]], dim, f.x[i]);
      for (int v = 0; v < dim; ++v) f.lattice[i][v] = cellLattice[onFacet[i]][vertices[v]];
    }
    double e1[3], e2[3] = {0, 0, 1}, n[3], toOpposite[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) e1[c] = f.x[1][c] - f.x[0][c];
    if (dim == 3)
      for (int c = 0; c < 3; ++c) e2[c] = f.x[2][c] - f.x[0][c];
    cross3(e1, e2, n);  // in 2D, e1 x e_z: in the plane, normal to the segment
    const double* opposite = &space.nodeCoordinates()[dim * nodes[facet]];  // local facet f is opposite vertex f
    for (int c = 0; c < dim; ++c) toOpposite[c] = opposite[c] - f.x[0][c];
    const double length = std::sqrt(dot3(n, n)), sign = dot3(n, toOpposite) > 0 ? -1.0 : 1.0;
    for (int c = 0; c < 3; ++c) f.normal[c] = sign * n[c] / length;
    result.facets.push_back(f);
  }
  return result;
}

std::vector<Piece> projectedOverlap(const MortarFacet& slave, const MortarFacet& master) {
  return slave.dim == 2 ? overlapOfSegments(slave, master) : overlapOfTriangles(slave, master);
}

void pack(const MortarFacet& f, std::vector<double>& out) {
  out.insert(out.end(), {double(f.dim), double(f.degree), double(f.count)});
  for (int i = 0; i < MortarFacet::kMaxNodes; ++i) {
    out.push_back(static_cast<double>(f.nodes[i]));
    out.insert(out.end(), {f.x[i][0], f.x[i][1], f.x[i][2]});
    out.insert(out.end(), {double(f.lattice[i][0]), double(f.lattice[i][1]), double(f.lattice[i][2])});
  }
  out.insert(out.end(), {f.normal[0], f.normal[1], f.normal[2]});
}

std::vector<MortarFacet> unpackFacets(const std::vector<double>& in) {
  if (in.size() % kFacetDoubles != 0) throw Error("unpackFacets: a truncated facet");
  std::vector<MortarFacet> facets;
  for (const double* p = in.data(); p != in.data() + in.size(); p += kFacetDoubles) {
    MortarFacet f;
    f.dim = static_cast<int>(p[0]);
    f.degree = static_cast<int>(p[1]);
    f.count = static_cast<int>(p[2]);
    for (int i = 0; i < MortarFacet::kMaxNodes; ++i) {
      const double* node = p + 3 + 7 * i;
      f.nodes[i] = static_cast<GlobalOrdinal>(node[0]);
      for (int c = 0; c < 3; ++c) {
        f.x[i][c] = node[1 + c];
        f.lattice[i][c] = static_cast<int>(node[4 + c]);
      }
    }
    std::copy_n(p + 3 + 7 * MortarFacet::kMaxNodes, 3, f.normal);
    facets.push_back(f);
  }
  return facets;
}

std::array<double, 3> meanOutwardNormal(const DistributedSpace& space, int tag) {
  std::array<double, 4> sums{{0, 0, 0, 0}};  // measure times normal, measure
  for (const MortarFacet& f : boundaryFacets(space, tag).facets) {
    const double measure = f.measure();
    for (int c = 0; c < 3; ++c) sums[c] += measure * f.normal[c];
    sums[3] += measure;
  }
  std::array<double, 4> global{};
  Teuchos::reduceAll(*space.comm(), Teuchos::REDUCE_SUM, 4, sums.data(), global.data());
  if (!(global[3] > 0)) return {{0, 0, 0}};
  return {{global[0] / global[3], global[1] / global[3], global[2] / global[3]}};
}

}  // namespace signorini
