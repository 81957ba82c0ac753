#include "signorini/problem/ProblemParameters.hpp"

#include <cmath>
#include <sstream>

#include <Teuchos_Array.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "core/ParameterValidation.hpp"
#include "problem/ValidatedProblem.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

using Teuchos::Array;
using Teuchos::ParameterList;
using Teuchos::rcp;

const char* kAxes[3] = {"x", "y", "z"};

std::string formatGap(double g0, const Array<double>& center, double radius, int dim) {
  std::ostringstream e;
  e.precision(17);
  e << g0;
  for (int i = 0; i < dim; ++i) {
    double c = i < center.size() ? center[i] : 0.0;
    e << " + (" << kAxes[i] << " - (" << c << "))^2 / (" << 2.0 * radius << ")";
  }
  return e.str();
}

// One BoundaryField per sublist of `group` (named after its boundary), components read from
// "<prefix>x", "<prefix>y"(, "<prefix>z"); an empty expression leaves the component free.
std::vector<BoundaryField> boundaryFields(const ParameterList& problem, const std::string& group,
                                          const std::string& prefix, int dim) {
  std::vector<BoundaryField> fields;
  const ParameterList& list = problem.sublist(group);
  for (auto it = list.begin(); it != list.end(); ++it) {
    const ParameterList& bc = list.sublist(list.name(it));
    BoundaryField field{list.name(it), {}};
    for (int i = 0; i < dim; ++i) {
      const std::string name = prefix + kAxes[i], text = bc.get<std::string>(name);
      if (text.empty())
        field.components.emplace_back(std::nullopt);
      else
        field.components.emplace_back(Expression(text, "Problem/" + group + "/" + field.boundary + "/" + name));
    }
    fields.push_back(std::move(field));
  }
  return fields;
}

// One Body per sublist of "Bodies" (named after it), what it does not give taken from `problem`.
std::vector<Body> namedBodies(const ParameterList& p, const Body& problem) {
  std::vector<Body> bodies;
  const ParameterList& list = p.sublist("Bodies");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const ParameterList& given = list.sublist(list.name(it));
    Body body = problem;
    body.name = list.name(it);
    body.material.youngsModulus = autoOrNumber(given, "material: young's modulus", problem.material.youngsModulus);
    body.material.poissonRatio = autoOrNumber(given, "material: poisson ratio", problem.material.poissonRatio);
    for (std::size_t i = 0; i < problem.bodyForce.size(); ++i) {
      const std::string name = std::string("body force: ") + kAxes[i], text = given.get<std::string>(name);
      if (!text.empty()) body.bodyForce[i] = Expression(text, "Problem/Bodies/" + body.name + "/" + name);
    }
    bodies.push_back(std::move(body));
  }
  return bodies;
}

void addContactParameters(ParameterList& contact) {
  contact.set("boundary", "", "Name of the contact boundary; empty: no contact");
  contact.set("master boundary", "",
              "The surface of another body that the contact boundary (then the slave side) touches: mortar "
              "constraints between the two bodies, normals and gaps from the slave side (doc/algorithms.md; "
              "2D and 3D, P1 to P3, with mesh: refinements too). The master may cover the slave in part: slave "
              "nodes that no master facet faces have no constraint. Make the slave the finer and the softer "
              "side (a slave much stiffer than its master shows an oscillating pressure). Empty: the rigid obstacle of the gap and "
              "obstacle parameters");
  contact.set("initial overlap: tolerance", 0.1,
              "With a master boundary: how far the bodies may overlap at the start (a slave node's weighted "
              "gap below zero), relative to the size of the slave facets there; a larger overlap is an "
              "input error",
              range(0.0, 1e300));
  contact.set("obstacle: direction", Array<double>(),
              "Vector from the obstacle into the body (normalised), along which the normal force is reported; "
              "empty: the last axis, (0,1) in 2D and (0,0,1) in 3D, and with a master boundary the direction "
              "from the master into the slave body, against the mean outward normal of the contact boundary "
              "(the last axis where that boundary faces every way)");
  contact.set("gap: type", "constant",
              "\"constant\": gap: value; \"paraboloid\": gap: value + |x - center|^2 / (2 radius) "
              "(rigid cylinder or sphere); \"expression\": gap: expression",
              choices({"constant", "paraboloid", "expression"}));
  contact.set("gap: value", 0.0, "Constant gap, or the paraboloid's gap at its center");
  contact.set("gap: center", Array<double>(), "Center of the paraboloid");
  contact.set("gap: radius", 1.0, "Radius of curvature of the paraboloid", range(1e-300, 1e300));
  contact.set("gap: expression", "0", "Gap as an expression of x, y, z");
  contact.set("formulation", "auto",
              "\"nodal\": -n.u <= g at every node of the contact boundary (the paper's constraints); "
              "\"weighted gap\": the integral of psi_j (g + n.u) >= 0 for every node j, psi_j its shape "
              "function (P2 triangles: a transformed basis with positive integrals); the multipliers are "
              "the pressure's coefficients; \"dual mortar\": the same with the dual (biorthogonal) basis "
              "psi_j, so that each constraint holds its own node and the multipliers are the pressure's "
              "nodal values (local means, never negative); \"auto\": nodal for P1, dual mortar for P2 and "
              "P3 (whose nodal multipliers are no pressure: doc/hertz-validation.md) and between two bodies",
              choices({"auto", "nodal", "weighted gap", "dual mortar"}));
}

