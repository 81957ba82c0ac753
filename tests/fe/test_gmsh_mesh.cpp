#include "fe/GmshMesh.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "signorini/core/Error.hpp"

// The meshes are made with the Gmsh API itself, written to a temporary directory in the
// format under test, and read back with readGmshMesh.

namespace signorini {
namespace {

// ---------------------------------------------------------------------------------------
// Helpers.

class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "signorini-gmsh-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// The test's own Gmsh session, finalised even when an assertion throws.
class GmshApi {
 public:
  GmshApi() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshApi() {
    try {
      gmsh::finalize();
    } catch (...) {
    }
  }
  GmshApi(const GmshApi&) = delete;
  GmshApi& operator=(const GmshApi&) = delete;
};

struct Format {
  double version;
  bool binary;
};

std::string formatName(const Format& format) {
  return std::string(format.version < 3 ? "msh22" : "msh41") +
         (format.binary ? "_binary" : "_ascii");
}

void PrintTo(const Format& format, std::ostream* os) { *os << formatName(format); }

void writeMesh(const std::string& path, const Format& format) {
  gmsh::option::setNumber("Mesh.MshFileVersion", format.version);
  gmsh::option::setNumber("Mesh.Binary", format.binary ? 1 : 0);
  gmsh::write(path);
}

int addNamedGroup(int dim, const std::vector<int>& entities, const std::string& name) {
  const int tag = gmsh::model::addPhysicalGroup(dim, entities);
  gmsh::model::setPhysicalName(dim, tag, name);
  return tag;
}

// What Gmsh itself says about the mesh it wrote.
struct Expected {
  long long vertices = 0;  // distinct nodes of the cells
  long long cells = 0;
  long long negativeCells = 0;  // in Gmsh's orientation
};

Expected countSimplices(int type, int entity = -1) {
  std::vector<std::size_t> elementTags, nodeTags;
  gmsh::model::mesh::getElementsByType(type, elementTags, nodeTags, entity);
  Expected expected;
  expected.cells = static_cast<long long>(elementTags.size());
  std::vector<std::size_t> nodes = nodeTags;
  std::sort(nodes.begin(), nodes.end());
  expected.vertices = std::unique(nodes.begin(), nodes.end()) - nodes.begin();
  if (type == 2) {
    for (std::size_t e = 0; e < elementTags.size(); ++e) {
      double x[3][3];
      for (int i = 0; i < 3; ++i) {
        std::vector<double> coord, parametric;
        gmsh::model::mesh::getNode(nodeTags[3 * e + i], coord, parametric);
        std::copy(coord.begin(), coord.end(), x[i]);
      }
      const double det =
          (x[1][0] - x[0][0]) * (x[2][1] - x[0][1]) - (x[2][0] - x[0][0]) * (x[1][1] - x[0][1]);
      if (det < 0) ++expected.negativeCells;
    }
  }
  return expected;
}

struct SquareOptions {
  double meshSize = 0.25;
  bool boundaryGroups = true;
  bool domainGroup = true;
  bool secondDomainGroup = false;  // the surface in a second physical group "whole"
  bool secondBottomGroup = false;  // curve 1 also in a physical group "ground"
  bool isolatedPoint = false;      // a meshed geometry point outside the square
  bool quads = false;
  int order = 1;
  bool reverse = false;
};

// Unit square: curves 1 bottom (y=0), 2 right (x=1), 3 top (y=1), 4 left (x=0), surface 1.
Expected writeSquare(const std::string& path, const Format& format,
                     const SquareOptions& options = {}) {
  GmshApi api;
  gmsh::model::add("square");
  const double h = options.meshSize;
  gmsh::model::geo::addPoint(0, 0, 0, h, 1);
  gmsh::model::geo::addPoint(1, 0, 0, h, 2);
  gmsh::model::geo::addPoint(1, 1, 0, h, 3);
  gmsh::model::geo::addPoint(0, 1, 0, h, 4);
  gmsh::model::geo::addLine(1, 2, 1);
  gmsh::model::geo::addLine(2, 3, 2);
  gmsh::model::geo::addLine(3, 4, 3);
  gmsh::model::geo::addLine(4, 1, 4);
  gmsh::model::geo::addCurveLoop({1, 2, 3, 4}, 1);
  gmsh::model::geo::addPlaneSurface({1}, 1);
  if (options.isolatedPoint) gmsh::model::geo::addPoint(3, 3, 0, h, 5);
  if (options.quads) gmsh::model::geo::mesh::setRecombine(2, 1);
  gmsh::model::geo::synchronize();
  if (options.reverse) gmsh::model::mesh::setReverse(2, 1);
  if (options.boundaryGroups) {
    addNamedGroup(1, {1}, "bottom");
    addNamedGroup(1, {2}, "right");
    addNamedGroup(1, {3}, "top");
    addNamedGroup(1, {4}, "left");
  }
  if (options.secondBottomGroup) addNamedGroup(1, {1}, "ground");
  if (options.domainGroup) addNamedGroup(2, {1}, "domain");
  if (options.secondDomainGroup) addNamedGroup(2, {1}, "whole");
  gmsh::model::mesh::generate(2);
  if (options.order != 1) gmsh::model::mesh::setOrder(options.order);
  const Expected expected = countSimplices(2);
  writeMesh(path, format);
  return expected;
}

// Unit cube (OpenCASCADE box) with physical surfaces xmin ... zmax, "bottom" = zmax's
// opposite z = 0, and physical volume "solid".
Expected writeCube(const std::string& path, const Format& format) {
  GmshApi api;
  gmsh::model::add("cube");
  const int box = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  const double eps = 1e-6;
  auto surfacesIn = [eps](double x0, double y0, double z0, double x1, double y1, double z1) {
    gmsh::vectorpair dimTags;
    gmsh::model::getEntitiesInBoundingBox(x0 - eps, y0 - eps, z0 - eps, x1 + eps, y1 + eps,
                                          z1 + eps, dimTags, 2);
    std::vector<int> tags;
    for (const auto& dimTag : dimTags) tags.push_back(dimTag.second);
    return tags;
  };
  addNamedGroup(2, surfacesIn(0, 0, 0, 1, 1, 0), "bottom");
  addNamedGroup(2, surfacesIn(0, 0, 1, 1, 1, 1), "top");
  addNamedGroup(2, surfacesIn(0, 0, 0, 0, 1, 1), "xmin");
  addNamedGroup(2, surfacesIn(1, 0, 0, 1, 1, 1), "xmax");
  addNamedGroup(2, surfacesIn(0, 0, 0, 1, 0, 1), "ymin");
  addNamedGroup(2, surfacesIn(0, 1, 0, 1, 1, 1), "ymax");
  addNamedGroup(3, {box}, "solid");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
  gmsh::model::mesh::generate(3);
  const Expected expected = countSimplices(4);
  writeMesh(path, format);
  return expected;
}

// A mesh given node by node: nodes (x, y, z) numbered 1.., triangles on surface 1 (physical
// group "domain"), and lines on curve 1 (physical group "edge").
// Node i at coords[3i..3i+2] has tag nodeTags[i] (default: i + 1); the elements name tags.
void writeHandMadeMesh(const std::string& path, const std::vector<double>& coords,
                       const std::vector<std::size_t>& triangles, const std::vector<std::size_t>& lines,
                       std::vector<std::size_t> nodeTags = {}) {
  GmshApi api;
  gmsh::model::add("hand-made");
  gmsh::model::addDiscreteEntity(1, 1);
  gmsh::model::addDiscreteEntity(2, 1);
  if (nodeTags.empty())
    for (std::size_t i = 0; i < coords.size() / 3; ++i) nodeTags.push_back(i + 1);
  gmsh::model::mesh::addNodes(2, 1, nodeTags, coords);
  std::vector<std::size_t> triangleTags(triangles.size() / 3), lineTags(lines.size() / 2);
  for (std::size_t i = 0; i < triangleTags.size(); ++i) triangleTags[i] = i + 1;
  for (std::size_t i = 0; i < lineTags.size(); ++i) lineTags[i] = triangleTags.size() + i + 1;
  gmsh::model::mesh::addElementsByType(1, 2, triangleTags, triangles);
  addNamedGroup(2, {1}, "domain");
  if (!lines.empty()) {
    gmsh::model::mesh::addElementsByType(1, 1, lineTags, lines);
    addNamedGroup(1, {1}, "edge");
  }
  writeMesh(path, {4.1, false});
}

double signedMeasure(const SimplexMesh& mesh, long long cell) {
  std::vector<double> x((mesh.dim + 1) * mesh.dim);
  mesh.cellVertexCoordinates(cell, x.data());
  if (mesh.dim == 2) return 0.5 * ((x[2] - x[0]) * (x[5] - x[1]) - (x[4] - x[0]) * (x[3] - x[1]));
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = x[3 * (r + 1) + c] - x[c];
  return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
          a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
          a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) /
         6.0;
}

double facetMeasure(const SimplexMesh& mesh, long long facet) {
  const long long* v = mesh.facets.data() + mesh.dim * facet;
  auto x = [&mesh](long long vertex, int c) { return mesh.vertices[mesh.dim * vertex + c]; };
  if (mesh.dim == 2) return std::hypot(x(v[1], 0) - x(v[0], 0), x(v[1], 1) - x(v[0], 1));
  double e1[3], e2[3];
  for (int c = 0; c < 3; ++c) {
    e1[c] = x(v[1], c) - x(v[0], c);
    e2[c] = x(v[2], c) - x(v[0], c);
  }
  return 0.5 * std::sqrt(std::pow(e1[1] * e2[2] - e1[2] * e2[1], 2) +
                         std::pow(e1[2] * e2[0] - e1[0] * e2[2], 2) +
                         std::pow(e1[0] * e2[1] - e1[1] * e2[0], 2));
}

// Total measure of the facets with the given tag, and whether all their vertices have
// coordinate `axis` equal to `value`.
double boundaryMeasure(const SimplexMesh& mesh, int tag, int axis = -1, double value = 0,
                       bool* onPlane = nullptr) {
  double total = 0;
  if (onPlane) *onPlane = true;
  for (long long f = 0; f < mesh.numFacets(); ++f) {
    if (mesh.facetTags[f] != tag) continue;
    total += facetMeasure(mesh, f);
    for (int i = 0; i < mesh.dim && onPlane; ++i)
      if (mesh.vertices[mesh.dim * mesh.facets[mesh.dim * f + i] + axis] != value) *onPlane = false;
  }
  return total;
}

void expectWellFormed(const SimplexMesh& mesh) {
  ASSERT_EQ(static_cast<long long>(mesh.vertices.size()), mesh.dim * mesh.numVertices());
  ASSERT_EQ(static_cast<long long>(mesh.cells.size()), (mesh.dim + 1) * mesh.numCells());
  ASSERT_EQ(static_cast<long long>(mesh.facets.size()), mesh.dim * mesh.numFacets());
  ASSERT_EQ(static_cast<long long>(mesh.facetTags.size()), mesh.numFacets());
  std::vector<bool> usedVertex(mesh.numVertices(), false);
  for (long long v : mesh.cells) {
    ASSERT_GE(v, 0);
    ASSERT_LT(v, mesh.numVertices());
    usedVertex[v] = true;
  }
  EXPECT_TRUE(std::all_of(usedVertex.begin(), usedVertex.end(), [](bool used) { return used; }))
      << "a vertex is used by no cell";
  for (long long v : mesh.facets) {
    ASSERT_GE(v, 0);
    ASSERT_LT(v, mesh.numVertices());
  }
  for (long long c = 0; c < mesh.numCells(); ++c)
    ASSERT_GT(signedMeasure(mesh, c), 0) << "cell " << c;
}

double totalMeasure(const SimplexMesh& mesh) {
  double total = 0;
  for (long long c = 0; c < mesh.numCells(); ++c) total += std::abs(signedMeasure(mesh, c));
  return total;
}

// Runs `read` and returns the InputError message; fails the test if nothing or something
// else is thrown.
std::string inputErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  } catch (...) {
    ADD_FAILURE() << "expected InputError, got a non-standard exception";
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return "";
}

