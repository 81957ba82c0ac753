#include "fe/LagrangeSpace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// The thirteen problems of doc/benchmark-family.md: n = dim * nodes, m = nodes on the bottom face.
struct PaperProblem {
  const char* name;
  int dim, degree;
  long long nx, n, m;
};

const PaperProblem paperProblems[] = {
    {"A", 2, 1, 4, 50, 5},       {"B", 3, 1, 4, 375, 25},     {"C", 3, 2, 4, 1995, 81},
    {"D", 3, 2, 8, 13203, 289},  {"E", 3, 1, 10, 3993, 121},  {"F", 3, 2, 10, 24783, 441},
    {"G", 2, 1, 20, 882, 21},    {"H", 2, 2, 20, 3362, 41},   {"I", 2, 3, 20, 7442, 61},
    {"J", 2, 1, 100, 20402, 101}, {"K", 2, 1, 50, 5202, 51},  {"L", 3, 1, 20, 27783, 441},
    {"M", 2, 1, 10, 242, 11}};

TEST(LagrangeSpace, PaperProblemSizes) {
  for (const PaperProblem& p : paperProblems) {
    const SimplexMesh mesh = makeBoxMesh(p.dim, {p.nx, p.nx, p.nx}, {1.0, 1.0, 1.0});
    const LagrangeSpace space(mesh, p.degree);
    EXPECT_EQ(p.dim * space.numNodes(), p.n) << "problem " << p.name;
    const int bottom = mesh.tag(p.dim == 2 ? "ymin" : "zmin");
    EXPECT_EQ(static_cast<long long>(space.boundaryNodes(bottom).size()), p.m) << "problem " << p.name;
  }
}

TEST(LagrangeSpace, RejectsBadDegree) {
  const SimplexMesh mesh = makeBoxMesh(2, {2, 2, 0}, {1, 1, 0});
  EXPECT_THROW(LagrangeSpace(mesh, 4), InputError);
  EXPECT_THROW(LagrangeSpace(mesh, 0), InputError);
}

TEST(LagrangeSpace, RejectsInconsistentMesh) {
  SimplexMesh mesh = makeBoxMesh(2, {2, 2, 0}, {1, 1, 0});
  SimplexMesh notAFace = mesh;
  notAFace.facets[1] = 8;  // edge 0-8 crosses the whole box: no cell has it
  EXPECT_THROW(LagrangeSpace(notAFace, 1), InputError);
  SimplexMesh missingVertex = mesh;
  missingVertex.cells[2] = 9;
  EXPECT_THROW(LagrangeSpace(missingVertex, 2), InputError);
}

struct SpaceCase {
  int dim;
  std::array<long long, 3> n;
  std::array<double, 3> lengths;
};

// Odd counts, so both 3D parities meet across faces in every direction.
const SpaceCase spaceCases[] = {{2, {3, 2, 0}, {1.5, 2.0, 0.0}}, {3, {3, 2, 3}, {1.5, 2.0, 0.5}}};

TEST(LagrangeSpace, VerticesComeFirst) {
  for (const SpaceCase& c : spaceCases)
    for (int k = 1; k <= 3; ++k) {
      const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
      const LagrangeSpace space(mesh, k);
      EXPECT_EQ(&space.mesh(), &mesh);
      EXPECT_EQ(space.dim(), c.dim);
      EXPECT_EQ(space.degree(), k);
      EXPECT_EQ(space.nodesPerCell(), space.basis().size());
      ASSERT_EQ(static_cast<long long>(space.nodeCoordinates().size()), c.dim * space.numNodes());
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_EQ(space.nodeCoordinates()[i], mesh.vertices[i]);
      for (long long cell = 0; cell < mesh.numCells(); ++cell)
        for (int v = 0; v <= c.dim; ++v) EXPECT_EQ(space.cellNodes(cell)[v], mesh.cells[(c.dim + 1) * cell + v]);
    }
}

// Every cell's local node, placed from the cell's own vertices, is where its global node is;
// and distinct global nodes are at distinct points, so shared nodes are numbered once.
TEST(LagrangeSpace, SharedNodesConsistent) {
  for (const SpaceCase& c : spaceCases)
    for (int k = 1; k <= 3; ++k) {
      const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
      const LagrangeSpace space(mesh, k);
      const int d = c.dim;
      const auto& x = space.nodeCoordinates();
      std::vector<char> seen(space.numNodes(), 0);
      for (long long cell = 0; cell < mesh.numCells(); ++cell) {
        const long long* vertex = &mesh.cells[(d + 1) * cell];
        for (int local = 0; local < space.nodesPerCell(); ++local) {
          const long long node = space.cellNodes(cell)[local];
          ASSERT_GE(node, 0);
          ASSERT_LT(node, space.numNodes());
          seen[node] = 1;
          const auto& a = space.basis().latticeIndices()[local];
          for (int j = 0; j < d; ++j) {
            double expected = 0;
            for (int i = 0; i <= d; ++i) expected += a[i] * mesh.vertices[d * vertex[i] + j] / k;
            EXPECT_NEAR(x[d * node + j], expected, 1e-14) << "dim " << d << " k " << k << " cell " << cell;
          }
        }
      }
      EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), space.numNodes());
      std::set<std::vector<long long>> points;  // coordinates in units of h / k: integers
      for (long long node = 0; node < space.numNodes(); ++node) {
        std::vector<long long> p;
        for (int j = 0; j < d; ++j) p.push_back(std::llround(x[d * node + j] * k * c.n[j] / c.lengths[j]));
        points.insert(p);
      }
      EXPECT_EQ(static_cast<long long>(points.size()), space.numNodes()) << "dim " << d << " k " << k;
    }
}

