#include "signorini/io/SolutionOutput.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "fe/ElasticityElement.hpp"
#include "io/AtomicFile.hpp"
#include "io/RunSummary.hpp"
#include "signorini/io/VtuWriter.hpp"

namespace signorini {
namespace {

double vonMises(const double* s, int dim, const IsotropicMaterial& material) {
  double sxx = s[0], syy, szz, sxy, syz = 0, szx = 0;
  if (dim == 2) {
    syy = s[3];
    sxy = s[1];
    szz = material.planeStrain ? material.poissonRatio * (sxx + syy) : 0.0;
  } else {
    syy = s[4];
    szz = s[8];
    sxy = s[1];
    syz = s[5];
    szx = s[2];
  }
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                   3.0 * (sxy * sxy + syz * syz + szx * szx));
}

}  // namespace

void writeSolution(const AssembledProblem& p, const SolveResult& r, const ContactFields* contact,
                   const std::string& directory) {
  const DistributedSpace& ds = *p.space;
  const ProblemDefinition& def = p.definition;
  const int dim = ds.dim();
  const auto& overlap = ds.overlapSpaceNodes();
  const Import toOverlap(ds.ownedDofMap(), ds.overlapDofMap());
  Vector u(ds.overlapDofMap()), force(ds.ownedDofMap()), forceHere(ds.overlapDofMap());
  u.doImport(*r.v, toOverlap, Tpetra::INSERT);
  p.qp.A->apply(*r.lambda, force, Teuchos::TRANS);
  forceHere.doImport(force, toOverlap, Tpetra::INSERT);

  NodeField displacement{"displacement", dim, {}}, forceField{"contact force", 1, {}},
      pressureField{"contact pressure", 1, {}}, gapField{"gap", 1, {}}, activeField{"active", 1, {}};
  auto ud = u.getData();
  auto fd = forceHere.getData();
  displacement.values.assign(ud.begin(), ud.end());
  std::vector<char> onContact(ds.space().numNodes(), 0);
  if (!def.contactBoundary.empty())
    for (long long node : ds.boundaryNodes(ds.mesh().tag(def.contactBoundary))) onContact[node] = 1;
  for (std::size_t i = 0; i < overlap.size(); ++i) {
    double normalForce = 0, normalDisplacement = 0;
    for (int c = 0; c < dim; ++c) {
      normalForce += fd[dim * i + c] * def.obstacleDirection[c];
      normalDisplacement += ud[dim * i + c] * def.obstacleDirection[c];
    }
    forceField.values.push_back(normalForce);
    const double* x = &ds.space().nodeCoordinates()[dim * overlap[i]];
    gapField.values.push_back(onContact[overlap[i]] ? (*def.gap)(x, dim) + normalDisplacement : 0.0);
  }
  pressureField.values.assign(overlap.size(), 0.0);
  activeField.values.assign(overlap.size(), 0.0);
  if (contact) {
    pressureField.values = contact->recovery.overlapNodeValues(contact->pressure);
    activeField.values = contact->recovery.overlapNodeValues(contact->active);
  }

  CellField rank{"rank", 1, {}}, mises{"von Mises stress", 1, {}};
  const LagrangeSpace& space = ds.space();
  const int npc = space.nodesPerCell();
  std::vector<int> localIndex(space.numNodes(), -1);
  for (std::size_t i = 0; i < overlap.size(); ++i) localIndex[overlap[i]] = static_cast<int>(i);
  std::vector<double> coords((dim + 1) * dim), local(dim * npc), sigma(dim * dim);
  double centroid[3];
  for (int i = 0; i < dim; ++i) centroid[i] = 1.0 / (dim + 1);
  for (long long cell = 0; cell < ds.mesh().numCells(); ++cell) {
    ds.mesh().cellVertexCoordinates(cell, coords.data());
    const long long* nodes = space.cellNodes(cell);
    for (int i = 0; i < npc; ++i)
      for (int c = 0; c < dim; ++c) local[dim * i + c] = ud[dim * localIndex[nodes[i]] + c];
    cellStress(space.basis(), coords.data(), p.definition.material, local.data(), centroid, sigma.data());
    mises.values.push_back(vonMises(sigma.data(), dim, p.definition.material));
    rank.values.push_back(ds.comm()->getRank());
  }
  writeVtu(ds, {displacement, pressureField, forceField, gapField, activeField}, {mises, rank}, directory, "solution");
}

// contact.csv on rank 0: every rank's samples, gathered (the contact boundary is a surface).
void writeContactSamples(const ContactPressureSamples& samples, const Comm& comm, const std::string& path) {
  const int width = samples.dim + 2;
  std::vector<double> packed;
  for (std::size_t q = 0; q < samples.weights.size(); ++q) {
    packed.insert(packed.end(), &samples.points[q * samples.dim], &samples.points[(q + 1) * samples.dim]);
    packed.push_back(samples.weights[q]);
    packed.push_back(samples.pressures[q]);
  }
  // Teuchos' gatherv only handles equal counts: every rank sends its block to rank 0.
  int count = static_cast<int>(packed.size());
  if (comm.getRank() != 0) {
    Teuchos::send(comm, 1, &count, 0);
    if (count > 0) Teuchos::send(comm, count, packed.data(), 0);
    return;
  }
  std::vector<double> all = packed;
  for (int rank = 1; rank < comm.getSize(); ++rank) {
    Teuchos::receive(comm, rank, 1, &count);
    std::vector<double> block(count);
    if (count > 0) Teuchos::receive(comm, rank, count, block.data());
    all.insert(all.end(), block.begin(), block.end());
  }
  std::ostringstream csv;
  csv.precision(17);
  csv << (samples.dim == 2 ? "x,y" : "x,y,z") << ",weight,pressure\n";
  for (std::size_t i = 0; i < all.size(); i += width)
    for (int k = 0; k < width; ++k) csv << all[i + k] << (k + 1 < width ? ',' : '\n');
  detail::writeFileAtomically(path, csv.str());
}

}  // namespace signorini