// ---------------------------------------------------------------------------------------
// Square and cube in every format.

class GmshFormat : public ::testing::TestWithParam<Format> {};

TEST_P(GmshFormat, UnitSquare) {
  TempDir dir;
  const std::string path = dir.file("square.msh");
  const Expected expected = writeSquare(path, GetParam());
  const SimplexMesh mesh = readGmshMesh(path);

  ASSERT_EQ(mesh.dim, 2);
  expectWellFormed(mesh);
  EXPECT_EQ(mesh.numVertices(), expected.vertices);
  EXPECT_EQ(mesh.numCells(), expected.cells);
  EXPECT_GT(mesh.numCells(), 10);
  EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12);

  ASSERT_EQ(mesh.boundaryTags.size(), 4u);
  const std::map<std::string, std::pair<int, double>> planes = {
      {"bottom", {1, 0.0}}, {"top", {1, 1.0}}, {"left", {0, 0.0}}, {"right", {0, 1.0}}};
  std::vector<int> tags;
  for (const auto& [name, plane] : planes) {
    ASSERT_EQ(mesh.boundaryTags.count(name), 1u) << name;
    const int tag = mesh.boundaryTags.at(name);
    tags.push_back(tag);
    bool onPlane = false;
    EXPECT_NEAR(boundaryMeasure(mesh, tag, plane.first, plane.second, &onPlane), 1.0, 1e-12)
        << name;
    EXPECT_TRUE(onPlane) << name;
  }
  std::sort(tags.begin(), tags.end());
  EXPECT_TRUE(std::adjacent_find(tags.begin(), tags.end()) == tags.end())
      << "boundary tags not distinct";
  for (int tag : mesh.facetTags) EXPECT_TRUE(std::binary_search(tags.begin(), tags.end(), tag));
  EXPECT_EQ(mesh.numFacets(), 16);  // mesh size 0.25: 4 edges per side
}