TEST(LagrangeSpace, NodeCounts) {
  for (int k = 1; k <= 3; ++k) {
    const SimplexMesh square = makeBoxMesh(2, {3, 2, 0}, {1, 1, 0});
    EXPECT_EQ(LagrangeSpace(square, k).numNodes(), (3 * k + 1) * (2 * k + 1));
  }
  const SimplexMesh cube = makeBoxMesh(3, {3, 3, 3}, {1, 1, 1});
  EXPECT_EQ(LagrangeSpace(cube, 1).numNodes(), 4 * 4 * 4);
  EXPECT_EQ(LagrangeSpace(cube, 2).numNodes(), 7 * 7 * 7 - 3 * 3 * 3);  // no cube centres
}

TEST(LagrangeSpace, BoundaryNodesAndFacets) {
  for (const SpaceCase& c : spaceCases)
    for (int k = 1; k <= 3; ++k) {
      const SimplexMesh mesh = makeBoxMesh(c.dim, c.n, c.lengths);
      const LagrangeSpace space(mesh, k);
      const int d = c.dim;
      for (const auto& [name, tag] : mesh.boundaryTags) {
        const int axis = (tag - 1) / 2, side = (tag - 1) % 2;
        // A structured face of the box carries a full tensor grid of nodes.
        long long expected = 1;
        for (int a = 0; a < d; ++a)
          if (a != axis) expected *= k * c.n[a] + 1;
        const std::vector<long long> nodes = space.boundaryNodes(tag);
        EXPECT_EQ(static_cast<long long>(nodes.size()), expected) << name << " k " << k;
        EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
        for (long long node : nodes) EXPECT_NEAR(space.nodeCoordinates()[d * node + axis], side * c.lengths[axis], 1e-14);

        const auto facets = space.boundaryFacets(tag);
        long long next = 0;
        for (const auto& [cell, f] : facets) {
          while (mesh.facetTags[next] != tag) ++next;  // facets come in mesh facet order
          std::set<long long> fromCell, fromMesh(mesh.facets.begin() + d * next, mesh.facets.begin() + d * (next + 1));
          for (int v = 0; v <= d; ++v)
            if (v != f) fromCell.insert(mesh.cells[(d + 1) * cell + v]);
          EXPECT_EQ(fromCell, fromMesh);
          ++next;
        }
        EXPECT_EQ(static_cast<long long>(facets.size()), std::count(mesh.facetTags.begin(), mesh.facetTags.end(), tag));
      }
      EXPECT_TRUE(space.boundaryNodes(99).empty());
    }
}

// A part's space takes the coordinates of the nodes past the vertices as given, and checks
// their count; facetCell() names the cell of each boundary facet.
TEST(LagrangeSpace, GivenNodeCoordinatesAndFacetCells) {
  const SimplexMesh mesh = makeBoxMesh(3, {2, 1, 1}, {1, 1, 1});
  const LagrangeSpace computed(mesh, 3);
  std::vector<double> given(computed.nodeCoordinates().begin() + 3 * mesh.numVertices(),
                            computed.nodeCoordinates().end());
  for (double& x : given) x += 1.0;
  const LagrangeSpace space(mesh, 3, given);
  ASSERT_EQ(space.numNodes(), computed.numNodes());
  for (long long i = 0; i < 3 * computed.numNodes(); ++i)
    EXPECT_EQ(space.nodeCoordinates()[i], computed.nodeCoordinates()[i] + (i < 3 * mesh.numVertices() ? 0.0 : 1.0));
  given.pop_back();
  EXPECT_THROW(LagrangeSpace(mesh, 3, given), InputError);

  const std::vector<std::pair<long long, int>> zmin = computed.boundaryFacets(mesh.tag("zmin"));
  std::vector<std::pair<long long, int>> fromFacets;
  for (long long f = 0; f < mesh.numFacets(); ++f)
    if (mesh.facetTags[f] == mesh.tag("zmin")) fromFacets.push_back(computed.facetCell(f));
  EXPECT_EQ(fromFacets, zmin);
}

}  // namespace
}  // namespace signorini
