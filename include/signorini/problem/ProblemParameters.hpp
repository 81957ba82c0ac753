#pragma once
/// \file
/// The "Problem" parameter list: its valid parameters and how it is read into a
/// ProblemDefinition. doc/parameters.md lists the parameters.
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "signorini/assembly/ProblemDefinition.hpp"

namespace signorini {

/// Every parameter of the "Problem" list with its default, documentation and validator.
Teuchos::ParameterList validProblemParameters();

/// The definition the list gives, validated (unknown names, wrong types, values out of range:
/// InputError naming the parameter). `meshDim`: the dimension of a Gmsh mesh once it is read
/// (0: "mesh: dimension").
ProblemDefinition readProblemDefinition(const Teuchos::ParameterList& problem, int meshDim = 0);

/// A Gmsh mesh to read: its file as given (empty for a box mesh), the .geo size factor and
/// how many times the mesh read is refined uniformly.
struct GmshSource {
  std::string file;
  double sizeFactor = 1.0;
  int refinements = 0;
  bool readByAllRanks = true;  // a whole .msh file read in slices by all ranks (Problem/mesh: read)
};
/// The mesh file alone, checked, before the mesh and so its dimension are known.
GmshSource readGmshSource(const Teuchos::ParameterList& problem);

}  // namespace signorini