TEST_P(GmshFormat, UnitCube) {
  TempDir dir;
  const std::string path = dir.file("cube.msh");
  const Expected expected = writeCube(path, GetParam());
  const SimplexMesh mesh = readGmshMesh(path);

  ASSERT_EQ(mesh.dim, 3);
  expectWellFormed(mesh);
  EXPECT_EQ(mesh.numVertices(), expected.vertices);
  EXPECT_EQ(mesh.numCells(), expected.cells);
  EXPECT_GT(mesh.numCells(), 20);
  EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12);

  ASSERT_EQ(mesh.boundaryTags.size(), 6u);
  const std::map<std::string, std::pair<int, double>> planes = {
      {"bottom", {2, 0.0}}, {"top", {2, 1.0}},  {"xmin", {0, 0.0}},
      {"xmax", {0, 1.0}},   {"ymin", {1, 0.0}}, {"ymax", {1, 1.0}}};
  double total = 0;
  for (const auto& [name, plane] : planes) {
    ASSERT_EQ(mesh.boundaryTags.count(name), 1u) << name;
    bool onPlane = false;
    const double area =
        boundaryMeasure(mesh, mesh.boundaryTags.at(name), plane.first, plane.second, &onPlane);
    EXPECT_NEAR(area, 1.0, 1e-12) << name;
    EXPECT_TRUE(onPlane) << name;
    total += area;
  }
  double facetTotal = 0;
  for (long long f = 0; f < mesh.numFacets(); ++f) facetTotal += facetMeasure(mesh, f);
  EXPECT_NEAR(facetTotal, total, 1e-12);  // no facet outside the six groups
}

