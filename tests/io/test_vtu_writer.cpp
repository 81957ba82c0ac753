// writeVtu: the pieces and the .pvtu index are read back in C++ (counts, every cell once over
// the ranks, fields, and the VTK Lagrange node order checked against VTK's point numbering),
// and with meshio from Python (point data shapes and an affine field against the coordinates).
#include "assembly/DistributedSpace.hpp"
#include "signorini/io/VtuWriter.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "fe/BoxMesh.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// VTK's point numbering of its Lagrange simplices, restated from vtkHigherOrderTriangle and
// vtkHigherOrderTetra (BarycentricIndex), for orders 1..3. VTK's barycentric index b has
// parametric point (b0, b1[, b2]) / order; the vertex v of the cell has b[vertexMax[v]] = order.
// Points: vertices, then for each edge (v, w) the order - 1 points walking from v to w, then
// (tetra) one point per face for order 3, face f having b[faceMin[f]] = 0, or (triangle) the
// centroid for order 3.
constexpr int triVertexMax[3] = {2, 0, 1};
constexpr int triEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int tetVertexMax[4] = {3, 0, 1, 2};
constexpr int tetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int tetFaceMin[4] = {1, 3, 0, 2};

// Parametric coordinates (3 entries) of VTK point `index` of a Lagrange simplex.
std::array<double, 3> vtkParametricPoint(int dim, int order, int index) {
  const int numVertices = dim + 1;
  const int* vertexMax = dim == 2 ? triVertexMax : tetVertexMax;
  const int numEdges = dim == 2 ? 3 : 6;
  std::array<int, 4> b = {0, 0, 0, 0};
  if (index < numVertices) {
    b[vertexMax[index]] = order;
  } else if (index < numVertices + numEdges * (order - 1)) {
    const int e = (index - numVertices) / (order - 1), step = (index - numVertices) % (order - 1) + 1;
    const int* edge = dim == 2 ? triEdges[e] : tetEdges[e];
    b[vertexMax[edge[0]]] = order - step;
    b[vertexMax[edge[1]]] = step;
  } else if (dim == 2) {
    EXPECT_EQ(order, 3);
    EXPECT_EQ(index, 9);
    b = {1, 1, 1, 0};
  } else {
    EXPECT_EQ(order, 3);
    const int f = index - numVertices - numEdges * (order - 1);
    EXPECT_TRUE(f >= 0 && f < 4) << "index " << index;
    b = {1, 1, 1, 1};
    b[tetFaceMin[f]] = 0;
  }
  std::array<double, 3> xi = {0.0, 0.0, 0.0};
  for (int j = 0; j < dim; ++j) xi[j] = double(b[j]) / order;
  return xi;
}

// ---------------------------------------------------------------------------------------------
// A minimal reader for what writeVtu writes: inline base64 arrays with a UInt64 byte count.
std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<unsigned char> base64Decode(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else continue;  // padding, whitespace
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  return out;
}

std::string attribute(const std::string& tag, const std::string& key) {
  const std::string pattern = " " + key + "=\"";
  std::size_t p = tag.find(pattern);
  if (p == std::string::npos) return {};
  p += pattern.size();
  return tag.substr(p, tag.find('"', p) - p);
}

struct DataArray {
  std::string type;
  int components = 0;
  std::vector<unsigned char> bytes;

  template <class T>
  std::vector<T> as() const {
    std::vector<T> v(bytes.size() / sizeof(T));
    EXPECT_EQ(v.size() * sizeof(T), bytes.size());
    if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
    return v;
  }
};

struct VtuPiece {
  long long numPoints = -1, numCells = -1;
  std::map<std::string, DataArray> arrays;  // by Name

  const DataArray& array(const std::string& name) const {
    static const DataArray missing;
    const auto it = arrays.find(name);
    EXPECT_NE(it, arrays.end()) << "no DataArray named " << name;
    return it == arrays.end() ? missing : it->second;
  }
};

