// IMPR_RESU(FORMAT='ASTER', RESU=_F(MAILLAGE=...)) from a command file: a mesh read from MED
// (independent of the .mail writer) is written on unit 26 and read back by stella's .mail reader
// (readAsterMesh): the same nodes (names, coordinates to the last bit), cells (types,
// connectivity, names) and groups, in 2D (linear and quadratic cells with their boundary edges)
// and 3D (every volume and face type). Fields and the keywords of fields are refused by name.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::CommRun;
using testing::runComm;

const char* const kWriteMesh =
    "DEBUT()\n"
    "MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
    "IMPR_RESU(FORMAT='ASTER', UNITE=26, RESU=_F(MAILLAGE=MA, SOUS_TITRE='round trip'))\n"
    "FIN()\n";

// Writes `m` as MED, runs kWriteMesh and checks that the mesh read back from unit 26 is the mesh
// LIRE_MAILLAGE read (MED stores the cells by type: the order is the reader's, not `m`'s).
void roundTrip(const std::string& name, const Mesh& m) {
  const auto dir = testing::tempDir(name);
  writeMedMesh(dir / "m.med", m, "MA");
  const Mesh read = readMedMesh(dir / "m.med");
  ASSERT_EQ(read.cellCount(), m.cellCount());
  ASSERT_EQ(read.nodeCount(), m.nodeCount());
  ASSERT_EQ(read.cellGroups().size(), m.cellGroups().size());
  const CommRun r = runComm(dir, "imp", kWriteMesh, {{20, dir / "m.med"}, {26, dir / "m.mail"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_NE(r.message.find("mesh MA written in the ASTER format"), std::string::npos) << r.message;
  const auto file = dir / "imp.work" / "fort.26";
  EXPECT_NE(testing::readText(file).find("round trip"), std::string::npos); // SOUS_TITRE in TITRE
  const Mesh back = readAsterMesh(file);
  EXPECT_EQ(back.dimension(), m.dimension());
  testing::expectSameMesh(read, back);
}

TEST(ImprResuAster, PlaneMeshesRoundTrip) {
  for (const CellType t :
       {CellType::QUAD4, CellType::QUAD8, CellType::QUAD9, CellType::TRIA3, CellType::TRIA6}) {
    Mesh m = buildStructuredMesh({t, {3, 2, 1}, {1.5, 0.7, 1}, {0.1, -0.2, 0}});
    m.setDimension(2);
    roundTrip(std::string("aster2d_") + std::string(name(t)), m);
  }
}

TEST(ImprResuAster, VolumeMeshesRoundTrip) {
  for (const CellType t : {CellType::HEXA8, CellType::HEXA20, CellType::TETRA10, CellType::PENTA15}) {
    const Mesh m = buildStructuredMesh({t, {2, 1, 2}, {1.0, 0.3, 2.0 / 3.0}, {0, 0, 0.25}});
    roundTrip(std::string("aster3d_") + std::string(name(t)), m);
  }
  // Every cell type, with overlapping cell groups and a node group.
  Mesh zoo = testing::zooMesh({CellType::HEXA8, CellType::HEXA20, CellType::HEXA27, CellType::TETRA4,
                               CellType::TETRA10, CellType::PENTA6, CellType::PENTA15, CellType::PENTA18,
                               CellType::PYRAM5, CellType::PYRAM13, CellType::QUAD4, CellType::QUAD8,
                               CellType::QUAD9, CellType::TRIA3, CellType::TRIA6, CellType::TRIA7,
                               CellType::SEG2, CellType::SEG3, CellType::POI1});
  roundTrip("aster_zoo", zoo);
}

TEST(ImprResuAster, FieldsAndTheirKeywordsAreRefused) {
  const auto dir = testing::tempDir("aster_refused");
  writeMedMesh(dir / "m.med", buildStructuredMesh({CellType::QUAD4, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}}), "MA");
  const std::string head = "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n";
  const std::pair<const char*, const char*> cases[] = {
      {"IMPR_RESU(FORMAT='ASTER', RESU=_F(MAILLAGE=MA, FORMAT_R='1PE12.5'))\n", "FORMAT_R"},
      {"IMPR_RESU(FORMAT='ASTER', RESU=(_F(MAILLAGE=MA), _F(MAILLAGE=MA)))\n", "several RESU occurrences"},
      {"MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
       "IMPR_RESU(FORMAT='ASTER', MODELE=MO, RESU=_F(MAILLAGE=MA))\n",
       "with MODELE"},
  };
  int k = 0;
  for (const auto& [call, what] : cases) {
    const CommRun r = runComm(dir, "refused" + std::to_string(k++), head + call + "FIN()\n",
                              {{20, dir / "m.med"}, {26, dir / "m.mail"}});
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Error) << call;
    EXPECT_NE(r.message.find("IMPR_RESU_1"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(what), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("is not implemented yet"), std::string::npos) << r.message;
  }
}

} // namespace
} // namespace stella