INSTANTIATE_TEST_SUITE_P(GmshFormats, GmshFormat,
                         ::testing::Values(Format{2.2, false}, Format{4.1, false},
                                           Format{4.1, true}, Format{2.2, true}),
                         [](const ::testing::TestParamInfo<Format>& info) {
                           return formatName(info.param);
                         });

// ---------------------------------------------------------------------------------------
// Selection of cells, vertices and facets.

TEST(GmshMesh, NegativelyOrientedCellsAreFlipped) {
  TempDir dir;
  const std::string path = dir.file("reversed.msh");
  SquareOptions options;
  options.reverse = true;
  const Expected expected = writeSquare(path, {4.1, false}, options);
  ASSERT_EQ(expected.negativeCells, expected.cells) << "the test mesh should be clockwise";
  const SimplexMesh mesh = readGmshMesh(path);
  expectWellFormed(mesh);  // all cells positive
  EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12);
  EXPECT_NEAR(boundaryMeasure(mesh, mesh.tag("bottom")), 1.0, 1e-12);
}

TEST(GmshMesh, WithoutPhysicalGroupsTakesAllTrianglesAndDropsUnusedNodes) {
  TempDir dir;
  const std::string path = dir.file("plain.msh");
  SquareOptions options;
  options.boundaryGroups = false;
  options.domainGroup = false;
  options.isolatedPoint = true;
  for (const Format format : {Format{2.2, false}, Format{4.1, false}}) {
    const Expected expected = writeSquare(path, format, options);
    const SimplexMesh mesh = readGmshMesh(path);
    ASSERT_EQ(mesh.dim, 2) << formatName(format);
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.numVertices(), expected.vertices) << formatName(format);
    EXPECT_EQ(mesh.numCells(), expected.cells) << formatName(format);
    EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12);
    EXPECT_TRUE(mesh.boundaryTags.empty());
    EXPECT_EQ(mesh.numFacets(), 0);
    for (long long v = 0; v < mesh.numVertices(); ++v)
      EXPECT_LE(mesh.vertices[2 * v], 1.0);  // not (3, 3)
  }
}

TEST(GmshMesh, VerticesFollowGmshNodeOrder) {
  TempDir dir;
  const std::string path = dir.file("order.msh");
  writeSquare(path, {4.1, false});
  const SimplexMesh mesh = readGmshMesh(path);
  // The four corners are geometry points 1..4, hence Gmsh nodes 1..4: vertices 0..3.
  const std::vector<double> corners = {0, 0, 1, 0, 1, 1, 0, 1};
  ASSERT_GE(mesh.vertices.size(), corners.size());
  EXPECT_EQ(std::vector<double>(mesh.vertices.begin(), mesh.vertices.begin() + 8), corners);
}

TEST(GmshMesh, CellsInTwoDomainGroupsAreTakenOnce) {
  TempDir dir;
  const std::string path = dir.file("twice.msh");
  SquareOptions options;
  options.secondDomainGroup = true;
  for (const Format format : {Format{2.2, false}, Format{4.1, false}}) {
    const Expected expected = writeSquare(path, format, options);
    const SimplexMesh mesh = readGmshMesh(path);
    EXPECT_EQ(mesh.numCells(), expected.cells) << formatName(format);
    EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12) << formatName(format);
  }
}

