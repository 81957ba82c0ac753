#include "signorini/io/VtuWriter.hpp"


#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/DistributedSpace.hpp"
#include "io/AtomicFile.hpp"
#include "io/XmlEscape.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

// VTK cell types (vtkCellType.h).
constexpr std::uint8_t kVtkTriangle = 5;
constexpr std::uint8_t kVtkTetra = 10;
constexpr std::uint8_t kVtkLagrangeTriangle = 69;
constexpr std::uint8_t kVtkLagrangeTetrahedron = 71;

// VTK's edges of the triangle and the tetrahedron (vtkHigherOrderTriangle, vtkHigherOrderTetra):
// the nodes inside edge (v, w) are listed walking from v to w.
constexpr int kTriangleEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kTetraEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
// VTK's tetrahedron faces in order, as vertex sets (vtkHigherOrderTetra's face f holds the
// barycentric coordinate FaceMinCoord[f] at 0: faces 013, 123, 023, 012).
constexpr int kTetraFaces[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 2}};

// Position in VTK's Lagrange point order of the lattice node a (a_i weighs vertex i) of a
// degree k simplex: vertices, then edge nodes edge by edge, then face nodes face by face, then
// interior nodes. Up to degree 3 each face (triangle interior) holds at most one node, so no
// order inside a face is needed.
int vtkPosition(const std::array<int, 4>& a, int dim, int k) {
  int support[4], size = 0;
  for (int i = 0; i <= dim; ++i)
    if (a[i] > 0) support[size++] = i;
  const int numVertices = dim + 1, numEdges = dim == 2 ? 3 : 6;
  if (size == 1) return support[0];
  if (size == 2) {
    for (int e = 0; e < numEdges; ++e) {
      const int* edge = dim == 2 ? kTriangleEdges[e] : kTetraEdges[e];
      if ((edge[0] == support[0] && edge[1] == support[1]) || (edge[0] == support[1] && edge[1] == support[0]))
        return numVertices + e * (k - 1) + (a[edge[1]] - 1);  // a[edge[1]] counts steps from edge[0]
    }
  }
  if (size == 3 && dim == 2) return numVertices + numEdges * (k - 1);  // the one interior node (k = 3)
  if (size == 3 && dim == 3) {
    for (int f = 0; f < 4; ++f)
      if (support[0] == kTetraFaces[f][0] && support[1] == kTetraFaces[f][1] && support[2] == kTetraFaces[f][2])
        return numVertices + numEdges * (k - 1) + f;  // one node per face (k = 3)
  }
  throw Error("VTK output: no VTK node position for this lattice node of degree " + std::to_string(k));
}

// For each position in VTK's order, the basis' local node found there.
std::vector<int> vtkNodeOrder(const LagrangeBasis& basis) {
  if (basis.degree() > 3) throw Error("VTK output: degrees above 3 are not supported");
  const int n = basis.size();
  std::vector<int> order(n, -1);
  for (int local = 0; local < n; ++local) {
    const int position = vtkPosition(basis.latticeIndices()[local], basis.dim(), basis.degree());
    if (position < 0 || position >= n || order[position] != -1)
      throw Error("VTK output: inconsistent VTK node order");  // a bug, not an input problem
    order[position] = local;
  }
  return order;
}

bool littleEndian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

void appendBase64(std::string& out, const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::size_t n = bytes.size();
  std::size_t i = 0;
  for (; i + 2 < n; i += 3) {
    const unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i + 1 == n) {
    const unsigned v = bytes[i] << 16;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == n) {
    const unsigned v = (bytes[i] << 16) | (bytes[i + 1] << 8);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += '=';
  }
}

