#include "support/TestProblems.hpp"

#include <gmsh.h>

#include <cmath>
#include <cstdlib>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fe/BoxMesh.hpp"
#include "solver/linear/KrylovSolver.hpp"
#include "solver/preconditioner/MueLuPreconditioner.hpp"

namespace signorini::testing {

std::string sourceDir() {
  const char* dir = std::getenv("SIGNORINI_SOURCE_DIR");
  return dir ? dir : SIGNORINI_TEST_SOURCE_DIR;
}

Teuchos::ParameterList shippedProblem(const std::string& relativePath) {
  auto list = Teuchos::getParametersFromXmlFile(sourceDir() + "/xml/" + relativePath + ".xml");
  return list->sublist("Problem");
}

Teuchos::ParameterList assembledShippedProblem(const std::string& relativePath) {
  Teuchos::ParameterList p = shippedProblem(relativePath);
  p.set("stiffness: operator", "assembled");
  return p;
}

Teuchos::ParameterList boxProblem(int dim, int cells, int degree) {
  Teuchos::ParameterList p("Problem");
  p.set("mesh: dimension", dim);
  p.set("mesh: cells", Teuchos::Array<int>(1, cells));
  p.set("element: degree", degree);
  // The tests of the pieces compare against Q assembled; those of whole solves set the path.
  p.set("stiffness: operator", "assembled");
  return p;
}

Teuchos::ParameterList contactBoxProblem(int dim, int cells) {
  Teuchos::ParameterList p = boxProblem(dim, cells, 1);
  p.sublist("Contact").set("boundary", dim == 2 ? "ymin" : "zmin");
  Teuchos::ParameterList& top = p.sublist("Dirichlet").sublist(dim == 2 ? "ymax" : "zmax");
  for (const char* c : {"x", "y", "z"})
    if (c[0] != 'z' || dim == 3) top.set(std::string("displacement: ") + c, "0");
  return p;
}

Teuchos::ParameterList gmshPressedProblem(int dim, const std::string& file, int degree, int refinements) {
  Teuchos::ParameterList p("Problem");
  p.set("mesh: type", "gmsh");
  p.set("mesh: file", file);
  p.set("mesh: refinements", refinements);
  p.set("element: degree", degree);
  p.set(dim == 2 ? "body force: y" : "body force: z", "-(1 + 8*(x - 0.5)^2)");
  auto& top = p.sublist("Dirichlet").sublist("top");
  for (const char* axis : {"x", "y", "z"})
    if (dim == 3 || std::string(axis) != "z") top.set(std::string("displacement: ") + axis, "0");
  p.sublist("Contact").set("boundary", "bottom");
  return p;
}

void meshUnitBox(int dim, double h) {
  gmsh::model::add("unit");
  const int body = dim == 2 ? gmsh::model::occ::addRectangle(0, 0, 0, 1, 1) : gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  const auto [bottom, top] = unitBoxBottomAndTop(dim, body);
  gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {bottom}), "bottom");
  gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, {top}), "top");
  gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, {body}), "body");
  gmsh::model::mesh::generate(dim);
}

std::pair<int, int> unitBoxBottomAndTop(int dim, int body) {
  int bottom = -1, top = -1;
  gmsh::vectorpair faces;
  gmsh::model::getBoundary({{dim, body}}, faces, false, false, false);
  for (const auto& [faceDim, tag] : faces) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(faceDim, tag, x0, y0, z0, x1, y1, z1);
    const double low = dim == 2 ? y1 : z1, high = dim == 2 ? y0 : z0;
    if (std::fabs(low) < 1e-6) bottom = tag;
    if (std::fabs(high - 1) < 1e-6) top = tag;
  }
  return {bottom, top};
}

SimplexMesh distortedBoxMesh(int dim, long long n) {
  SimplexMesh mesh = makeBoxMesh(dim, {n, n, dim == 3 ? n : 1}, {1.0, 1.0, 1.0});
  for (long long v = 0; v < mesh.numVertices(); ++v) {
    double* x = &mesh.vertices[dim * v];
    bool interior = true;
    for (int c = 0; c < dim; ++c) interior = interior && x[c] > 1e-9 && x[c] < 1 - 1e-9;
    if (interior)
      for (int c = 0; c < dim; ++c) x[c] += 0.2 / n * std::sin(7.0 * v + 3.0 * c);
  }
  return mesh;
}

int solveLinear(const ContactQP& qp, const MultigridInput& multigrid, Vector& x, double tol) {
  MueLuPreconditioner amg(Teuchos::ParameterList(), multigrid.blockSize, multigrid.nearNullspace(qp),
                          multigrid.coordinates);
  amg.compute(Teuchos::rcp_const_cast<CrsMatrix>(assembledStiffness(qp, multigrid)));
  KrylovSolver cg;
  x.putScalar(0.0);
  KrylovResult r = cg.solve(qp.Q, amg.getOperator(), qp.b, Teuchos::rcpFromRef(x), tol, 2000);
  return r.converged ? r.iterations : -1;
}

AssembledProblem buildSerial(const Teuchos::ParameterList& problem) {
  // A one-rank MPI communicator: MueLu assumes an MPI communicator in an MPI build.
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  return buildProblem(problem, self);
}

}  // namespace signorini::testing