TEST(GmshMesh, FacetInTwoGroupsIsListedOncePerGroup) {
  TempDir dir;
  const std::string path = dir.file("ground.msh");
  SquareOptions options;
  options.secondBottomGroup = true;
  for (const Format format : {Format{2.2, false}, Format{4.1, false}}) {
    writeSquare(path, format, options);
    const SimplexMesh mesh = readGmshMesh(path);
    ASSERT_EQ(mesh.boundaryTags.size(), 5u) << formatName(format);
    EXPECT_NE(mesh.tag("ground"), mesh.tag("bottom"));
    EXPECT_NEAR(boundaryMeasure(mesh, mesh.tag("ground")), 1.0, 1e-12) << formatName(format);
    EXPECT_NEAR(boundaryMeasure(mesh, mesh.tag("bottom")), 1.0, 1e-12) << formatName(format);
    EXPECT_EQ(mesh.numFacets(), 20) << formatName(format);
  }
}

TEST(GmshMesh, UnnamedGroupsGetPhysicalTagNames) {
  TempDir dir;
  const std::string path = dir.file("unnamed.msh");
  {
    GmshApi api;
    gmsh::model::add("unnamed");
    gmsh::model::occ::addRectangle(0, 0, 0, 2, 1);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair curves;
    gmsh::model::getEntities(curves, 1);
    std::vector<int> all;
    for (const auto& c : curves) all.push_back(c.second);
    gmsh::model::addPhysicalGroup(1, all, 42);
    gmsh::model::addPhysicalGroup(2, {1}, 7);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
    gmsh::model::mesh::generate(2);
    writeMesh(path, {4.1, false});
  }
  const SimplexMesh mesh = readGmshMesh(path);
  ASSERT_EQ(mesh.boundaryTags.size(), 1u);
  EXPECT_EQ(mesh.tag("physical42"), 42);
  EXPECT_NEAR(boundaryMeasure(mesh, 42), 6.0, 1e-12);
  EXPECT_NEAR(totalMeasure(mesh), 2.0, 1e-12);
}

// ---------------------------------------------------------------------------------------
// Errors.

TEST(GmshMesh, MissingFileIsAnInputErrorNamingThePath) {
  const std::string path = "/nonexistent-signorini-dir/mesh.msh";
  const std::string message = inputErrorOf([&] { readGmshMesh(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  TempDir dir;
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(dir.file("")); }), "");  // a directory
}

TEST(GmshMesh, QuadrangleMeshIsRejected) {
  TempDir dir;
  const std::string path = dir.file("quads.msh");
  SquareOptions options;
  options.quads = true;
  writeSquare(path, {4.1, false}, options);
  const std::string message = inputErrorOf([&] { readGmshMesh(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("Quadrilateral"), std::string::npos) << message;
  EXPECT_NE(message.find("type 3"), std::string::npos) << message;
  EXPECT_NE(message.find("triangles"), std::string::npos) << message;
}

TEST(GmshMesh, SecondOrderMeshIsRejected) {
  TempDir dir;
  const std::string path = dir.file("p2.msh");
  SquareOptions options;
  options.order = 2;
  writeSquare(path, {2.2, false}, options);
  const std::string message = inputErrorOf([&] { readGmshMesh(path); });
  EXPECT_NE(message.find("type 9"), std::string::npos) << message;  // 6-node triangle
}

TEST(GmshMesh, UnreadableFilesAreInputErrorsAndLeaveGmshUsable) {
  TempDir dir;
  const std::string garbage = dir.file("garbage.msh");
  std::ofstream(garbage) << "this is not a mesh\n";
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(garbage); }).find(garbage), std::string::npos);

  const std::string empty = dir.file("empty.msh");
  std::ofstream{empty};
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(empty); }).find("no elements"), std::string::npos);

  const std::string truncated = dir.file("truncated.msh");
  std::ofstream(truncated)
      << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n2 1 0 2\n1\n2\n0 0 0\n";
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(truncated); }), "");

  // A failed read must not leave Gmsh busy or initialised.
  const std::string good = dir.file("good.msh");
  const Expected expected = writeSquare(good, {4.1, false});
  EXPECT_EQ(readGmshMesh(good).numCells(), expected.cells);
}

