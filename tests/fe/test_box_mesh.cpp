#include "fe/BoxMesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Signed volume of a cell (area in 2D).
double signedVolume(const SimplexMesh& mesh, long long cell) {
  const int d = mesh.dim;
  double x[12];
  mesh.cellVertexCoordinates(cell, x);
  double e[3][3];
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) e[i][j] = x[(i + 1) * d + j] - x[j];
  if (d == 2) return (e[0][0] * e[1][1] - e[0][1] * e[1][0]) / 2;
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
         6;
}

// Measure of a boundary facet (length in 2D, area in 3D).
double facetMeasure(const SimplexMesh& mesh, long long facet) {
  const int d = mesh.dim;
  const double* p[3];
  for (int v = 0; v < d; ++v) p[v] = &mesh.vertices[d * mesh.facets[d * facet + v]];
  if (d == 2) return std::hypot(p[1][0] - p[0][0], p[1][1] - p[0][1]);
  double a[3], b[3];
  for (int j = 0; j < 3; ++j) {
    a[j] = p[1][j] - p[0][j];
    b[j] = p[2][j] - p[0][j];
  }
  return 0.5 * std::sqrt(std::pow(a[1] * b[2] - a[2] * b[1], 2) + std::pow(a[2] * b[0] - a[0] * b[2], 2) +
                         std::pow(a[0] * b[1] - a[1] * b[0], 2));
}

std::set<long long> cellVertexSet(const SimplexMesh& mesh, long long cell) {
  return std::set<long long>(mesh.cells.begin() + (mesh.dim + 1) * cell,
                             mesh.cells.begin() + (mesh.dim + 1) * (cell + 1));
}

struct BoxCase {
  int dim;
  std::array<long long, 3> n;
  std::array<double, 3> lengths;
};

const std::vector<BoxCase> boxCases = {
    {2, {3, 2, 0}, {1.5, 2.0, 0.0}}, {2, {1, 1, 1}, {1, 1, 1}},  {3, {3, 2, 2}, {1.5, 2.0, 0.5}},
    {3, {2, 3, 1}, {1, 1, 1}},       {3, {1, 1, 1}, {1, 1, 1}}};

TEST(BoxMesh, RejectsBadInput) {
  EXPECT_THROW(makeBoxMesh(1, {2, 2, 2}, {1, 1, 1}), InputError);
  EXPECT_THROW(makeBoxMesh(4, {2, 2, 2}, {1, 1, 1}), InputError);
  EXPECT_THROW(makeBoxMesh(2, {0, 2, 2}, {1, 1, 1}), InputError);
  EXPECT_THROW(makeBoxMesh(3, {2, 2, 2}, {1, 1, -1}), InputError);
}

TEST(BoxMesh, CountsAndVertexNumbering) {
  for (const BoxCase& c : boxCases) {
    const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
    const long long n0 = c.n[0], n1 = c.n[1], n2 = c.dim == 3 ? c.n[2] : 1;
    EXPECT_EQ(mesh.dim, c.dim);
    EXPECT_EQ(mesh.numVertices(), (n0 + 1) * (n1 + 1) * (c.dim == 3 ? n2 + 1 : 1));
    EXPECT_EQ(mesh.numCells(), (c.dim == 2 ? 2 : 5) * n0 * n1 * n2);
    EXPECT_EQ(mesh.numFacets(), c.dim == 2 ? 2 * (n0 + n1) : 4 * (n0 * n1 + n1 * n2 + n0 * n2));
    EXPECT_EQ(static_cast<long long>(mesh.facetTags.size()), mesh.numFacets());
    // Vertex (i,j,k) has id i + (n0+1)(j + (n1+1)k) and sits at (i L0/n0, j L1/n1, k L2/n2).
    for (long long k = 0; k <= (c.dim == 3 ? n2 : 0); ++k)
      for (long long j = 0; j <= n1; ++j)
        for (long long i = 0; i <= n0; ++i) {
          const long long id = i + (n0 + 1) * (j + (n1 + 1) * k);
          const long long index[3] = {i, j, k};
          for (int a = 0; a < c.dim; ++a)
            EXPECT_NEAR(mesh.vertices[c.dim * id + a], c.lengths[a] * index[a] / c.n[a], 1e-15);
        }
  }
}

TEST(BoxMesh, BoundaryNamesAndTags) {
  const SimplexMesh mesh = makeBoxMesh(3, {2, 2, 2}, {1, 1, 1});
  EXPECT_EQ(mesh.tag("xmin"), 1);
  EXPECT_EQ(mesh.tag("xmax"), 2);
  EXPECT_EQ(mesh.tag("ymin"), 3);
  EXPECT_EQ(mesh.tag("ymax"), 4);
  EXPECT_EQ(mesh.tag("zmin"), 5);
  EXPECT_EQ(mesh.tag("zmax"), 6);
  EXPECT_THROW(makeBoxMesh(2, {2, 2, 0}, {1, 1, 0}).tag("zmin"), InputError);
}

