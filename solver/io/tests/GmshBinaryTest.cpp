// Binary Gmsh files (gmsh -bin) in formats 2.2 and 4.1, produced by gmsh at test time from the
// .geo scripts of testcases/meshes/: each must give exactly the mesh of the ASCII file gmsh writes
// from the same script (coordinates to 4 ulps, as the ASCII file prints 16 digits; cells, names, groups);
// truncated binary files give a clean MESHFILE error naming the file.

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace stella {
namespace {

std::filesystem::path gmsh(const std::string& geo, const std::string& out, const std::string& options) {
  const auto dir = testing::tempDir("gmsh_bin");
  const auto msh = dir / out;
  const std::string cmd = "gmsh " + options + " " + STELLA_SOURCE_DIR + "/testcases/meshes/" + geo + " -o " +
                          msh.string() + " > " + (dir / "gmsh.log").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return msh;
}

bool isBinary(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string marker, version;
  int type = -1;
  in >> marker >> version >> type;
  return type == 1;
}

struct Case {
  const char* geo;
  const char* options;
};

TEST(GmshBinary, SameMeshAsAsciiIn22And41) {
  const Case cases[] = {{"block_hex.geo", "-3 -order 2"},
                        {"block_tet.geo", "-3"},
                        {"wedge.geo", "-3 -order 2"},
                        {"two_blocks_2d.geo", "-2"}};
  for (const auto& c : cases) {
    for (const std::string format : {"msh22", "msh41"}) {
      SCOPED_TRACE(std::string(c.geo) + " " + format);
      const std::string options = std::string(c.options) + " -format " + format;
      const auto ascii = gmsh(c.geo, "a.msh", options);
      const auto binary = gmsh(c.geo, "b.msh", options + " -bin");
      ASSERT_FALSE(isBinary(ascii));
      ASSERT_TRUE(isBinary(binary));
      const Mesh a = readGmshMesh(ascii);
      const Mesh b = readGmshMesh(binary);
      EXPECT_GT(b.cellCount(), 10);
      testing::expectSameMesh(a, b);
    }
  }
}

TEST(GmshBinary, GroupsOfTheTwoBlocks) {
  const Mesh m = readGmshMesh(gmsh("two_blocks_2d.geo", "tb.msh", "-2 -format msh41 -bin"));
  EXPECT_EQ(m.dimension(), 2);
  EXPECT_EQ(m.cellGroup("Top_B")->size(), 12u);
  EXPECT_EQ(m.cellGroup("Bottom_C")->size(), 7u);
  EXPECT_EQ(m.cellGroup("B")->size(), 72u);
  EXPECT_EQ(m.nodeGroup("Top_B")->size(), 13u);
}

// Cut the binary file at every tenth of its length: always a MESHFILE error naming the file.
TEST(GmshBinary, TruncatedFilesGiveCleanErrors) {
  for (const std::string format : {"msh22", "msh41"}) {
    const auto full = gmsh("block_hex.geo", "full.msh", "-3 -format " + format + " -bin");
    std::ifstream in(full, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string bytes = buffer.str();
    int errors = 0;
    for (int k = 1; k < 10; ++k) {
      const auto cut = full.parent_path() / ("cut_" + format + "_" + std::to_string(k) + ".msh");
      std::ofstream(cut, std::ios::binary)
          << bytes.substr(0, bytes.size() * static_cast<std::size_t>(k) / 10);
      try {
        readGmshMesh(cut);
        ADD_FAILURE() << cut << " read without error";
      } catch (const UserError& e) {
        EXPECT_EQ(e.first().id.rfind("MESHFILE_", 0), 0u) << e.first().id;
        EXPECT_NE(e.first().message.find(cut.filename().string()), std::string::npos) << e.first().message;
        ++errors;
      }
    }
    EXPECT_EQ(errors, 9) << format;
  }
}

} // namespace
} // namespace stella