// A malformed file on which Gmsh 4.8's own reader crashes (found by tests/fuzz, a $PhysicalNames
// entry of dimension 22): an InputError, and this process goes on reading meshes.
TEST(GmshMesh, FileThatCrashesGmshIsAnInputError) {
  static const char bytes[] =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalName"
      "s\n3\n1 1 \"cottom\"\n1 2 \"top\"\n22 3 \" 0 1 0 0 \n1 0 0"
      " 0 1 0 0 1 1 2 1\377\377\377\377 -2 \n2 1 \313\313\313\313\313\313\313\313\313\313\377\377\377\377\377\377\377\377\377"
      "\377\377\377\377\377\377\377\313\313\313\313\313\313\313\313\313\313\313\313\001\000\000\000\000\000\000\004\313\313\313\313\313\313\313\313\3131 1 0 1 \n7 1"
      " 5 10 \n8 3 7 11 \n9 5 2 12 \n10 2 8 7 9 11 \n$EndEl"
      "ement.mshs\n";
  TempDir dir;
  const std::string bad = dir.file("crashes-gmsh.msh");
  std::ofstream(bad, std::ios::binary).write(bytes, sizeof bytes - 1);
  // What Gmsh 4.8 does with this file varies from run to run: it crashes, loops without end
  // or finds no elements. Each is an input error naming the file, within the time limit.
  const std::string message = inputErrorOf([&] { readGmshMesh(bad, 1.0, 5.0); });
  EXPECT_NE(message.find("Gmsh mesh file '" + bad + "'"), std::string::npos) << message;
  const bool known = message.find("Gmsh crashed (Segmentation fault) while reading it") != std::string::npos ||
                        message.find("Gmsh did not finish reading it within 5 s") != std::string::npos ||
                        message.find("no elements at all") != std::string::npos;
  EXPECT_TRUE(known) << message;
  const std::string good = dir.file("good.msh");
  const Expected expected = writeSquare(good, {4.1, false});
  EXPECT_EQ(readGmshMesh(good).numCells(), expected.cells);
}

// The reading process is a copy of this one, with its Gmsh session: a caller's Gmsh set to
// exit the process on an error (General.AbortOnError 4) and to print nothing still gets the
// error as an input error with Gmsh's message.
TEST(GmshMesh, CallerGmshSettingsDoNotChangeHowErrorsAreReported) {
  TempDir dir;
  const std::string empty = dir.file("empty.msh");
  std::ofstream{empty};
  const std::string quads = dir.file("quads.msh");
  SquareOptions options;
  options.quads = true;
  writeSquare(quads, {4.1, false}, options);

  GmshApi api;
  gmsh::option::setNumber("General.AbortOnError", 4);
  gmsh::option::setNumber("General.Terminal", 0);
  const std::string message = inputErrorOf([&] { readGmshMesh(empty); });
  const std::string quadMessage = inputErrorOf([&] { readGmshMesh(quads); });
  gmsh::option::setNumber("General.AbortOnError", 2);  // so that this process's own Gmsh goes on
  EXPECT_NE(message.find("no elements"), std::string::npos) << message;
  EXPECT_NE(quadMessage.find("type 3"), std::string::npos) << quadMessage;
}

TEST(GmshMesh, LineMeshIsRejected) {
  TempDir dir;
  const std::string path = dir.file("lines.msh");
  {
    GmshApi api;
    gmsh::model::add("lines");
    gmsh::model::geo::addPoint(0, 0, 0, 0.5, 1);
    gmsh::model::geo::addPoint(1, 0, 0, 0.5, 2);
    gmsh::model::geo::addLine(1, 2, 1);
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(1);
    writeMesh(path, {4.1, false});
  }
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(path); }).find("dimension 1"), std::string::npos);
}

TEST(GmshMesh, HandMadeMeshIsReadAsGiven) {
  TempDir dir;
  const std::string path = dir.file("hand.msh");
  // Unit square cut along its diagonal 1-3; triangle 2 (1, 4, 3) is clockwise.
  writeHandMadeMesh(path, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {1, 2, 3, 1, 4, 3}, {1, 2, 3, 2});
  const SimplexMesh mesh = readGmshMesh(path);
  EXPECT_EQ(mesh.vertices, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1}));
  EXPECT_EQ(mesh.cells,
            (std::vector<long long>{0, 1, 2, 0, 2, 3}));         // vertices 1, 2 of cell 1 swapped
  EXPECT_EQ(mesh.facets, (std::vector<long long>{0, 1, 2, 1}));  // Gmsh's order
  EXPECT_EQ(mesh.facetTags, (std::vector<int>{mesh.tag("edge"), mesh.tag("edge")}));
  EXPECT_EQ(mesh.boundaryTags.size(), 1u);
}

