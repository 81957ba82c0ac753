#include "signorini/io/SolutionOutput.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "assembly/DistributedSpace.hpp"
#include "assembly/SolutionFields.hpp"
#include "io/AtomicFile.hpp"
#include "io/RunSummary.hpp"
#include "signorini/io/VtuWriter.hpp"

namespace signorini {

void writeSolution(const AssembledProblem& p, const SolveResult& r, const std::vector<ContactFields>& contact,
                   const std::string& directory) {
  const DistributedSpace& ds = distributedSpace(*p.space);
  const SolutionFields fields = solutionFields(ds, p.definition, *p.qp.A, *p.qp.d, *r.v, *r.lambda);
  const std::size_t nodes = ds.overlapSpaceNodes().size();
  NodeField displacement{"displacement", ds.dim(), fields.displacement},
      force{"contact force", 1, fields.normalContactForce}, gap{"gap", 1, fields.gap},
      pressure{"contact pressure", 1, std::vector<double>(nodes, 0.0)},
      active{"active", 1, std::vector<double>(nodes, 0.0)};
  for (const ContactFields& pair : contact) {  // a node on two pairs' boundaries: the sum, active in either
    const std::vector<double> p = pair.recovery.overlapNodeValues(pair.pressure),
                              a = pair.recovery.overlapNodeValues(pair.active);
    for (std::size_t i = 0; i < nodes; ++i) {
      pressure.values[i] += p[i];
      active.values[i] = std::max(active.values[i], a[i]);
    }
  }
  CellField mises{"von Mises stress", 1, fields.vonMisesStress},
      rank{"rank", 1, std::vector<double>(fields.vonMisesStress.size(), ds.comm()->getRank())};
  std::vector<CellField> cellFields{mises, rank};
  if (!ds.mesh().bodyTags.empty()) {  // the body of each cell: its physical group's tag
    CellField body{"body", 1, {}};
    for (long long c = 0; c < ds.mesh().numCells(); ++c) body.values.push_back(ds.mesh().cellTag(c));
    cellFields.push_back(std::move(body));
  }
  writeVtu(ds, {displacement, pressure, force, gap, active}, cellFields, directory, "solution");
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
