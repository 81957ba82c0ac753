#pragma once
// Helpers shared by the tests: the shipped XML problems, box problems built in code, and
// linear solves for checks that need a discrete solution.
#include <string>
#include <utility>

#include <Teuchos_ParameterList.hpp>

#include "assembly/DistributedSpace.hpp"
#include "fe/SimplexMesh.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/MultigridInput.hpp"

namespace signorini::testing {

std::string sourceDir();

// The "Problem" sublist of xml/<relativePath>.
Teuchos::ParameterList shippedProblem(const std::string& relativePath);
// The same with the stiffness assembled, for tests that read Q's matrix (P2/P3 box meshes
// are matrix-free by default).
Teuchos::ParameterList assembledShippedProblem(const std::string& relativePath);

// A box problem: no load, no boundary condition, no contact, the stiffness assembled; the
// caller adds what it needs.
Teuchos::ParameterList boxProblem(int dim, int cells, int degree);

// A P1 box clamped on its top face, with contact on its bottom one and no load.
Teuchos::ParameterList contactBoxProblem(int dim, int cells);

// A Gmsh mesh `file` with boundary groups "top" and "bottom": clamped on top, pressed onto
// the rigid plane under it by a varying weight, refined `refinements` times.
Teuchos::ParameterList gmshPressedProblem(int dim, const std::string& file, int degree, int refinements);

// Into the current Gmsh model (Gmsh initialised by the caller): the unit square (2D) or cube
// (3D) with groups "bottom" (y or z = 0), "top" and "body", meshed at size h.
void meshUnitBox(int dim, double h);

// The Gmsh tags of the bottom (y or z = 0) and top (y or z = 1) sides of the unit square or
// cube `body` of the current model.
std::pair<int, int> unitBoxBottomAndTop(int dim, int body);

// The unit box mesh of n cells per side with its interior vertices moved by up to a fifth of
// the spacing, deterministically: a mesh whose vertices are not on a lattice.
SimplexMesh distortedBoxMesh(int dim, long long n);

// Solves Q x = b by CG + MueLu to a relative residual of tol; returns the iterations.
int solveLinear(const ContactQP& qp, const MultigridInput& multigrid, Vector& x, double tol);

// Assembles on a one-rank communicator (every rank its own copy): the reference for
// rank-count independence.
AssembledProblem buildSerial(const Teuchos::ParameterList& problem);

}  // namespace signorini::testing