// Node tags far apart (no table by tag): the vertices still come in increasing tag.
TEST(GmshMesh, SparseNodeTagsAreReadInTagOrder) {
  TempDir dir;
  const std::string path = dir.file("sparse.msh");
  // The square of HandMadeMeshIsReadAsGiven, its corners tagged 7, 100000, 3, 5000000.
  writeHandMadeMesh(path, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {7, 100000, 3, 7, 5000000, 3}, {7, 100000, 3, 100000},
                    {7, 100000, 3, 5000000});
  const SimplexMesh mesh = readGmshMesh(path);
  EXPECT_EQ(mesh.vertices, (std::vector<double>{1, 1, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(mesh.cells, (std::vector<long long>{1, 2, 0, 1, 0, 3}));  // the second one's 1, 2 swapped
  EXPECT_EQ(mesh.facets, (std::vector<long long>{1, 2, 0, 2}));
}

TEST(GmshMesh, TriangleOffThePlaneIsRejected) {
  TempDir dir;
  const std::string path = dir.file("tilted.msh");
  writeHandMadeMesh(path, {0, 0, 0, 1, 0, 0, 0, 1, 0.5}, {1, 2, 3}, {});
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(path); }).find("z = 0"), std::string::npos);
}

TEST(GmshMesh, DegenerateCellIsRejected) {
  TempDir dir;
  const std::string path = dir.file("flat.msh");
  writeHandMadeMesh(path, {0, 0, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0}, {1, 2, 3, 1, 2, 4}, {});
  const std::string message = inputErrorOf([&] { readGmshMesh(path); });
  EXPECT_NE(message.find("degenerate"), std::string::npos) << message;
  EXPECT_NE(message.find("element 2 "), std::string::npos) << message;
}

TEST(GmshMesh, BoundaryElementThatIsNotACellFaceIsRejected) {
  TempDir dir;
  const std::string path = dir.file("diagonal.msh");
  // The line 2-4 crosses the square: it is no edge of triangles 1-2-3 and 1-3-4.
  writeHandMadeMesh(path, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, {1, 2, 3, 1, 3, 4}, {1, 2, 2, 4});
  const std::string message = inputErrorOf([&] { readGmshMesh(path); });
  EXPECT_NE(message.find("\"edge\""), std::string::npos) << message;
  EXPECT_NE(message.find("not a"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------------------
// Gmsh session handling.

TEST(GmshMesh, CallerGmshSessionIsLeftAsItWas) {
  TempDir dir;
  const std::string path = dir.file("square.msh");
  const Expected expected = writeSquare(path, {4.1, false});

  const std::string quadPath = dir.file("quads.msh");
  SquareOptions quads;
  quads.quads = true;
  writeSquare(quadPath, {4.1, false}, quads);

  GmshApi api;
  gmsh::model::add("caller");
  gmsh::model::geo::addPoint(0.5, 0.5, 0);
  gmsh::model::geo::synchronize();
  gmsh::option::setNumber("General.Terminal", 1);

  const SimplexMesh mesh = readGmshMesh(path);
  EXPECT_EQ(mesh.numCells(), expected.cells);
  EXPECT_NEAR(totalMeasure(mesh), 1.0, 1e-12);

  // Still initialised, same current model with the same content, no model left behind.
  std::string current;
  EXPECT_NO_THROW(gmsh::model::getCurrent(current));
  EXPECT_EQ(current, "caller");
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities);
  EXPECT_EQ(entities.size(), 1u);
  std::vector<std::string> models;
  gmsh::model::list(models);
  EXPECT_EQ(std::count(models.begin(), models.end(), "caller"), 1);
  EXPECT_EQ(models.size(), 2u);  // Gmsh's unnamed initial model and "caller"
  double terminal = -1;
  gmsh::option::getNumber("General.Terminal", terminal);
  EXPECT_EQ(terminal, 1);

  // Errors while the caller's Gmsh session is open leave it as it was too.
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(dir.file("missing.msh")); }), "");
  EXPECT_NE(inputErrorOf([&] { readGmshMesh(quadPath); }).find("type 3"), std::string::npos);
  EXPECT_NO_THROW(gmsh::model::getCurrent(current));
  EXPECT_EQ(current, "caller");
  models.clear();
  gmsh::model::list(models);
  EXPECT_EQ(models.size(), 2u);
  gmsh::model::getEntities(entities);
  EXPECT_EQ(entities.size(), 1u);
  gmsh::option::getNumber("General.Terminal", terminal);
  EXPECT_EQ(terminal, 1);
  gmsh::option::setNumber("General.Terminal", 0);
}

// A quarter of the unit disk as a .geo geometry (mesh size 0.1), with physical groups
// "bottom", "arc" and "body".
void writeQuarterDisk(const std::string& path) {
  std::ofstream(path) << "Point(1) = {0, 0, 0, 0.1};\nPoint(2) = {1, 0, 0, 0.1};\nPoint(3) = {0, 1, 0, 0.1};\n"
                         "Line(1) = {1, 2};\nCircle(2) = {2, 1, 3};\nLine(3) = {3, 1};\n"
                         "Curve Loop(1) = {1, 2, 3};\nPlane Surface(1) = {1};\n"
                         "Physical Curve(\"bottom\") = {1};\nPhysical Curve(\"arc\") = {2};\n"
                         "Physical Surface(\"body\") = {1};\n";
}

