#pragma once
// Private to the library: the body of each cell of a mesh, for the assembly and the operators
// that work cell by cell. A cell's body is the entry of ProblemDefinition::bodies that its
// cell tag names, else the Problem-level body. The bodies are copied: an operator built from
// them outlives the problem.
#include <cstddef>
#include <vector>

#include "fe/SimplexMesh.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"

namespace signorini {

class CellBodies {
 public:
  // Throws InputError for a body that the mesh does not have (naming the mesh's bodies).
  CellBodies(const SimplexMesh& mesh, const ProblemDefinition& problem);

  int numBodies() const { return static_cast<int>(bodies_.size()); }
  const Body& body(int index) const { return bodies_[index]; }
  int indexOf(long long cell) const { return ofCell_.empty() ? 0 : ofCell_[cell]; }
  const Body& of(long long cell) const { return bodies_[indexOf(cell)]; }
  // Heap bytes of the per-cell indices.
  std::size_t bytes() const { return ofCell_.capacity() * sizeof(int); }

 private:
  std::vector<Body> bodies_;  // [0]: the Problem-level body
  std::vector<int> ofCell_;   // index into bodies_ per cell; empty: every cell in bodies_[0]
};

}  // namespace signorini
