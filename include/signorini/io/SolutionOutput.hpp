#pragma once
/// \file
/// The outputs of a solved problem: the ParaView solution and the contact pressure samples.
#include <string>
#include <vector>

#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/solver/SolveResult.hpp"

namespace signorini {

/// The contact fields of a solved problem, on A's range map (one value per constraint): the
/// pressure's nodal values and the active indicator (1 or 0), with the recovery that maps
/// them to the contact nodes.
struct ContactFields {
  const ContactPressure& recovery;
  const Vector& pressure;
  const Vector& active;
};

/// `directory`/solution.pvtu and one .vtu piece per rank (writeVtu): per node the displacement,
/// the contact pressure and active indicator (one ContactFields per contact pair; 0 without),
/// the contact force (A^T lambda) . n_o (the node's share of the obstacle's force, in force
/// units; n_o the direction of the node's pair) and the gap g + n_o . u on the contact
/// boundaries; per cell the von Mises stress at the centroid and the
/// rank. Creates the directory. Collective.
void writeSolution(const AssembledProblem& problem, const SolveResult& result, const std::vector<ContactFields>& contact,
                   const std::string& directory);

/// `path` (contact.csv), written by rank 0 with every rank's samples: the columns x, y(, z),
/// weight, pressure, one row per quadrature point of the contact boundary. Collective.
void writeContactSamples(const ContactPressureSamples& samples, const Comm& comm, const std::string& path);

}  // namespace signorini
