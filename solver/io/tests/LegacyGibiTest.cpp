// GIBI meshes (Cast3M SAUVER FORMATTE): testcases/legacy_meshes/gibi_*.mgib, written by
// make_gibi.py from the meshes of make_med23.py. Each must read to the same mesh as its ASTER
// twin (coordinates through piles 32/33, connectivity in code_aster order for every Cast3M
// element type, named objects and compound objects as cell groups, named points as node
// groups). Damaged variants give a MESHFILE_* error that names the file and the line.

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace stella {
namespace {

using testing::expectSameMesh;
using testing::tempDir;

const std::filesystem::path legacy = std::filesystem::path(STELLA_SOURCE_DIR) / "testcases/legacy_meshes";

void expectLikeTwin(const std::string& stem) {
  SCOPED_TRACE(stem);
  expectSameMesh(readGibiMesh(legacy / (stem + ".mgib")), readAsterMesh(legacy / (stem + ".mail")));
}

TEST(LegacyGibi, Plate2dLinearReadsLikeItsTwin) {
  expectLikeTwin("gibi_plate_lin");
}

TEST(LegacyGibi, Plate2dQuadraticReadsLikeItsTwin) {
  expectLikeTwin("gibi_plate_quad");
}

TEST(LegacyGibi, Block3dReadsLikeItsTwin) {
  expectLikeTwin("gibi_block");
}

TEST(LegacyGibi, EveryElementTypeReadsLikeItsTwin) {
  expectLikeTwin("gibi_zoo");
}

// Explicit contents, so that the twins cannot agree by both missing the groups: SURF and BAS are
// compound objects, N_BAS an object of POI1 elements (a GROUP_MA, as in code_aster), N_COIN a
// named point (a GROUP_NO of one node).
TEST(LegacyGibi, NamedObjectsAndPointsBecomeGroups) {
  const Mesh m = readMesh(legacy / "gibi_plate_lin.mgib", MeshFormat::Gibi);
  EXPECT_EQ(m.dimension(), 2);
  EXPECT_EQ(m.nodeCount(), 9);
  EXPECT_EQ(m.cellCount(), 6 + 4 + 6); // POI1 of N_BAS and N_HAUT, SEG2, TRIA3 and QUAD4
  const auto size = [](const auto* group) { return group == nullptr ? std::size_t{0} : group->size(); };
  EXPECT_EQ(size(m.cellGroup("SURF")), 6u);
  EXPECT_EQ(size(m.cellGroup("GAUCHE")), 2u);
  EXPECT_EQ(size(m.cellGroup("BAS")), 2u);
  EXPECT_EQ(size(m.cellGroup("N_BAS")), 3u);
  EXPECT_EQ(m.nodeGroup("N_BAS"), nullptr);
  ASSERT_EQ(size(m.nodeGroup("N_COIN")), 1u);
  const auto corner = m.point(m.nodeGroup("N_COIN")->front());
  EXPECT_EQ(corner[0], 0.0);
  EXPECT_EQ(corner[1], 0.0);
  EXPECT_EQ(m.nodeName(m.nodeGroup("N_COIN")->front()), "N1");
}

TEST(LegacyGibi, GeneratorRewritesTheCommittedFiles) {
  if (std::system("/usr/bin/python3 -c 'import numpy' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "python3-numpy is not installed";
  }
  const auto dir = tempDir("gibigen");
  const std::string cmd =
      "/usr/bin/python3 " + (legacy / "make_gibi.py").string() + " " + dir.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  for (const char* stem :
       {"gibi_plate_lin.mgib", "gibi_plate_quad.mgib", "gibi_block.mgib", "gibi_zoo.mgib", "gibi_zoo.mail"}) {
    EXPECT_EQ(readWholeFile(dir / stem), readWholeFile(legacy / stem)) << stem;
  }
}

// --- damaged files: each variant of gibi_plate_lin.mgib must fail cleanly, naming the line.

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < text.size()) {
    const auto end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at));
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) {
    s += l + "\n";
  }
  return s;
}