// Problem/Contact: the parameters of one pair, and the template of a pair's sublist.
void addContactPairs(ParameterList& problem) {
  ParameterList& contact = problem.sublist(
      "Contact", false,
      "Frictionless contact of a boundary with a rigid obstacle or with another body's surface: one pair given "
      "by the parameters here, or several, one sublist per pair (named as the user likes) with the same "
      "parameters; then the parameters here keep their defaults");
  addContactParameters(contact);
  addContactParameters(contact.sublist(kAnyNameSublist));
}

// The mesh: a box, or a Gmsh file and how it is read and refined.
void addMeshParameters(ParameterList& p) {
  p.set("mesh: type", "box", "\"box\": structured simplex mesh of a box; \"gmsh\": a .msh file",
        choices({"box", "gmsh"}));
  p.set("mesh: dimension", 2, "Space dimension of a box mesh", range(2, 3));
  p.set("mesh: cells", Array<int>(1, 10),
        "Cells per direction of a box mesh: one value for all directions, or one per direction");
  p.set("mesh: lengths", Array<double>(3, 1.0), "Edge lengths of the box [0,L0]x[0,L1](x[0,L2])");
  p.set("mesh: file", "",
        "Gmsh .msh file (format 2.2 or 4.1), or a .geo geometry that Gmsh meshes; relative to the XML file. "
        "When name.msh does not exist but name_1.msh .. name_N.msh do (a mesh Gmsh partitioned and wrote "
        "in parts: gmsh -part N -part_split), each of the N ranks reads its own part; N must be the rank "
        "count");
  p.set("mesh: read", "all ranks",
        "How a whole .msh file is read on more than one rank. \"all ranks\": every rank reads a slice of "
        "the file, the ranks put the cells along a Morton curve, PT-Scotch partitions them in parallel and "
        "each rank receives its part, so that no rank holds the whole mesh (for MSH 4.1 ASCII files with "
        "linear simplices, Gmsh's default output, that every rank can open; other files are read by rank "
        "0, and the log says why). \"rank 0\": rank 0 reads it (Gmsh) and partitions it (METIS), then sends each rank its part",
        choices({"rank 0", "all ranks"}));
  p.set("mesh: size factor", 1.0, "A .geo geometry's mesh sizes are multiplied by this (Gmsh's Mesh.MeshSizeFactor)",
        range(1e-6, 1e6));
  p.set("mesh: refinements", 0,
        "A Gmsh mesh is refined uniformly this many times (triangles into 4, tetrahedra into 8) by every "
        "rank on its own part of it, the mesh read (or a .geo geometry meshed at its sizes) being the "
        "coarsest level of a geometric multigrid with one level per refinement. New vertices are edge "
        "midpoints; those on the boundary of a .geo geometry are moved onto it (curved boundaries stay "
        "curved), those of a .msh file stay on the facets of the mesh read",
        range(0, 10));
  p.set("mesh: coarse grids", "delaunay",
        "The geometric multigrid's levels below the coarsest grid of a Gmsh mesh: the P1 grid of a mesh "
        "that is not refined (a .msh file read as is, or a .geo geometry meshed at its sizes), the mesh "
        "read of a refined one. \"delaunay\": each level's vertices are a maximal independent set of the "
        "finer level's, the domain's corners, edges and faces first (the same set on any rank count), "
        "triangulated by CGAL's Delaunay triangulation per body and held by every rank, down to a grid the direct solver takes; \"none\": below the P1 grid "
        "MueLu's algebraic multigrid, below the mesh read of a refined mesh the direct solver up to "
        "Solver/Preconditioner/geometric: direct solve size unknowns, MueLu above",
        choices({"delaunay", "none"}));
}

}  // namespace

