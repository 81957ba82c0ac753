#pragma once
// The readers of a "Problem" list already validated against validProblemParameters():
// buildProblem validates the user's list once and reads it with these (the mesh source
// first, the rest once a Gmsh mesh's dimension is known).
#include <Teuchos_ParameterList.hpp>

#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/problem/ProblemParameters.hpp"

namespace signorini::detail {

GmshSource gmshSourceOf(const Teuchos::ParameterList& validated);
// meshDim: the dimension of a Gmsh mesh once it is read (0: "mesh: dimension").
ProblemDefinition definitionOf(const Teuchos::ParameterList& validated, int meshDim);

}  // namespace signorini::detail