struct Damage {
  const char* name;
  int line;            // 1-based line to change (0: none)
  const char* text;    // its replacement (nullptr: remove the line)
  const char* message; // expected in the message
};

void expectCleanError(const std::filesystem::path& file, const std::string& expected, bool located) {
  SCOPED_TRACE(file.filename().string());
  try {
    const Mesh m = readGibiMesh(file);
    ADD_FAILURE() << "read without error: " << m.nodeCount() << " nodes, " << m.cellCount() << " cells";
  } catch (const UserError& e) {
    const auto& d = e.first();
    EXPECT_EQ(d.id.rfind("MESHFILE_", 0), 0u) << d.id;
    EXPECT_NE(d.message.find(file.filename().string()), std::string::npos) << d.message;
    if (located) {
      EXPECT_NE(d.message.find(" line "), std::string::npos) << d.message;
    }
    EXPECT_NE(d.message.find(expected), std::string::npos) << d.message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a UserError: " << e.what();
  }
}

TEST(LegacyGibi, DamagedFilesGiveLocatedErrors) {
  const auto good = linesOf(readWholeFile(legacy / "gibi_plate_lin.mgib"));
  // Line numbers in gibi_plate_lin.mgib: 2 dimension, 9 pile 1 header, 12 the header of object 1
  // (3 POI1), 14 its connectivity, 38 the parts of object 9 (the first compound), 46 the node of
  // the named point, 47 the count of pile 32, 48 its entries, 52 the first coordinates.
  ASSERT_EQ(good.size(), 62u);
  const std::vector<Damage> damages{
      {"dimension", 2, " NIVEAU  15 NIVEAU ERREUR   0 DIMENSION   4", "space dimension 4"},
      {"no_dimension", 2, " NIVEAU  15", "expected 'DIMENSION'"},
      {"pile_header", 9, " PILE NUMERO   1", "expected 'NBRE OBJETS NOMMES'"},
      {"text_in_header", 12, "       1       0       0    deux       3", "columns 25-32"},
      {"node_count", 12, "       1       0       0       2       3", "2 nodes per element, expected 1"},
      {"unknown_type", 12, "      99       0       0       1       3", "element type 99"},
      {"node_out_of_range", 14, "       1       2      12", "refers to node 12"},
      {"part_out_of_range", 38, "       3      30", "has part 30"},
      {"self_part", 38, "       3       9", "contains itself"},
      {"point_out_of_range", 46, "      10", "refers to node 10"},
      {"negative_count", 47, "      -9", "node count is -9"},
      {"coordinate_entry", 48, "      99       8       7       6       5       4       3       2       1",
       "coordinate entry 99"},
      {"extra_value", 48, "       9       8       7       6       5       4       3       2       1       1",
       "more values than expected"},
      {"coordinate_text", 52, "  2.00000000000000E+00  abc  0.00000000000000E+00", "found 'abc'"},
      {"coordinate_nan", 52, "  2.00000000000000E+00  nan  0.00000000000000E+00", "found 'nan'"},
  };
  const auto dir = tempDir("gibidamaged");
  for (const auto& d : damages) {
    auto lines = good;
    lines[static_cast<std::size_t>(d.line - 1)] = d.text;
    const auto file = dir / (std::string(d.name) + ".mgib");
    std::ofstream(file) << joined(lines);
    expectCleanError(file, d.message, true);
  }
  // Cut after every line: never a crash, always a MESHFILE error.
  for (std::size_t n = 1; n + 2 < good.size(); ++n) {
    const auto file = dir / ("cut_" + std::to_string(n) + ".mgib");
    std::ofstream(file) << joined(
        std::vector<std::string>(good.begin(), good.begin() + static_cast<long>(n)));
    expectCleanError(file, "", false);
  }
  const auto notGibi = dir / "not_gibi.mgib";
  std::ofstream(notGibi) << "TITRE\n hello\nFINSF\n";
  expectCleanError(notGibi, "not a GIBI", false);
}

} // namespace
} // namespace stella
