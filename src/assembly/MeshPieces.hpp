#pragma once
// Private to the library: the connected pieces of a distributed mesh, cells that share a node
// being in one piece: the bodies of a problem whose bodies were meshed apart (a body made of
// several materials meshed together is one piece).
#include <vector>

#include "assembly/DistributedSpace.hpp"

namespace signorini {

struct MeshPieces {
  int count = 0;
  std::vector<int> ofOwnedNode;  // the piece of each owned node, in ownedNodeMap() order
  std::vector<int> ofSpaceNode;  // the piece of each local node of the space, by space node
};

// Pieces numbered in the order of their smallest global node id, found at the first call on
// a space and kept with it. Collective at that call: a few Tpetra exchanges of one value per
// node (as many as the pieces cross rank boundaries in a chain).
const MeshPieces& meshPieces(const DistributedSpace& space);

}  // namespace signorini