// A DataArray in VTK's inline "binary" format: base64 of a UInt64 byte count followed by the
// raw values (native byte order, declared in the VTKFile element).
template <class T>
void appendDataArray(std::string& out, const char* type, const std::string& name, int components,
                     const std::vector<T>& data) {
  out += "        <DataArray type=\"";
  out += type;
  out += '"';
  if (!name.empty()) out += " Name=\"" + detail::xmlEscaped(name) + '"';
  out += " NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">\n          ";
  const std::uint64_t numBytes = data.size() * sizeof(T);
  std::vector<unsigned char> bytes(sizeof(numBytes) + numBytes);
  std::memcpy(bytes.data(), &numBytes, sizeof(numBytes));
  if (numBytes > 0) std::memcpy(bytes.data() + sizeof(numBytes), data.data(), numBytes);
  appendBase64(out, bytes);
  out += "\n        </DataArray>\n";
}

// Values of a field with `components` per entity, padded to 3 components if it has 2.
int outputComponents(int components) { return components == 2 ? 3 : components; }

std::vector<double> padded(const std::vector<double>& values, int components) {
  if (components != 2) return values;
  std::vector<double> out;
  out.reserve(values.size() / 2 * 3);
  for (std::size_t i = 0; i + 1 < values.size(); i += 2) {
    out.push_back(values[i]);
    out.push_back(values[i + 1]);
    out.push_back(0.0);
  }
  return out;
}

std::string fileHeader(const char* type) {
  return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"") + type +
         "\" version=\"1.0\" byte_order=\"" + (littleEndian() ? "LittleEndian" : "BigEndian") +
         "\" header_type=\"UInt64\">\n";
}

std::string pieceText(const DistributedSpace& space, const std::vector<NodeField>& nodeFields,
                      const std::vector<CellField>& cellFields) {
  const LagrangeSpace& lagrange = space.space();
  const int dim = space.dim(), npc = lagrange.nodesPerCell();
  const std::vector<long long>& nodes = space.overlapSpaceNodes();
  const long long numCells = space.mesh().numCells();

  std::vector<double> points(3 * nodes.size(), 0.0);
  std::unordered_map<long long, long long> pointOf;
  pointOf.reserve(nodes.size());
  const std::vector<double>& coords = lagrange.nodeCoordinates();
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    for (int j = 0; j < dim; ++j) points[3 * p + j] = coords[dim * nodes[p] + j];
    pointOf[nodes[p]] = static_cast<long long>(p);
  }

  const std::vector<int> order = vtkNodeOrder(lagrange.basis());
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(numCells * npc);
  offsets.reserve(numCells);
  for (long long cell = 0; cell < numCells; ++cell) {
    const long long* cellNodes = lagrange.cellNodes(cell);
    for (int position = 0; position < npc; ++position) {
      const auto it = pointOf.find(cellNodes[order[position]]);
      if (it == pointOf.end()) throw Error("VTK output: a node of a local cell is not an overlap node");
      connectivity.push_back(it->second);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  std::uint8_t type;
  if (lagrange.degree() == 1)
    type = dim == 2 ? kVtkTriangle : kVtkTetra;
  else
    type = dim == 2 ? kVtkLagrangeTriangle : kVtkLagrangeTetrahedron;
  const std::vector<std::uint8_t> types(numCells, type);

  std::string out = fileHeader("UnstructuredGrid");
  out += "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" + std::to_string(nodes.size()) +
         "\" NumberOfCells=\"" + std::to_string(numCells) + "\">\n";
  out += "      <PointData>\n";
  for (const NodeField& f : nodeFields)
    appendDataArray(out, "Float64", f.name, outputComponents(f.components), padded(f.values, f.components));
  out += "      </PointData>\n      <CellData>\n";
  for (const CellField& f : cellFields)
    appendDataArray(out, "Float64", f.name, outputComponents(f.components), padded(f.values, f.components));
  out += "      </CellData>\n      <Points>\n";
  appendDataArray(out, "Float64", "Points", 3, points);
  out += "      </Points>\n      <Cells>\n";
  appendDataArray(out, "Int64", "connectivity", 1, connectivity);
  appendDataArray(out, "Int64", "offsets", 1, offsets);
  appendDataArray(out, "UInt8", "types", 1, types);
  out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string indexText(int numRanks, const std::vector<NodeField>& nodeFields,
                      const std::vector<CellField>& cellFields, const std::string& basename) {
  std::string out = fileHeader("PUnstructuredGrid");
  out += "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
  for (const NodeField& f : nodeFields)
    out += "      <PDataArray type=\"Float64\" Name=\"" + detail::xmlEscaped(f.name) + "\" NumberOfComponents=\"" +
           std::to_string(outputComponents(f.components)) + "\"/>\n";
  out += "    </PPointData>\n    <PCellData>\n";
  for (const CellField& f : cellFields)
    out += "      <PDataArray type=\"Float64\" Name=\"" + detail::xmlEscaped(f.name) + "\" NumberOfComponents=\"" +
           std::to_string(outputComponents(f.components)) + "\"/>\n";
  out += "    </PCellData>\n    <PPoints>\n";
  out += "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n";
  out += "    </PPoints>\n";
  for (int r = 0; r < numRanks; ++r)
    out += "    <Piece Source=\"" + detail::xmlEscaped(basename + "_" + std::to_string(r) + ".vtu") + "\"/>\n";
  out += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return out;
}

// Collective: if any rank reports an error, every rank throws the lowest failing rank's
// message, an OutputError if it is one of writing the files.
template <class Failure = Error>
void throwIfAnyFailed(const Comm& comm, const std::string& localError) {
  const int size = comm.getSize();
  const int local = localError.empty() ? size : comm.getRank();
  int failing = size;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local, &failing);
  if (failing == size) return;
  int length = comm.getRank() == failing ? static_cast<int>(localError.size()) : 0;
  Teuchos::broadcast(comm, failing, 1, &length);
  std::string message = comm.getRank() == failing ? localError : std::string(length, ' ');
  if (length > 0) Teuchos::broadcast(comm, failing, length, &message[0]);
  throw Failure("VTK output: " + message);
}

template <class Field>
std::string checkField(const Field& f, std::size_t entities, const char* what) {
  if (f.name.empty()) return std::string(what) + " field without a name";
  if (f.components < 1) return std::string(what) + " field '" + f.name + "' has no components";
  if (f.values.size() != entities * static_cast<std::size_t>(f.components))
    return std::string(what) + " field '" + f.name + "' has " + std::to_string(f.values.size()) +
           " values, expected " + std::to_string(entities) + " x " + std::to_string(f.components);
  return {};
}

}  // namespace

