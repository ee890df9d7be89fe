// MED files in the MED 2.3 layout (older Salome): testcases/legacy_meshes/med23_*.med, written
// by make_med23.py beside them with an ASTER .mail twin of the same mesh. Both must read to
// identical meshes (coordinates, connectivity in code_aster order, cell and node groups, families
// carrying several groups); the mesh written again in the current MED layout reads back the same.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace stella {
namespace {

using testing::expectSameMesh;
using testing::tempDir;

const std::filesystem::path legacy = std::filesystem::path(STELLA_SOURCE_DIR) / "testcases/legacy_meshes";

void expectLikeTwin(const std::string& stem) {
  SCOPED_TRACE(stem);
  const Mesh med23 = readMedMesh(legacy / (stem + ".med"));
  const Mesh twin = readAsterMesh(legacy / (stem + ".mail"));
  expectSameMesh(med23, twin);
  const auto dir = tempDir("med23");
  writeMedMesh(dir / (stem + ".med"), med23);
  expectSameMesh(readMedMesh(dir / (stem + ".med")), twin);
}

TEST(LegacyMed, Plate2dLinearReadsLikeItsTwin) {
  expectLikeTwin("med23_plate_lin");
}

TEST(LegacyMed, Plate2dQuadraticReadsLikeItsTwin) {
  expectLikeTwin("med23_plate_quad");
}

TEST(LegacyMed, Block3dReadsLikeItsTwin) {
  expectLikeTwin("med23_block");
}

TEST(LegacyMed, EveryCellTypeReadsLikeItsTwin) {
  expectLikeTwin("med23_zoo");
}

// Families carrying several groups: explicit contents, so that the twins cannot agree by
// both missing the groups.
TEST(LegacyMed, FamiliesWithSeveralGroupsGiveEveryGroup) {
  const Mesh m = readMedMesh(legacy / "med23_plate_lin.med");
  EXPECT_EQ(m.name(), "PLAQ2D");
  const auto size = [](const auto* group) { return group == nullptr ? std::size_t{0} : group->size(); };
  EXPECT_EQ(size(m.cellGroup("SURF")), 6u);
  EXPECT_EQ(size(m.cellGroup("GAUCHE")), 2u);
  EXPECT_EQ(size(m.cellGroup("DROITE")), 4u);
  EXPECT_EQ(size(m.cellGroup("BAS")), 2u);
  EXPECT_EQ(size(m.nodeGroup("N_BAS")), 3u);
  ASSERT_EQ(size(m.nodeGroup("N_COIN")), 1u);
  EXPECT_EQ(m.point(m.nodeGroup("N_COIN")->front())[0], 0.0);
  EXPECT_EQ(size(m.nodeGroup("N_HAUT")), 3u);
}

// Names stored in the file (NOM datasets of the 2.3 layout) are kept.
TEST(LegacyMed, NodeAndCellNamesAreRead) {
  const Mesh m = readMedMesh(legacy / "med23_block.med");
  EXPECT_EQ(m.nodeName(0), "NO1");
  EXPECT_EQ(m.nodeName(11), "NO12");
  EXPECT_EQ(m.cellName(0), "FACE_BAS");
  EXPECT_EQ(m.cellName(3), "HEXA2");
}

// The committed files are what the generator writes (run when python3-h5py is installed).
TEST(LegacyMed, GeneratorRewritesTheCommittedFiles) {
  if (std::system("/usr/bin/python3 -c 'import h5py' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "python3-h5py is not installed";
  }
  const auto dir = tempDir("med23gen");
  const std::string cmd =
      "/usr/bin/python3 " + (legacy / "make_med23.py").string() + " " + dir.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  for (const char* stem : {"med23_plate_lin", "med23_plate_quad", "med23_block", "med23_zoo"}) {
    SCOPED_TRACE(stem);
    expectSameMesh(readMedMesh(dir / (std::string(stem) + ".med")),
                   readMedMesh(legacy / (std::string(stem) + ".med")));
    expectSameMesh(readAsterMesh(dir / (std::string(stem) + ".mail")),
                   readAsterMesh(legacy / (std::string(stem) + ".mail")));
  }
}

} // namespace
} // namespace stella