// A .geo geometry is meshed when read, with linear triangles, its physical groups as the
// boundaries; the size factor scales its mesh sizes.
TEST(GmshGeometry, IsMeshedWhenReadAndRefinedByTheSizeFactor) {
  TempDir dir;
  const std::string path = dir.file("quarter-disk.geo");
  writeQuarterDisk(path);
  const SimplexMesh coarse = readGmshMesh(path, 1.0);
  const SimplexMesh fine = readGmshMesh(path, 0.5);
  EXPECT_EQ(coarse.dim, 2);
  EXPECT_GT(coarse.numCells(), 50);
  EXPECT_GT(fine.numCells(), 3 * coarse.numCells());  // about 4 times as many
  EXPECT_EQ(coarse.boundaryTags.count("bottom"), 1u);
  EXPECT_EQ(coarse.boundaryTags.count("arc"), 1u);
  double area = 0;  // the quarter disk's, pi / 4, to the polygon's chord error
  std::vector<double> x(6);
  for (long long c = 0; c < fine.numCells(); ++c) {
    fine.cellVertexCoordinates(c, x.data());
    area += 0.5 * std::abs((x[2] - x[0]) * (x[5] - x[1]) - (x[4] - x[0]) * (x[3] - x[1]));
  }
  EXPECT_NEAR(area, M_PI / 4, 2e-3);
}

// The geometry facets that a refinement places new vertices on are those on curved entities:
// the quarter disk's arc (its facets' vertices at distance 1 from the centre), not its two
// straight sides, on which edge midpoints already lie.
TEST(GmshGeometry, GeometryFacetsAreThoseOnCurvedEntities) {
  TempDir dir;
  const std::string path = dir.file("quarter-disk.geo");
  writeQuarterDisk(path);
  const SimplexMesh mesh = readGmshMesh(path, 1.0);
  const int arc = mesh.boundaryTags.at("arc");
  const auto arcFacets = std::count(mesh.facetTags.begin(), mesh.facetTags.end(), arc);
  ASSERT_GT(arcFacets, 0);
  EXPECT_EQ(static_cast<long long>(mesh.geometryFacets.size()), 2 * arcFacets);
  EXPECT_EQ(mesh.geometryFacetEntities.size(), static_cast<std::size_t>(arcFacets));
  for (long long vertex : mesh.geometryFacets)
    EXPECT_NEAR(std::hypot(mesh.vertices[2 * vertex], mesh.vertices[2 * vertex + 1]), 1.0, 1e-12);
}

// A .geo that selects Gmsh's HXT 3D mesher is meshed as it asks, with a note that its mesh may
// change from run to run; one meshed by the default Delaunay mesher has no note.
TEST(GmshGeometry, HxtMesherIsNotedAsChangingFromRunToRun) {
  TempDir dir;
  const std::string box = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                          "MeshSize{ PointsOf{ Volume{1}; } } = 0.3;\n";
  std::ofstream(dir.file("delaunay.geo")) << box;
  std::ofstream(dir.file("hxt.geo")) << box << "Mesh.Algorithm3D = 10;\n";
  const SimplexMesh delaunay = readGmshMesh(dir.file("delaunay.geo"));
  const SimplexMesh hxt = readGmshMesh(dir.file("hxt.geo"));
  EXPECT_TRUE(delaunay.notes.empty());
  EXPECT_GT(hxt.numCells(), 0);
  ASSERT_EQ(hxt.notes.size(), 1u);
  EXPECT_NE(hxt.notes[0].find("'" + dir.file("hxt.geo") + "' selects Gmsh's HXT 3D mesher (Mesh.Algorithm3D = 10)"),
            std::string::npos)
      << hxt.notes[0];
  EXPECT_NE(hxt.notes[0].find("different mesh at every run"), std::string::npos) << hxt.notes[0];
}

// A reader that does not answer within the time limit is stopped: an InputError naming the
// file and the limit, and the next file is read as usual. (Meshing this geometry 200 times
// finer than its sizes takes seconds; the limit is a tenth of one.)
TEST(GmshGeometry, ReaderPastItsTimeLimitIsStopped) {
  TempDir dir;
  const std::string path = dir.file("quarter-disk.geo");
  writeQuarterDisk(path);
  const std::string message = inputErrorOf([&] { readGmshMesh(path, 0.005, 0.1); });
  EXPECT_NE(message.find("Gmsh mesh file '" + path + "': Gmsh did not finish reading it within 0.1 s"),
            std::string::npos)
      << message;
  EXPECT_GT(readGmshMesh(path, 1.0, 60.0).numCells(), 50);
}

}  // namespace
}  // namespace signorini
