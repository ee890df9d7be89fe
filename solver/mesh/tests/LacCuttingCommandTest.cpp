// CREA_MAILLAGE/DECOUPE_LAC through a command file: the cut mesh's counts in the message file,
// and bad slave groups refused with the located errors (file:line of GROUP_MA_ESCL).

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(LacCuttingCommand, CutsAndRefusesWithLocatedErrors) {
  const auto dir = testing::tempDir("decoupe_lac_cmd");
  writeAsterMesh(dir / "box.mail", buildStructuredMesh({CellType::HEXA8, {2, 2, 1}, {2, 2, 1}, {0, 0, 0}}),
                 {"box"});
  const auto ok = testing::runComm(
      dir, "ok",
      "DEBUT()\n"
      "M0 = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
      "M = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='ZMAX', DECOUPE_HEXA='HEXA'))\n"
      "FIN()\n",
      {{20, dir / "box.mail"}});
  EXPECT_EQ(ok.diagnostic, JobDiagnostic::Ok) << ok.message;
  EXPECT_NE(ok.message.find("DECOUPE_LAC: 4 cells cut, 32 nodes and 36 cells added"), std::string::npos)
      << ok.message;
  const auto bad = testing::runComm(dir, "bad",
                                    "DEBUT()\n"
                                    "M0 = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
                                    "M = CREA_MAILLAGE(MAILLAGE=M0,\n"
                                    "    DECOUPE_LAC=_F(GROUP_MA_ESCL='VOLUME'))\n"
                                    "FIN()\n",
                                    {{20, dir / "box.mail"}});
  EXPECT_EQ(bad.diagnostic, JobDiagnostic::Error) << bad.message;
  EXPECT_NE(bad.message.find("CREALAC_1"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("bad.comm:4"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("slave cells of a 3D mesh are TRIA3"), std::string::npos) << bad.message;
}

} // namespace
} // namespace stella
