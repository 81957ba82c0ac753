#pragma once
// What the user asks to solve: mesh source, element degree, material, loads, boundary
// conditions and obstacle, read from the "Problem" parameter list and validated there.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "signorini/ElasticityElement.hpp"
#include "signorini/Expression.hpp"

namespace signorini {

// A vector field on a named boundary; absent components are free (Dirichlet) or zero (traction).
struct BoundaryField {
  std::string boundary;
  std::vector<std::optional<Expression>> components;  // dim entries
};

// How the non-penetration condition -n_o . u <= g is imposed on the contact boundary, one
// constraint per node of Gamma_c in both cases.
//  nodal:        at the node (the paper's constraints);
//  weightedGap:  integral of psi_j (g + n_o . u) >= 0 with the multiplier function psi_j of
//                node j (ContactMultiplierBasis): every constraint has the positive weight
//                integral of psi_j, also at the vertices of P2 triangles, whose nodal
//                constraints carry no force; the multipliers are the pressure's coefficients.
enum class ContactFormulation { nodal, weightedGap };

// A Gmsh mesh to read: its file as given (empty for a box mesh) and the .geo size factor.
struct GmshSource {
  std::string file;
  double sizeFactor = 1.0;
};

struct ProblemDefinition {
  std::string name;
  std::string meshType;  // "box" or "gmsh"
  int dim = 2;
  std::array<long long, 3> cells{{1, 1, 1}};
  std::array<double, 3> lengths{{1.0, 1.0, 1.0}};
  std::string meshFile;
  double meshSizeFactor = 1.0;  // of a .geo geometry
  int degree = 1;
  IsotropicMaterial material;
  std::vector<Expression> bodyForce;  // dim components
  int loadQuadratureDegree = 5;
  std::vector<BoundaryField> dirichlet, traction;
  std::string contactBoundary;
  std::array<double, 3> obstacleDirection{{0.0, 0.0, 0.0}};  // unit, from obstacle into body
  std::optional<Expression> gap;
  ContactFormulation contactFormulation = ContactFormulation::nodal;

  static Teuchos::ParameterList validParameters();
  // `dim` of a Gmsh mesh is only known once it is read: pass it then (0 = from the list).
  static ProblemDefinition fromParameters(const Teuchos::ParameterList& problem, int meshDim = 0);
  // The mesh file alone, checked, before the mesh and so its dimension are known.
  static GmshSource gmshSource(const Teuchos::ParameterList& problem);
};

}  // namespace signorini
