#pragma once
/// \file
/// What the user asks to solve: mesh source, element degree, the bodies (material, body
/// force), boundary conditions and the contact pairs; what the assembly turns into a
/// ContactQP. readProblemDefinition (ProblemParameters.hpp) fills it from the "Problem"
/// parameter list, each part from its own sublist or parameters.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "signorini/assembly/Expression.hpp"
#include "signorini/fe/IsotropicMaterial.hpp"

namespace signorini {

/// A vector field on a named boundary; absent components are free (Dirichlet) or zero (traction).
struct BoundaryField {
  std::string boundary;
  std::vector<std::optional<Expression>> components;  ///< dim entries
};

/// How the non-penetration condition -n_o . u <= g is imposed on the contact boundary, one
/// constraint per node of Gamma_c in every case (between two bodies: the weighted gap of
/// MortarConstraints, a weighted formulation).
///  nodal:        at the node (the paper's constraints);
///  weightedGap:  integral of psi_j (g + n_o . u) >= 0 with the multiplier function psi_j of
///                node j (ContactMultiplierBasis): every constraint has the positive weight
///                integral of psi_j, also at the vertices of P2 triangles, whose nodal
///                constraints carry no force; the multipliers are the pressure's coefficients.
///  dualMortar:   the same with the dual (biorthogonal) basis psi_j: each constraint holds
///                its own node's (transformed) displacement, and the multipliers are the
///                pressure's nodal values, local means of the pressure.
enum class ContactFormulation { nodal, weightedGap, dualMortar };

/// Whether the constraints are integrals against multiplier functions (weighted gaps).
inline bool isWeightedGap(ContactFormulation f) { return f != ContactFormulation::nodal; }

/// An elastic body: its material and the body force on it.
struct Body {
  /// The mesh's body it is (a Gmsh physical group of the domain's dimension); empty for the
  /// Problem-level body, which holds every cell of no named body.
  std::string name;
  IsotropicMaterial material;
  std::vector<Expression> bodyForce;  ///< dim components
};

/// Frictionless contact of a boundary with a rigid obstacle or, given a master boundary, with
/// the surface of another body (mortar constraints, the contact boundary their slave side).
struct ContactPair {
  std::string name;  ///< its sublist of Problem/Contact; empty for the pair given in Problem/Contact itself
  std::string boundary;  ///< the body's contact boundary Gamma_c (a boundary name)
  std::string masterBoundary;  ///< the other body's surface; empty: the rigid obstacle below
  /// Unit, from the obstacle (the master body) into the body; between bodies, zero until
  /// buildProblem() sets it from the mesh, where Problem/Contact does not give it
  std::array<double, 3> obstacleDirection{{0.0, 0.0, 0.0}};
  Expression gap;  ///< g(x), the distance to the obstacle along obstacleDirection
  ContactFormulation formulation = ContactFormulation::nodal;
  /// Between two bodies: the overlap at the start that is refused, relative to the size of
  /// the slave facets where it is
  double initialOverlapTolerance = 0.1;

  /// Where the pair's parameters are, for messages: Problem/Contact or Problem/Contact/<name>
  std::string path() const { return name.empty() ? "Problem/Contact" : "Problem/Contact/" + name; }
};

struct ProblemDefinition {
  std::string name;
  std::string meshType;  ///< "box" or "gmsh"
  int dim = 2;
  std::array<long long, 3> cells{{1, 1, 1}};
  std::array<double, 3> lengths{{1.0, 1.0, 1.0}};
  std::string meshFile;
  double meshSizeFactor = 1.0;  ///< of a .geo geometry
  int meshRefinements = 0;      ///< uniform refinements of a Gmsh mesh
  /// A Gmsh mesh gets coarse grids made from vertices (DelaunayCoarseGrid) below its coarsest
  /// grid: its P1 grid, or the mesh read of a refined one
  bool delaunayCoarseGrids = false;
  int degree = 1;
  Body body;                ///< the Problem-level material and body force
  std::vector<Body> bodies;  ///< Problem/Bodies: bodies of the mesh with their own (unnamed: body)
  int loadQuadratureDegree = 5;
  /// Q applied cell by cell (assembled as well for P1); by default of degree 2 and 3
  bool matrixFreeStiffness = false;
  /// Of degree 2 and 3, the geometric multigrid's P1 grid is the mesh split at the nodes
  /// (MeshVertexGrid::Refinement::atNodes) instead of the mesh's own cells
  bool gridRefinedAtNodes = false;
  std::vector<BoundaryField> dirichlet, traction;
  /// Each pair's constraints are rows of A, pair after pair on every rank (ElasticityAssembler);
  /// empty: no contact
  std::vector<ContactPair> contacts;
};

}  // namespace signorini