ParameterList validProblemParameters() {
  ParameterList p("Problem");
  p.set("name", "unnamed", "Name of the problem, reported in outputs");
  addMeshParameters(p);
  p.set("element: degree", 1, "Degree of the continuous Lagrange elements", range(1, 3));
  p.set("material: young's modulus", 1.0, "Young's modulus E", range(1e-300, 1e300));
  p.set("material: poisson ratio", 0.3, "Poisson ratio nu", range(-0.999, 0.4999));
  p.set("material: plane strain", true, "2D only: plane strain (true) or plane stress (false)");
  for (const char* axis : kAxes)
    p.set(std::string("body force: ") + axis, "0",
          std::string("Body force component ") + axis +
              ", an expression of x, y, z (muparser syntax) evaluated at every quadrature point, a "
              "cell's points at once; a power with an integer exponent from 2 to 16 is computed by "
              "multiplications");
  p.set("load: quadrature degree", -1,
        "Quadrature degree for body forces and tractions; -1: element degree + 4 (exact for "
        "the benchmark family)",
        expert(range(-1, 30)));
  p.set("stiffness: operator", "auto",
        "\"assembled\": Q is a sparse matrix; \"matrix-free\": Q is applied cell by cell. Of degree 2 or 3 "
        "no Q is assembled then (the geometric multigrid starts from the mesh's P1 stiffness); P1 still "
        "assembles Q for the preconditioner. \"auto\": matrix-free of degree 2 or 3 (less memory, as fast end "
        "to end), else assembled",
        choices({"auto", "assembled", "matrix-free"}));
  p.set("stiffness: P1 grid", "mesh",
        "Of degree 2 or 3, the P1 grid the geometric multigrid goes to first, whose stiffness is assembled: "
        "\"mesh\": the mesh's own cells (a box mesh's coarser grids follow); \"refined at nodes\": each cell "
        "split at its nodes into degree^dim cells, every node a vertex, with MueLu below (as many unknowns as "
        "the P_k space, a sparser matrix; slower and larger than \"mesh\" on the meshes of doc/benchmarks.md)",
        choices({"mesh", "refined at nodes"}));

  ParameterList& dirichlet = p.sublist("Dirichlet", false,
                                       "One sublist per clamped boundary, named after it");
  ParameterList& prescribed = dirichlet.sublist(kAnyNameSublist);
  for (const char* axis : kAxes)
    prescribed.set(std::string("displacement: ") + axis, "",
                   "Prescribed displacement component (expression); empty: free");

  ParameterList& traction = p.sublist("Traction", false,
                                      "One sublist per loaded boundary, named after it");
  ParameterList& load = traction.sublist(kAnyNameSublist);
  for (const char* axis : kAxes)
    load.set(std::string("traction: ") + axis, "0", "Surface traction component (expression)");

  ParameterList& bodies = p.sublist(
      "Bodies", false,
      "One sublist per body of the mesh with a material or body force of its own, named after it: a Gmsh "
      "mesh's bodies are its physical groups of the domain's dimension (surfaces in 2D, volumes in 3D; a "
      "cell in several of them belongs to the one with the lowest tag). Cells of no listed body have the "
      "Problem-level material and body force");
  ParameterList& body = bodies.sublist(kAnyNameSublist);
  body.set("material: young's modulus", "auto", "Young's modulus E; \"auto\": the Problem's",
           autoOrRange(1e-300, 1e300));
  body.set("material: poisson ratio", "auto", "Poisson ratio nu; \"auto\": the Problem's", autoOrRange(-0.999, 0.4999));
  for (const char* axis : kAxes)
    body.set(std::string("body force: ") + axis, "",
             std::string("Body force component ") + axis + " (expression); empty: the Problem's");

  addContactPairs(p);
  return p;
}

