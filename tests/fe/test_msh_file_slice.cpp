// The slices of a Gmsh MSH 4.1 ASCII file against the file itself: every cell and boundary
// facet in exactly one slice, every node in the slice of its tag, bodies and boundary names as
// readGmshMesh gives them; files outside the reader's format are said to be, not misread.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "fe/GmshMesh.hpp"
#include "fe/MshFileSlice.hpp"
#include "signorini/core/Error.hpp"

namespace {

using namespace signorini;

// The unit square cut into two triangles by Gmsh's conventions: groups "bottom" (line 1-2),
// "side" (line 2-3) and the body "plate"; an unused node 9.
const char* kSquare = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "bottom"
1 2 "side"
2 3 "plate"
$EndPhysicalNames
$Entities
0 2 1 0
1 0 0 0 1 0 0 1 1 0
2 1 0 0 1 1 0 1 2 0
1 0 0 0 1 1 0 1 3 0
$EndEntities
$Nodes
1 5 1 9
2 1 0 5
1
2
3
4
9
0 0 0
1 0 0
1 1 0
0 1 0
0.5 0.5 0
$EndNodes
$Elements
3 4 1 4
1 1 1 1
1 1 2
1 2 1 1
2 2 3
2 1 2 2
3 1 2 3
4 1 3 4
$EndElements
)";

std::string written(const std::string& name, const std::string& text) {
  const char* binary = std::getenv("SIGNORINI_BINARY_DIR");
  const std::filesystem::path directory = std::filesystem::path(binary ? binary : "/tmp") / "msh-file-slice-test";
  std::filesystem::create_directories(directory);
  const std::string path = (directory / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(MshFileSlice, SlicesHoldEveryCellFacetAndNodeOnce) {
  const std::string path = written("square.msh", kSquare);
  const SimplexMesh whole = readGmshMesh(path);
  for (int slices : {1, 2, 3}) {
    std::multiset<long long> cells, nodes;
    long long facets = 0;
    for (int s = 0; s < slices; ++s) {
      std::string unsupported;
      const MshFileSlice slice = readMshSlice(path, s, slices, unsupported);
      ASSERT_EQ(unsupported, "");
      EXPECT_EQ(slice.dim, 2);
      EXPECT_EQ(slice.numCells, 2);
      EXPECT_EQ(slice.boundaryTags, whole.boundaryTags);
      EXPECT_EQ(slice.bodyTags, whole.bodyTags);
      EXPECT_EQ(slice.cellNodes.size(), 3 * slice.cellElements.size());
      EXPECT_EQ(slice.cellBodies, std::vector<int>(slice.cellElements.size(), 3));
      cells.insert(slice.cellElements.begin(), slice.cellElements.end());
      facets += static_cast<long long>(slice.facetTags.size());
      for (long long tag : slice.nodeTags) {
        EXPECT_EQ(MshFileSlice::sliceOfNode(tag, 1, 9, slices), s);
        nodes.insert(tag);
      }
    }
    EXPECT_EQ(cells, (std::multiset<long long>{3, 4})) << slices << " slices";
    EXPECT_EQ(facets, whole.numFacets()) << slices << " slices";
    EXPECT_EQ(nodes, (std::multiset<long long>{1, 2, 3, 4, 9})) << slices << " slices";
  }
}

TEST(MshFileSlice, CoordinatesAndNodesAreTheFilesOwn) {
  std::string unsupported;
  const MshFileSlice slice = readMshSlice(written("square.msh", kSquare), 0, 1, unsupported);
  ASSERT_EQ(slice.nodeTags, (std::vector<long long>{1, 2, 3, 4, 9}));
  EXPECT_EQ(slice.nodeCoordinates, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0}));
  EXPECT_EQ(slice.cellNodes, (std::vector<long long>{1, 2, 3, 1, 3, 4}));
  EXPECT_EQ(slice.facetNodes, (std::vector<long long>{1, 2, 2, 3}));
  EXPECT_EQ(slice.facetTags, (std::vector<int>{1, 2}));
}

TEST(MshFileSlice, FilesOutsideTheFormatAreSaidToBe) {
  std::string text = kSquare;
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  const struct {
    std::string name, text, reason;
  } cases[] = {
      {"msh22.msh", replaced("4.1 0 8", "2.2 0 8"), "MSH 4.1 ASCII"},
      {"binary.msh", replaced("4.1 0 8", "4.1 1 8"), "MSH 4.1 ASCII"},
      {"quads.msh", replaced("2 1 2 2", "2 1 3 2"), "linear simplices"},
      {"partitioned.msh", replaced("$Nodes", "$PartitionedEntities\n$EndPartitionedEntities\n$Nodes"), "partitioned"},
      {"names.msh", replaced("\"side\"", "\"bottom\""), "same name"},
  };
  for (const auto& c : cases) {
    std::string unsupported;
    const MshFileSlice slice = readMshSlice(written(c.name, c.text), 0, 1, unsupported);
    EXPECT_NE(unsupported.find(c.reason), std::string::npos) << c.name << ": " << unsupported;
    EXPECT_EQ(slice.dim, 0) << c.name;
  }
}

TEST(MshFileSlice, AMissingFileOrAMalformedSliceIsAnInputError) {
  std::string unsupported;
  EXPECT_THROW(readMshSlice("/nonexistent/mesh.msh", 0, 1, unsupported), InputError);
  std::string text = kSquare;
  text.replace(text.find("1 1 0\n0 1 0"), 5, "1 x 0");
  EXPECT_THROW(readMshSlice(written("malformed.msh", text), 0, 1, unsupported), InputError);
}

}  // namespace