VtuPiece readPiece(const fs::path& path) {
  const std::string text = readText(path);
  VtuPiece piece;
  const std::size_t file = text.find("<VTKFile");
  EXPECT_NE(file, std::string::npos);
  if (file == std::string::npos) return piece;
  const std::string fileTag = text.substr(file, text.find('>', file) - file);
  EXPECT_EQ(attribute(fileTag, "type"), "UnstructuredGrid");
  EXPECT_EQ(attribute(fileTag, "header_type"), "UInt64");
  EXPECT_EQ(attribute(fileTag, "byte_order"), "LittleEndian");  // the test machines are
  const std::size_t p = text.find("<Piece ");
  EXPECT_NE(p, std::string::npos);
  if (p == std::string::npos) return piece;
  const std::string pieceTag = text.substr(p, text.find('>', p) - p);
  piece.numPoints = std::stoll(attribute(pieceTag, "NumberOfPoints"));
  piece.numCells = std::stoll(attribute(pieceTag, "NumberOfCells"));
  for (std::size_t pos = text.find("<DataArray"); pos != std::string::npos; pos = text.find("<DataArray", pos)) {
    const std::size_t tagEnd = text.find('>', pos), close = text.find("</DataArray>", tagEnd);
    EXPECT_NE(close, std::string::npos);
    if (close == std::string::npos) break;
    const std::string tag = text.substr(pos, tagEnd - pos);
    EXPECT_EQ(attribute(tag, "format"), "binary");
    DataArray a;
    a.type = attribute(tag, "type");
    a.components = std::stoi(attribute(tag, "NumberOfComponents"));
    const std::vector<unsigned char> bytes = base64Decode(text.substr(tagEnd + 1, close - tagEnd - 1));
    std::uint64_t numBytes = 0;
    EXPECT_GE(bytes.size(), sizeof(numBytes));
    if (bytes.size() >= sizeof(numBytes)) std::memcpy(&numBytes, bytes.data(), sizeof(numBytes));
    EXPECT_EQ(numBytes + sizeof(numBytes), bytes.size()) << "array " << attribute(tag, "Name");
    if (bytes.size() >= sizeof(numBytes)) a.bytes.assign(bytes.begin() + sizeof(numBytes), bytes.end());
    piece.arrays[attribute(tag, "Name")] = a;
    pos = close;
  }
  return piece;
}

// ---------------------------------------------------------------------------------------------
// The written problem: an affine displacement u(x) = A x + c and scalar t(x), cell fields
// with the rank and the global cell id.
constexpr double A[3][3] = {{1.5, -0.25, 0.75}, {0.5, 2.0, -1.0}, {-0.5, 0.25, 3.0}};
constexpr double c[3] = {0.1, -0.2, 0.3};

double displacement(const double* x, int dim, int i) {
  double u = c[i];
  for (int j = 0; j < dim; ++j) u += A[i][j] * x[j];
  return u;
}

double temperature(const double* x, int dim) { return 1.0 + 2.0 * x[0] - 3.0 * x[1] + (dim == 3 ? 0.5 * x[2] : 0.0); }

struct Case {
  int dim, degree;
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.dim << "D P" << c.degree; }

std::shared_ptr<const SimplexMesh> boxMesh(int dim) {
  // Unequal lengths and counts, so swapped axes or parametric directions show.
  return std::make_shared<const SimplexMesh>(dim == 2 ? makeBoxMesh(2, {4, 3, 1}, {1.0, 0.75, 1.0})
                                                      : makeBoxMesh(3, {2, 2, 3}, {1.0, 0.75, 0.5}));
}

// This process' output root, the same on every rank; each test writes below it and removes
// it when it passed.
fs::path outputRoot(const Comm& comm) {
  long long pid = static_cast<long long>(::getpid());
  Teuchos::broadcast(comm, 0, 1, &pid);
  const char* binaryDir = std::getenv("SIGNORINI_BINARY_DIR");
  const fs::path base = binaryDir ? fs::path(binaryDir) / "tests" : fs::temp_directory_path();
  return base / ("vtu_test_" + std::to_string(pid) + "_np" + std::to_string(comm.getSize()));
}