TEST(BoxMesh, PositiveCellsFillTheBox) {
  for (const BoxCase& c : boxCases) {
    const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
    double total = 0, expected = 1, smallest = 1e300;
    for (int a = 0; a < c.dim; ++a) expected *= c.lengths[a];
    for (long long cell = 0; cell < mesh.numCells(); ++cell) {
      const double v = signedVolume(mesh, cell);
      smallest = std::min(smallest, v);
      total += v;
    }
    EXPECT_GT(smallest, 0.0) << "dim " << c.dim;
    EXPECT_NEAR(total, expected, 1e-12 * expected) << "dim " << c.dim;
  }
}

TEST(BoxMesh, BoundaryFacetsCoverEachFace) {
  for (const BoxCase& c : boxCases) {
    const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
    std::map<int, double> measure;
    for (long long facet = 0; facet < mesh.numFacets(); ++facet) {
      const int tag = mesh.facetTags[facet];
      ASSERT_GE(tag, 1);
      ASSERT_LE(tag, 2 * c.dim);
      const int axis = (tag - 1) / 2, side = (tag - 1) % 2;
      for (int v = 0; v < c.dim; ++v)  // every vertex lies on the face the tag names
        EXPECT_EQ(mesh.vertices[c.dim * mesh.facets[c.dim * facet + v] + axis], side * c.lengths[axis]);
      measure[tag] += facetMeasure(mesh, facet);
    }
    for (int tag = 1; tag <= 2 * c.dim; ++tag) {
      double expected = 1;
      for (int a = 0; a < c.dim; ++a)
        if (a != (tag - 1) / 2) expected *= c.lengths[a];
      EXPECT_NEAR(measure[tag], expected, 1e-12) << "dim " << c.dim << " tag " << tag;
    }
  }
}

// Each face of a cell is shared by two cells, or by one if and only if it is a boundary facet.
TEST(BoxMesh, Conforming) {
  for (const BoxCase& c : boxCases) {
    const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
    std::map<std::vector<long long>, int> faceCount;
    for (long long cell = 0; cell < mesh.numCells(); ++cell)
      for (int f = 0; f <= c.dim; ++f) {
        std::vector<long long> face;
        for (int v = 0; v <= c.dim; ++v)
          if (v != f) face.push_back(mesh.cells[(c.dim + 1) * cell + v]);
        std::sort(face.begin(), face.end());
        ++faceCount[face];
      }
    std::set<std::vector<long long>> boundary;
    for (long long facet = 0; facet < mesh.numFacets(); ++facet) {
      std::vector<long long> face(mesh.facets.begin() + c.dim * facet, mesh.facets.begin() + c.dim * (facet + 1));
      std::sort(face.begin(), face.end());
      EXPECT_TRUE(boundary.insert(face).second) << "facet listed twice";
    }
    for (const auto& [face, count] : faceCount) {
      EXPECT_TRUE(count == 1 || count == 2) << count;
      EXPECT_EQ(count == 1, boundary.count(face) == 1);
    }
  }
}

// The subdivision is the one of doc/benchmark-family.md, as vertex sets.
TEST(BoxMesh, SubdivisionOfProblemSet) {
  const SimplexMesh square = makeBoxMesh(2, {2, 2, 0}, {1, 1, 0});
  // Square (0,0): a=0, b=1, c=3, e=4 -> triangles (a,b,e), (a,e,c).
  EXPECT_EQ(cellVertexSet(square, 0), (std::set<long long>{0, 1, 4}));
  EXPECT_EQ(cellVertexSet(square, 1), (std::set<long long>{0, 4, 3}));

  const SimplexMesh cube = makeBoxMesh(3, {2, 1, 1}, {1, 1, 1});
  // Vertex v_abc of cube i is (i + a) + 3 b + 6 c.
  auto v = [](int i, int a, int b, int c) { return static_cast<long long>(i + a + 3 * b + 6 * c); };
  const std::vector<std::set<long long>> even = {{v(0, 0, 0, 0), v(0, 1, 0, 0), v(0, 0, 1, 0), v(0, 0, 0, 1)},
                                                 {v(0, 1, 1, 0), v(0, 1, 0, 0), v(0, 0, 1, 0), v(0, 1, 1, 1)},
                                                 {v(0, 1, 0, 1), v(0, 1, 0, 0), v(0, 0, 0, 1), v(0, 1, 1, 1)},
                                                 {v(0, 0, 1, 1), v(0, 0, 1, 0), v(0, 0, 0, 1), v(0, 1, 1, 1)},
                                                 {v(0, 1, 0, 0), v(0, 0, 1, 0), v(0, 0, 0, 1), v(0, 1, 1, 1)}};
  const std::vector<std::set<long long>> odd = {{v(1, 1, 0, 0), v(1, 0, 0, 0), v(1, 1, 1, 0), v(1, 1, 0, 1)},
                                                {v(1, 0, 1, 0), v(1, 0, 0, 0), v(1, 1, 1, 0), v(1, 0, 1, 1)},
                                                {v(1, 0, 0, 1), v(1, 0, 0, 0), v(1, 1, 0, 1), v(1, 0, 1, 1)},
                                                {v(1, 1, 1, 1), v(1, 1, 1, 0), v(1, 1, 0, 1), v(1, 0, 1, 1)},
                                                {v(1, 0, 0, 0), v(1, 1, 1, 0), v(1, 1, 0, 1), v(1, 0, 1, 1)}};
  for (int t = 0; t < 5; ++t) {
    EXPECT_EQ(cellVertexSet(cube, t), even[t]) << "even tet " << t;
    EXPECT_EQ(cellVertexSet(cube, 5 + t), odd[t]) << "odd tet " << t;
  }
}