void writeVtu(const FiniteElementSpace& feSpace, const std::vector<NodeField>& nodeFields,
              const std::vector<CellField>& cellFields, const std::string& directory,
              const std::string& basename) {
  const DistributedSpace& space = distributedSpace(feSpace);
  const Comm& comm = *space.comm();
  const int rank = comm.getRank();

  std::string error;
  for (const NodeField& f : nodeFields)
    if (error.empty()) error = checkField(f, space.overlapSpaceNodes().size(), "node");
  for (const CellField& f : cellFields)
    if (error.empty()) error = checkField(f, static_cast<std::size_t>(space.mesh().numCells()), "cell");
  throwIfAnyFailed(comm, error);

  const fs::path dir(directory);
  if (rank == 0) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) error = "cannot create directory '" + directory + "'" + (ec ? ": " + ec.message() : "");
  }
  throwIfAnyFailed<OutputError>(comm, error);  // also the barrier: the directory exists from here on

  std::string text;
  try {
    text = pieceText(space, nodeFields, cellFields);
  } catch (const std::exception& e) {  // Error or bad_alloc: let every rank know
    error = e.what();
  }
  throwIfAnyFailed(comm, error);
  error = detail::tryWriteFileAtomically((dir / (basename + "_" + std::to_string(rank) + ".vtu")).string(), text);
  throwIfAnyFailed<OutputError>(comm, error);

  if (rank == 0)
    error = detail::tryWriteFileAtomically((dir / (basename + ".pvtu")).string(),
                                           indexText(comm.getSize(), nodeFields, cellFields, basename));
  throwIfAnyFailed<OutputError>(comm, error);
}

}  // namespace signorini