void removeOutput(const Comm& comm) {
  const fs::path root = outputRoot(comm);  // collective, so before the rank test
  comm.barrier();
  if (comm.getRank() == 0 && !::testing::Test::HasFailure()) {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
}

struct Written {
  std::shared_ptr<const SimplexMesh> mesh;
  std::unique_ptr<DistributedSpace> space;
  fs::path directory;
};

Written writeCase(const Case& k, const std::string& tag) {
  Written w;
  auto comm = Tpetra::getDefaultComm();
  w.mesh = boxMesh(k.dim);
  w.space = std::make_unique<DistributedSpace>(comm, w.mesh, k.degree);
  const DistributedSpace& space = *w.space;
  const int dim = k.dim;

  NodeField u{"displacement", dim, {}}, t{"temperature", 1, {}};
  const std::vector<double>& coords = space.space().nodeCoordinates();
  for (long long n : space.overlapSpaceNodes()) {
    const double* x = &coords[dim * n];
    for (int i = 0; i < dim; ++i) u.values.push_back(displacement(x, dim, i));
    t.values.push_back(temperature(x, dim));
  }
  CellField rank{"rank", 1, {}}, cell{"cell", 1, {}};
  for (long long e = 0; e < space.mesh().numCells(); ++e) {
    rank.values.push_back(comm->getRank());
    cell.values.push_back(static_cast<double>(space.globalCell(e)));
  }
  // A directory two levels below one that does not exist: writeVtu creates both.
  w.directory = outputRoot(*comm) / (tag + "_" + std::to_string(dim) + "d_p" + std::to_string(k.degree)) / "out";
  writeVtu(space, {u, t}, {rank, cell}, w.directory.string());
  return w;
}

class VtuWriterTest : public ::testing::TestWithParam<Case> {};

// ---------------------------------------------------------------------------------------------
// Each rank checks its own piece against the space; rank 0 checks the index and that the
// pieces hold every cell of the mesh exactly once.
TEST_P(VtuWriterTest, PiecesMatchTheSpaceAndVtkNodeOrder) {
  const Case k = GetParam();
  const Written w = writeCase(k, "pieces");
  const DistributedSpace& space = *w.space;
  const Comm& comm = *space.comm();
  const int rank = comm.getRank(), dim = k.dim, npc = space.space().nodesPerCell();
  const SimplexMesh& mesh = *w.mesh;

  const VtuPiece piece = readPiece(w.directory / ("solution_" + std::to_string(rank) + ".vtu"));
  const long long numPoints = static_cast<long long>(space.overlapSpaceNodes().size());
  const long long numCells = space.mesh().numCells();
  EXPECT_GT(numCells, 0);
  EXPECT_EQ(piece.numPoints, numPoints);
  EXPECT_EQ(piece.numCells, numCells);

  // Points: the overlap nodes in order, z = 0 in 2D.
  const DataArray& pointArray = piece.array("Points");
  EXPECT_EQ(pointArray.type, "Float64");
  EXPECT_EQ(pointArray.components, 3);
  const std::vector<double> points = pointArray.as<double>();
  ASSERT_EQ(static_cast<long long>(points.size()), 3 * numPoints);
  const std::vector<double>& coords = space.space().nodeCoordinates();
  for (long long p = 0; p < numPoints; ++p)
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(points[3 * p + j], j < dim ? coords[dim * space.overlapSpaceNodes()[p] + j] : 0.0);

  // Point data: displacement padded to 3 components, values tied to the written coordinates.
  const DataArray& uArray = piece.array("displacement");
  EXPECT_EQ(uArray.components, 3);
  const std::vector<double> u = uArray.as<double>();
  ASSERT_EQ(static_cast<long long>(u.size()), 3 * numPoints);
  const DataArray& tArray = piece.array("temperature");
  EXPECT_EQ(tArray.components, 1);
  const std::vector<double> t = tArray.as<double>();
  ASSERT_EQ(static_cast<long long>(t.size()), numPoints);
  for (long long p = 0; p < numPoints; ++p) {
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(u[3 * p + i], i < dim ? displacement(&points[3 * p], dim, i) : 0.0, 1e-13);
    EXPECT_NEAR(t[p], temperature(&points[3 * p], dim), 1e-13);
  }

  // Cells: types, offsets, cell data.
  const std::vector<std::int64_t> connectivity = piece.array("connectivity").as<std::int64_t>();
  const std::vector<std::int64_t> offsets = piece.array("offsets").as<std::int64_t>();
  const std::vector<std::uint8_t> types = piece.array("types").as<std::uint8_t>();
  EXPECT_EQ(piece.array("connectivity").type, "Int64");
  EXPECT_EQ(piece.array("offsets").type, "Int64");
  EXPECT_EQ(piece.array("types").type, "UInt8");
  ASSERT_EQ(static_cast<long long>(connectivity.size()), npc * numCells);
  ASSERT_EQ(static_cast<long long>(offsets.size()), numCells);
  ASSERT_EQ(static_cast<long long>(types.size()), numCells);
  const int expectedType = k.degree == 1 ? (dim == 2 ? 5 : 10) : (dim == 2 ? 69 : 71);
  const std::vector<double> cellRank = piece.array("rank").as<double>();
  const std::vector<double> cellId = piece.array("cell").as<double>();
  ASSERT_EQ(static_cast<long long>(cellRank.size()), numCells);
  ASSERT_EQ(static_cast<long long>(cellId.size()), numCells);
  for (long long e = 0; e < numCells; ++e) {
    EXPECT_EQ(offsets[e], npc * (e + 1));
    EXPECT_EQ(int(types[e]), expectedType);
    EXPECT_EQ(cellRank[e], rank);
    EXPECT_EQ(cellId[e], static_cast<double>(space.globalCell(e)));
  }

  // Geometry of each written cell: its first dim + 1 points are the mesh cell's vertices in
  // order, and VTK point i lies at VTK's parametric point i mapped through those vertices.
  double worst = 0.0;
  for (long long e = 0; e < numCells; ++e) {
    const std::int64_t* ids = &connectivity[npc * e];
    for (int i = 0; i < npc; ++i) ASSERT_TRUE(ids[i] >= 0 && ids[i] < numPoints);
    const long long meshCell = space.globalCell(e);  // in the global mesh
    for (int v = 0; v <= dim; ++v)
      for (int j = 0; j < dim; ++j)
        EXPECT_EQ(points[3 * ids[v] + j], mesh.vertices[dim * mesh.cells[(dim + 1) * meshCell + v] + j]);
    for (int i = 0; i < npc; ++i) {
      const std::array<double, 3> xi = vtkParametricPoint(dim, k.degree, i);
      for (int j = 0; j < 3; ++j) {
        double x = points[3 * ids[0] + j];
        for (int v = 1; v <= dim; ++v) x += xi[v - 1] * (points[3 * ids[v] + j] - points[3 * ids[0] + j]);
        worst = std::max(worst, std::abs(x - points[3 * ids[i] + j]));
      }
    }
    // The nodes of a cell are distinct points.
    for (int i = 0; i < npc; ++i)
      for (int j = 0; j < i; ++j) EXPECT_NE(ids[i], ids[j]);
  }
  EXPECT_LT(worst, 1e-13) << "a written node is not where VTK's numbering puts it";

  // No temporary file is left.
  for (const auto& entry : fs::directory_iterator(w.directory))
    EXPECT_EQ(entry.path().extension(), entry.path().filename() == "solution.pvtu" ? ".pvtu" : ".vtu")
        << entry.path();

  comm.barrier();
  if (rank == 0) {
    // The index lists every piece once and declares the fields.
    const std::string index = readText(w.directory / "solution.pvtu");
    EXPECT_NE(index.find("type=\"PUnstructuredGrid\""), std::string::npos);
    EXPECT_NE(index.find("header_type=\"UInt64\""), std::string::npos);
    std::size_t pieces = 0;
    for (std::size_t p = index.find("<Piece "); p != std::string::npos; p = index.find("<Piece ", p + 1)) ++pieces;
    EXPECT_EQ(pieces, static_cast<std::size_t>(comm.getSize()));
    for (int r = 0; r < comm.getSize(); ++r)
      EXPECT_NE(index.find("<Piece Source=\"solution_" + std::to_string(r) + ".vtu\"/>"), std::string::npos) << r;
    EXPECT_NE(index.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
    EXPECT_NE(index.find("Name=\"temperature\" NumberOfComponents=\"1\""), std::string::npos);
    EXPECT_NE(index.find("Name=\"rank\" NumberOfComponents=\"1\""), std::string::npos);
    EXPECT_NE(index.find("Name=\"cell\" NumberOfComponents=\"1\""), std::string::npos);

    // Every mesh cell is in exactly one piece.
    std::vector<int> seen(mesh.numCells(), 0);
    long long total = 0;
    for (int r = 0; r < comm.getSize(); ++r) {
      const VtuPiece other = readPiece(w.directory / ("solution_" + std::to_string(r) + ".vtu"));
      total += other.numCells;
      for (double id : other.array("cell").as<double>()) {
        ASSERT_TRUE(id >= 0 && id < mesh.numCells());
        ++seen[static_cast<std::size_t>(id)];
      }
    }
    EXPECT_EQ(total, mesh.numCells());
    for (long long e = 0; e < mesh.numCells(); ++e) EXPECT_EQ(seen[e], 1) << "cell " << e;
  }
  removeOutput(comm);
}

INSTANTIATE_TEST_SUITE_P(AllCases, VtuWriterTest,
                         ::testing::Values(Case{2, 1}, Case{2, 2}, Case{2, 3}, Case{3, 1}, Case{3, 2}, Case{3, 3}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::to_string(info.param.dim) + "D_P" + std::to_string(info.param.degree);
                         });

// ---------------------------------------------------------------------------------------------
// meshio (Debian's python3-meshio) reads every piece of every case; the script checks the point
// data shapes, the affine displacement against the point coordinates, the cell type and cell
// data, and the position of every node of every cell from the cell's vertices (VTK's Lagrange
// numbering: edges 01, 12, 20 (, 03, 13, 23) walked from their first vertex, then the centroids
// of faces 013, 123, 023, 012, or the triangle's centroid). Exit code 77: no meshio.
const char* const meshioScript = R"PY(
import os, sys
try:
    import numpy as np
    import meshio
except ImportError:
    sys.exit(77)

def check(directory, nranks, dim, degree, ncells):
    A = np.array([[1.5, -0.25, 0.75], [0.5, 2.0, -1.0], [-0.5, 0.25, 3.0]])[:dim, :dim]
    c = np.array([0.1, -0.2, 0.3])[:dim]
    if dim == 2:
        edges, faces = [(0, 1), (1, 2), (2, 0)], [(0, 1, 2)] if degree == 3 else []
        name = "triangle" if degree == 1 else "VTK_LAGRANGE_TRIANGLE"
    else:
        edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
        faces = [(0, 1, 3), (1, 2, 3), (0, 2, 3), (0, 1, 2)] if degree == 3 else []
        name = "tetra" if degree == 1 else "VTK_LAGRANGE_TETRAHEDRON"
    # Barycentric weights (over the dim + 1 vertices) of VTK's points, in VTK order.
    weights = [np.eye(dim + 1)[v] for v in range(dim + 1)]
    for v, w in edges:
        for step in range(1, degree):
            b = np.zeros(dim + 1); b[v] = (degree - step) / degree; b[w] = step / degree
            weights.append(b)
    for f in faces:
        b = np.zeros(dim + 1); b[list(f)] = 1.0 / 3.0
        weights.append(b)
    weights = np.array(weights)

    total = 0
    for r in range(nranks):
        path = os.path.join(directory, "solution_%d.vtu" % r)
        m = meshio.read(path)
        n = len(m.points)
        assert m.points.shape == (n, 3), (path, m.points.shape)
        x = m.points[:, :dim]
        if dim == 2:
            assert np.all(m.points[:, 2] == 0.0), path
        u = np.asarray(m.point_data["displacement"])
        assert u.shape == (n, 3), (path, u.shape)
        expected = np.zeros((n, 3)); expected[:, :dim] = x @ A.T + c
        assert np.allclose(u, expected, rtol=0, atol=1e-12), (path, np.abs(u - expected).max())
        t = np.asarray(m.point_data["temperature"])
        assert t.size == n and t.shape[0] == n, (path, t.shape)
        assert len(m.cells) == 1, (path, [b.type for b in m.cells])
        block = m.cells[0]
        assert block.type == name, (path, block.type, name)
        assert block.data.shape[1] == len(weights), (path, block.data.shape)
        # Every node of every cell where VTK's numbering puts it, from the cell's vertices.
        cellpoints = m.points[block.data]                     # (cells, nodes, 3)
        predicted = np.einsum("kv,cvj->ckj", weights, cellpoints[:, :dim + 1, :])
        err = np.abs(predicted - cellpoints).max()
        assert err < 1e-12, (path, err)
        ranks = np.asarray(m.cell_data["rank"][0]).reshape(-1)
        assert ranks.size == len(block.data) and np.all(ranks == r), path
        total += len(block.data)
    assert total == ncells, (directory, total, ncells)
    print("meshio: %dD P%d, %d pieces, %d cells checked" % (dim, degree, nranks, total))

nranks = int(sys.argv[1])
for case in sys.argv[2:]:
    directory, dim, degree, ncells = case.split(",")
    check(directory, nranks, int(dim), int(degree), int(ncells))
)PY";

TEST(VtuWriter, MeshioReadsEveryCase) {
  auto comm = Tpetra::getDefaultComm();
  std::string arguments;
  for (const Case k : {Case{2, 1}, Case{2, 2}, Case{2, 3}, Case{3, 1}, Case{3, 2}, Case{3, 3}}) {
    const Written w = writeCase(k, "meshio");
    arguments += " " + w.directory.string() + "," + std::to_string(k.dim) + "," + std::to_string(k.degree) + "," +
                 std::to_string(w.mesh->numCells());
  }
  const fs::path script = outputRoot(*comm) / "check_meshio.py";  // collective
  int status = 0;
  if (comm->getRank() == 0) {
    std::ofstream(script) << meshioScript;
    // Debian's meshio is in /usr/bin's python3, which a pyenv python3 may shadow on the PATH.
    for (const char* python : {"/usr/bin/python3", "python3"}) {
      const std::string command =
          std::string(python) + " " + script.string() + " " + std::to_string(comm->getSize()) + arguments;
      const int code = std::system(command.c_str());
      status = WIFEXITED(code) ? WEXITSTATUS(code) : 1;
      if (status != 77 && status != 127) {
        EXPECT_EQ(status, 0) << command;
        break;
      }
    }
  }
  Teuchos::broadcast(*comm, 0, 1, &status);
  removeOutput(*comm);
  if (status == 77 || status == 127) GTEST_SKIP() << "no python3 with meshio (Debian package python3-meshio)";
}

// ---------------------------------------------------------------------------------------------
// Errors are collective: every rank throws, even if only rank 0 had a problem.
TEST(VtuWriter, WrongFieldSizeOnOneRankThrowsOnEveryRank) {
  auto comm = Tpetra::getDefaultComm();
  const DistributedSpace space(comm, boxMesh(2), 1);
  NodeField u{"u", 2, std::vector<double>(2 * space.overlapSpaceNodes().size(), 0.0)};
  if (comm->getRank() == 0) u.values.pop_back();
  const fs::path dir = outputRoot(*comm) / "bad_size" / "out";
  EXPECT_THROW(writeVtu(space, {u}, {}, dir.string()), Error);
  comm->barrier();
  EXPECT_FALSE(fs::exists(dir));  // nothing was written
  removeOutput(*comm);
}

TEST(VtuWriter, UncreatableDirectoryThrowsOnEveryRank) {
  auto comm = Tpetra::getDefaultComm();
  const DistributedSpace space(comm, boxMesh(2), 1);
  const fs::path top = outputRoot(*comm) / "blocked";
  if (comm->getRank() == 0) {
    fs::create_directories(top);
    std::ofstream(top / "file") << "not a directory\n";
  }
  comm->barrier();
  const fs::path dir = top / "file" / "out";
  try {
    writeVtu(space, {}, {}, dir.string());
    ADD_FAILURE() << "no exception";
  } catch (const OutputError& e) {  // an error of the environment, with the system's reason
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
  }
  removeOutput(*comm);
}

}  // namespace
}  // namespace signorini