// The blocks of a decomposition together are the whole mesh: each block's cells are the
// global cells (same vertex coordinates, same order), and its facets the global ones.
TEST(BoxMesh, BlocksMakeUpTheWholeMesh) {
  for (int dim = 2; dim <= 3; ++dim) {
    const std::array<long long, 3> n = {5, 4, 3};
    const std::array<double, 3> lengths = {1.0, 0.8, 0.6};
    const SimplexMesh whole = makeBoxMesh(dim, n, lengths);
    const BoxDecomposition blocks = decomposeBox(dim, n, 6);
    ASSERT_EQ(blocks.numBlocks(), 6);
    std::vector<int> seen(whole.numCells(), 0);
    long long facets = 0;
    std::vector<double> x((dim + 1) * dim), y((dim + 1) * dim);
    for (int b = 0; b < 6; ++b) {
      const SimplexMesh part = makeBoxMesh(dim, n, lengths, blocks.block(b));
      const std::vector<long long> cells = boxBlockCells(dim, n, blocks.block(b));
      ASSERT_EQ(static_cast<long long>(cells.size()), part.numCells());
      for (long long c = 0; c < part.numCells(); ++c) {
        ++seen[cells[c]];
        part.cellVertexCoordinates(c, x.data());
        whole.cellVertexCoordinates(cells[c], y.data());
        EXPECT_EQ(x, y) << "block " << b << " cell " << cells[c];
      }
      facets += part.numFacets();
    }
    for (int count : seen) EXPECT_EQ(count, 1);
    EXPECT_EQ(facets, whole.numFacets());
  }
}

TEST(BoxMesh, DecompositionPicksTheSmallestLargestBlock) {
  auto counts = [](const BoxDecomposition& d) {
    return std::array<std::size_t, 3>{d.splits[0].size() - 1, d.splits[1].size() - 1, d.splits[2].size() - 1};
  };
  EXPECT_EQ(counts(decomposeBox(3, {40, 40, 40}, 8)), (std::array<std::size_t, 3>{2, 2, 2}));
  EXPECT_EQ(counts(decomposeBox(2, {7, 5, 1}, 8)), (std::array<std::size_t, 3>{4, 2, 1}));
  // A tie in size and interface: the most blocks along the first axes.
  EXPECT_EQ(counts(decomposeBox(3, {3, 4, 3}, 3)), (std::array<std::size_t, 3>{3, 1, 1}));
  EXPECT_EQ(counts(decomposeBox(3, {10, 10, 10}, 2)), (std::array<std::size_t, 3>{2, 1, 1}));
  // More ranks than the boxes can be cut into.
  EXPECT_EQ(decomposeBox(2, {2, 2, 1}, 7).numBlocks(), 0);
  const BoxDecomposition d = decomposeBox(2, {7, 5, 1}, 8);
  EXPECT_EQ(d.splits[0], (std::vector<long long>{0, 1, 3, 5, 7}));
  EXPECT_EQ(d.block(5).begin, (std::array<long long, 3>{1, 2, 0}));
  EXPECT_EQ(d.block(5).end, (std::array<long long, 3>{3, 5, 1}));
}

// A point on a face between blocks belongs to the lower-numbered block.
TEST(BoxMesh, LowestBlockHoldingAPoint) {
  const BoxDecomposition d = decomposeBox(2, {4, 4, 1}, 4);  // 2 x 2 blocks of 2 x 2 boxes
  ASSERT_EQ(d.numBlocks(), 4);
  const int degree = 2;  // lattice points at half box widths
  EXPECT_EQ(d.lowestBlockHolding({0, 0, 0}, degree), 0);
  EXPECT_EQ(d.lowestBlockHolding({4, 0, 0}, degree), 0);  // x = 2 boxes: the face of blocks 0 and 1
  EXPECT_EQ(d.lowestBlockHolding({5, 0, 0}, degree), 1);
  EXPECT_EQ(d.lowestBlockHolding({5, 4, 0}, degree), 1);
  EXPECT_EQ(d.lowestBlockHolding({5, 5, 0}, degree), 3);
  EXPECT_EQ(d.lowestBlockHolding({8, 8, 0}, degree), 3);
  EXPECT_EQ(d.lowestBlockHolding({3, 7, 0}, degree), 2);
}

}  // namespace
}  // namespace signorini