namespace {

// mesh: cells and mesh: lengths, for def.dim.
void readBoxSize(const ParameterList& p, ProblemDefinition& def) {
  const int dim = def.dim;
  const auto cells = p.get<Array<int>>("mesh: cells");
  if (cells.size() != 1 && cells.size() != dim)
    throw InputError("Problem/mesh: cells: give 1 or " + std::to_string(dim) + " values");
  for (int i = 0; i < 3; ++i) {
    def.cells[i] = cells[cells.size() == 1 ? 0 : std::min<int>(i, cells.size() - 1)];
    if (i < dim && def.cells[i] < 1)
      throw InputError("Problem/mesh: cells: every value must be >= 1");
  }
  const auto lengths = p.get<Array<double>>("mesh: lengths");
  for (int i = 0; i < dim; ++i) {
    if (i >= static_cast<int>(lengths.size()) || !(lengths[i] > 0))
      throw InputError("Problem/mesh: lengths: give " + std::to_string(dim) + " positive values");
    def.lengths[i] = lengths[i];
  }
}

// The contact boundary, the obstacle's direction and gap, and the constraints' formulation of
// the pair `contact` (path: its place in the parameter lists, for messages).
ContactPair readContactPair(const ParameterList& contact, const std::string& path, const ProblemDefinition& def) {
  const int dim = def.dim;
  const std::string boundary = contact.get<std::string>("boundary");
  const std::string master = contact.get<std::string>("master boundary");
  auto direction = contact.get<Array<double>>("obstacle: direction");
  // Between bodies, an empty direction stays zero here: buildProblem sets it from the mesh.
  const bool fromMesh = direction.empty() && !master.empty();
  if (direction.empty() && !fromMesh) {
    direction.assign(dim, 0.0);
    direction[dim - 1] = 1.0;
  }
  std::array<double, 3> unit{{0.0, 0.0, 0.0}};
  if (!fromMesh) {
    if (static_cast<int>(direction.size()) != dim)
      throw InputError(path + "obstacle: direction: give " + std::to_string(dim) + " values");
    double norm = 0;
    for (double c : direction) norm += c * c;
    norm = std::sqrt(norm);
    if (!(norm > 0)) throw InputError(path + "obstacle: direction: must not be zero");
    for (int i = 0; i < dim; ++i) unit[i] = direction[i] / norm;
  }

  const std::string type = contact.get<std::string>("gap: type");
  const double g0 = contact.get<double>("gap: value");
  std::string text;
  if (type == "constant") {
    std::ostringstream e;
    e.precision(17);
    e << g0;
    text = e.str();
  } else if (type == "paraboloid") {
    auto center = contact.get<Array<double>>("gap: center");
    if (static_cast<int>(center.size()) != dim)
      throw InputError(path + "gap: center: give " + std::to_string(dim) + " values");
    text = formatGap(g0, center, contact.get<double>("gap: radius"), dim);
  } else {
    text = contact.get<std::string>("gap: expression");
  }
  const std::string formulation = contact.get<std::string>("formulation");
  const bool dual = formulation == "dual mortar" || (formulation == "auto" && (def.degree > 1 || !master.empty()));
  return ContactPair{contact.name(), boundary, master, unit, Expression(text, path + "gap"),
                     formulation == "weighted gap" ? ContactFormulation::weightedGap
                     : dual                        ? ContactFormulation::dualMortar
                                                   : ContactFormulation::nodal,
                     contact.get<double>("initial overlap: tolerance")};
}

// The pair given in Problem/Contact itself (its boundary named), or one per sublist, in the
// order given; a pair's parameters are read from one place only.
std::vector<ContactPair> readContactPairs(const ParameterList& contact, const ProblemDefinition& def) {
  std::vector<ContactPair> pairs;
  ParameterList defaults;
  addContactParameters(defaults);
  for (auto it = contact.begin(); it != contact.end(); ++it) {
    const std::string& name = contact.name(it);
    if (!contact.isSublist(name)) continue;
    ContactPair pair = readContactPair(contact.sublist(name), "Problem/Contact/" + name + "/", def);
    if (pair.boundary.empty()) throw InputError("Problem/Contact/" + name + "/boundary: name the pair's contact boundary");
    pairs.push_back(std::move(pair));
  }
  if (!pairs.empty()) {
    for (auto it = defaults.begin(); it != defaults.end(); ++it)
      if (!(contact.getEntry(defaults.name(it)).getAny(false) == defaults.entry(it).getAny(false)))
        throw InputError("Problem/Contact/" + defaults.name(it) +
                         ": with one sublist per contact pair, give it in the pairs' sublists");
    for (std::size_t i = 0; i < pairs.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (pairs[i].boundary == pairs[j].boundary)
          throw InputError("Problem/Contact: the pairs \"" + pairs[j].name + "\" and \"" + pairs[i].name +
                           "\" have the same contact boundary \"" + pairs[i].boundary + "\"");
    return pairs;
  }
  if (!contact.get<std::string>("boundary").empty()) {
    pairs.push_back(readContactPair(contact, "Problem/Contact/", def));
    pairs.back().name.clear();
  }
  return pairs;
}

}  // namespace

GmshSource readGmshSource(const ParameterList& user) {
  return detail::gmshSourceOf(validatedParameters(user, validProblemParameters(), "Problem"));
}

ProblemDefinition readProblemDefinition(const ParameterList& user, int meshDim) {
  return detail::definitionOf(validatedParameters(user, validProblemParameters(), "Problem"), meshDim);
}

GmshSource detail::gmshSourceOf(const ParameterList& p) {
  if (p.get<std::string>("mesh: type") != "gmsh") return {};
  const std::string file = p.get<std::string>("mesh: file");
  if (file.empty()) throw InputError("Problem/mesh: file: required when mesh: type is \"gmsh\"");
  return {file, p.get<double>("mesh: size factor"), p.get<int>("mesh: refinements"),
          p.get<std::string>("mesh: read") == "all ranks"};
}

ProblemDefinition detail::definitionOf(const ParameterList& p, int meshDim) {
  ProblemDefinition def;
  def.name = p.get<std::string>("name");
  def.meshType = p.get<std::string>("mesh: type");
  def.dim = meshDim > 0 ? meshDim : p.get<int>("mesh: dimension");
  const int dim = def.dim;

  readBoxSize(p, def);
  def.meshFile = p.get<std::string>("mesh: file");
  def.meshSizeFactor = p.get<double>("mesh: size factor");
  def.meshRefinements = p.get<int>("mesh: refinements");
  def.delaunayCoarseGrids = def.meshType == "gmsh" && p.get<std::string>("mesh: coarse grids") == "delaunay";
  if (def.meshType == "gmsh" && def.meshFile.empty())
    throw InputError("Problem/mesh: file: required when mesh: type is \"gmsh\"");

  def.degree = p.get<int>("element: degree");
  def.body.material.youngsModulus = p.get<double>("material: young's modulus");
  def.body.material.poissonRatio = p.get<double>("material: poisson ratio");
  def.body.material.planeStrain = p.get<bool>("material: plane strain");
  for (int i = 0; i < dim; ++i) {
    std::string name = std::string("body force: ") + kAxes[i];
    def.body.bodyForce.emplace_back(p.get<std::string>(name), "Problem/" + name);
  }
  const int q = p.get<int>("load: quadrature degree");
  def.loadQuadratureDegree = q < 0 ? def.degree + 4 : q;
  const std::string stiffness = p.get<std::string>("stiffness: operator");
  def.matrixFreeStiffness =
      stiffness == "matrix-free" || (stiffness == "auto" && def.degree > 1);
  def.gridRefinedAtNodes = def.degree > 1 && p.get<std::string>("stiffness: P1 grid") == "refined at nodes";

  def.bodies = namedBodies(p, def.body);
  def.dirichlet = boundaryFields(p, "Dirichlet", "displacement: ", dim);
  def.traction = boundaryFields(p, "Traction", "traction: ", dim);

  def.contacts = readContactPairs(p.sublist("Contact"), def);
  return def;
}

}  // namespace signorini
