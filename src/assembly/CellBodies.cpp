#include "assembly/CellBodies.hpp"

#include <map>

namespace signorini {

CellBodies::CellBodies(const SimplexMesh& mesh, const ProblemDefinition& problem) : bodies_{problem.body} {
  std::map<int, int> indexOfTag;
  for (const Body& body : problem.bodies) {
    indexOfTag[mesh.bodyTag(body.name)] = numBodies();
    bodies_.push_back(body);
  }
  if (indexOfTag.empty()) return;
  ofCell_.resize(mesh.numCells(), 0);
  for (long long cell = 0; cell < mesh.numCells(); ++cell) {
    const auto it = indexOfTag.find(mesh.cellTag(cell));
    if (it != indexOfTag.end()) ofCell_[cell] = it->second;
  }
}

}  // namespace signorini
