// The mesh commands from command files, run by the batch runner: LIRE_MAILLAGE in the three
// formats with VERI_MAIL alarms, DEFI_GROUP, MODI_MAILLAGE, CREA_MAILLAGE, MACR_INFO_MAIL and
// IMPR_RESU of a mesh, checked through the message file and the files written; the DEFI_GROUP
// options NOEUD_CENTRE, INTERVALLE_VALE (coordinates) and TUNNEL; MODI_MAILLAGE ORIE_NORM_COQUE
// and ORIE_LIGNE; refusals of what is not implemented.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/GroupOperations.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace stella {
namespace {

using testing::CommRun;
using testing::runComm;

TEST(MeshOperators, LireMaillageInEveryFormat) {
  const auto dir = testing::tempDir("lire");
  Mesh m = buildStructuredMesh({CellType::HEXA8, {2, 2, 2}, {1, 1, 1}, {0, 0, 0}});
  m.setName("BLOC");
  writeMedMesh(dir / "m.med", m);
  writeAsterMesh(dir / "m.mail", m);
  writeGmshMesh(dir / "m.msh", m);
  const CommRun r = runComm(dir, "lire",
                            "DEBUT()\n"
                            "MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20, INFO=2)\n"
                            "MB = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=21)\n"
                            "MC = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=22)\n"
                            "MD = LIRE_MAILLAGE(UNITE=20, NOM_MED='BLOC')\n"
                            "FIN()\n",
                            {{20, dir / "m.med"}, {21, dir / "m.mail"}, {22, dir / "m.msh"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_NE(r.message.find("mesh MA: 3D, 27 nodes"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("mesh MB: 3D, 27 nodes"), std::string::npos);
  EXPECT_NE(r.message.find("GROUP_MA XMAX"), std::string::npos);
}

TEST(MeshOperators, LireMaillageErrorsAndAlarms) {
  const auto dir = testing::tempDir("lire_err");
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  m.addNode(m.point(0)); // duplicate node
  writeMedMesh(dir / "dup.med", m, "M");
  const CommRun alarm =
      runComm(dir, "alarm", "DEBUT()\nMA = LIRE_MAILLAGE(UNITE=20)\nFIN()\n", {{20, dir / "dup.med"}});
  EXPECT_EQ(alarm.diagnostic, JobDiagnostic::Alarm) << alarm.message;
  EXPECT_NE(alarm.message.find("MESHCHECK_1"), std::string::npos) << alarm.message;
  std::ofstream(dir / "bad.med") << "not a med file";
  const CommRun bad =
      runComm(dir, "bad", "DEBUT()\nMA = LIRE_MAILLAGE(UNITE=20)\nFIN()\n", {{20, dir / "bad.med"}});
  EXPECT_NE(bad.diagnostic, JobDiagnostic::Ok);
  EXPECT_NE(bad.message.find("MESHFILE_4"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("bad.med (unit 20)"), std::string::npos)
      << bad.message; // the user's file, not its copy fort.20 in the work directory
}

TEST(MeshOperators, DefiGroup) {
  const auto dir = testing::tempDir("defi_group");
  writeMedMesh(dir / "m.med", buildStructuredMesh({CellType::HEXA8, {2, 2, 2}, {1, 1, 1}, {0, 0, 0}}), "M");
  const CommRun r = runComm(
      dir, "dg",
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(UNITE=20)\n"
      "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA,\n"
      "    DETR_GROUP_MA=_F(NOM='YMIN'),\n"
      "    CREA_GROUP_MA=(_F(NOM='CUBES', TOUT='OUI', TYPE_MAILLE='3D'),\n"
      "                   _F(NOM='SIDES', UNION=('XMIN', 'XMAX')),\n"
      "                   _F(NOM='UP', OPTION='FACE_NORMALE', VECT_NORMALE=(0., 0., 1.)),\n"
      "                   _F(NOM='BALL', OPTION='SPHERE', POINT=(0., 0., 0.), RAYON=0.1, "
      "TYPE_MAILLE='3D')),\n"
      "    CREA_GROUP_NO=(_F(GROUP_MA='UP', NOM='UPN'),\n"
      "                   _F(NOM='MIDZ', OPTION='PLAN', POINT=(0., 0., 0.5), VECT_NORMALE=(0., 0., 1.),\n"
      "                      PRECISION=1e-6)))\n"
      "FIN()\n",
      {{20, dir / "m.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  for (const char* line :
       {"group of cells CUBES (8 cells)", "group of cells SIDES (8 cells)", "group of cells UP (4 cells)",
        "group of cells BALL (1 cells)", "group of nodes UPN (9 nodes)", "group of nodes MIDZ (9 nodes)"}) {
    EXPECT_NE(r.message.find(line), std::string::npos) << line << "\n" << r.message;
  }
  const CommRun bad =
      runComm(dir, "dg_bad",
              "DEBUT()\nMA = LIRE_MAILLAGE(UNITE=20)\n"
              "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_MA=_F(NOM='A', UNION=('XMIN', 'NOPE')))\n"
              "FIN()\n",
              {{20, dir / "m.med"}});
  EXPECT_NE(bad.message.find("DEFI_GROUP_1"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("NOPE"), std::string::npos);
}

TEST(MeshOperators, ModiCreaInfoAndImpr) {
  const auto dir = testing::tempDir("modi_crea");
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}});
  reverseCell(m, m.cellGroup("YMAX")->front()); // a skin edge pointing inwards
  writeMedMesh(dir / "m.med", m, "M");
  const CommRun r =
      runComm(dir, "modi",
              "DEBUT()\n"
              "MA = LIRE_MAILLAGE(UNITE=20)\n"
              "MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('YMAX', 'XMAX')))\n"
              "MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, TRANSLATION=(1., 0.))\n"
              "MQ = CREA_MAILLAGE(MAILLAGE=MA, LINE_QUAD=_F(TOUT='OUI'))\n"
              "MACR_INFO_MAIL(MAILLAGE=MQ)\n"
              "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MQ))\n"
              "FIN()\n",
              {{20, dir / "m.med"}, {80, dir / "out.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_NE(r.message.find("ORIE_PEAU: 1 of 4 skin cells reoriented"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("QUAD8"), std::string::npos);
  EXPECT_NE(r.message.find("aspect ratio"), std::string::npos);
  const Mesh out = readMedMesh(dir / "out.med"); // unit 80 comes back to its --unit path
  EXPECT_EQ(out.nodeCount(), 21);
  EXPECT_DOUBLE_EQ(out.point(0)[0], 1.0);
}

TEST(MeshOperators, DefiGroupCentreIntervalAndTunnel) {
  const auto dir = testing::tempDir("defi_group_more");
  // A 4 x 4 x 4 box of unit cubes with an axis of 4 SEG2 along x at y = z = 2 (group AXE) and its
  // first node (0, 2, 2) in ORIG.
  Mesh m = buildStructuredMesh({CellType::HEXA8, {4, 4, 4}, {4, 4, 4}, {0, 0, 0}});
  const auto at = [&](double x) {
    return nodesWhere(m, [&](const Point3& p) { return p[0] == x && p[1] == 2.0 && p[2] == 2.0; }).front();
  };
  std::vector<CellId> axis;
  for (int i = 0; i < 4; ++i) {
    axis.push_back(m.addCell(CellType::SEG2, std::vector<NodeId>{at(i), at(i + 1)}));
  }
  m.setCellGroup("AXE", axis);
  m.setNodeGroup("ORIG", {at(0)});
  writeMedMesh(dir / "m.med", m, "M");
  const CommRun r = runComm(
      dir, "dg2",
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(UNITE=20)\n"
      "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA,\n"
      "    CREA_GROUP_MA=(_F(NOM='BALL', OPTION='SPHERE', NOEUD_CENTRE='N1', RAYON=0.1, TYPE_MAILLE='3D'),\n"
      "                   _F(NOM='TUBE', OPTION='CYLINDRE', NOEUD_CENTRE='N1', VECT_NORMALE=(0., 0., 1.),\n"
      "                      RAYON=1.5, CRIT_NOEUD='TOUS', TYPE_MAILLE='3D')),\n"
      "    CREA_GROUP_NO=(_F(NOM='SHELL', OPTION='ENV_SPHERE', NOEUD_CENTRE='N1', RAYON=1.0, "
      "PRECISION=1e-6),\n"
      "                   _F(NOM='SLAB', OPTION='INTERVALLE_VALE', NOM_CMP='X', VALE=(0.5, 2.0)),\n"
      "                   _F(NOM='TUN', OPTION='TUNNEL', GROUP_MA='VOLUME', GROUP_MA_AXE='AXE',\n"
      "                      GROUP_NO_ORIG='ORIG', RAYON=1.01, LONGUEUR=2.5),\n"
      "                   _F(NOM='TUNALL', OPTION='TUNNEL', TOUT='OUI', GROUP_MA_AXE='AXE',\n"
      "                      GROUP_NO_ORIG='ORIG', RAYON=1.01)))\n"
      "FIN()\n",
      {{20, dir / "m.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  // BALL: the corner cube; TUBE: the 4 columns of cubes whose nodes all lie within 1.5 of the z
  // axis (x, y in [0, 1]); SHELL: (1,0,0), (0,1,0), (0,0,1); SLAB: x in {1, 2}, 2 x 25 nodes;
  // TUN: x in {0, 1, 2} (the cut at 2.5), 5 nodes per plane within 1.01 of (y, z) = (2, 2);
  // TUNALL: the 5 planes.
  for (const char* line : {"group of cells BALL (1 cells)", "group of cells TUBE (4 cells)",
                           "group of nodes SHELL (3 nodes)", "group of nodes SLAB (50 nodes)",
                           "group of nodes TUN (15 nodes)", "group of nodes TUNALL (25 nodes)"}) {
    EXPECT_NE(r.message.find(line), std::string::npos) << line << "\n" << r.message;
  }
  const CommRun bad =
      runComm(dir, "dg2_bad",
              "DEBUT()\nMA = LIRE_MAILLAGE(UNITE=20)\n"
              "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(NOM='I', OPTION='INCLUSION',\n"
              "    CAS_FIGURE='3D', GROUP_MA='VOLUME', GROUP_MA_INCL='AXE'))\n"
              "FIN()\n",
              {{20, dir / "m.med"}});
  EXPECT_NE(bad.message.find("DEFI_GROUP_4"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("OPTION='INCLUSION' is not implemented yet"), std::string::npos) << bad.message;
}

TEST(MeshOperators, ModiMaillageShellAndLineOrientation) {
  const auto dir = testing::tempDir("modi_orie");
  Mesh box = buildStructuredMesh({CellType::HEXA8, {2, 2, 2}, {1, 1, 1}, {0, 0, 0}});
  reverseCell(box, box.cellGroup("ZMAX")->back());
  writeMedMesh(dir / "box.med", box, "BOX");
  Mesh plate = buildStructuredMesh({CellType::QUAD4, {2, 2, 1}, {2, 2, 1}, {0, 0, 0}});
  reverseCell(plate, plate.cellGroup("XMIN")->front());
  writeMedMesh(dir / "plate.med", plate, "PLATE");
  const CommRun r = runComm(
      dir, "orie",
      "DEBUT()\n"
      "MB = LIRE_MAILLAGE(UNITE=20)\n"
      "MB = DEFI_GROUP(reuse=MB, MAILLAGE=MB, CREA_GROUP_NO=_F(NOM='TOP', NOEUD='N27'))\n"
      "MB = MODI_MAILLAGE(reuse=MB, MAILLAGE=MB,\n"
      "                   ORIE_NORM_COQUE=_F(GROUP_MA='ZMAX', VECT_NORM=(0., 0., -1.), GROUP_NO='TOP'))\n"
      "MP = LIRE_MAILLAGE(UNITE=21)\n"
      "MP = MODI_MAILLAGE(reuse=MP, MAILLAGE=MP,\n"
      "                   ORIE_LIGNE=_F(GROUP_MA=('XMIN', 'YMIN'), VECT_TANG=(1., 0.), GROUP_NO='ORIGIN'))\n"
      "MP = MODI_MAILLAGE(reuse=MP, MAILLAGE=MP,\n"
      "                   ORIE_LIGNE=_F(GROUP_MA=('XMIN', 'YMIN'), VECT_TANG=(-1., 0.), GROUP_NO='ORIGIN'))\n"
      "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MB))\n"
      "FIN()\n",
      {{20, dir / "box.med"}, {21, dir / "plate.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  // ZMAX: 3 faces pointed up, one (reversed above) down: turning them all down reverses 3.
  // The L line XMIN + YMIN (4 SEG2, one of XMIN reversed above): along +x at the origin, the
  // skin's own direction (down XMIN, along YMIN) but for the reversed one; then VECT_TANG (-1, 0)
  // at the origin turns the whole line over.
  EXPECT_NE(r.message.find("ORIE_NORM_COQUE: 3 of 4 cells reversed (1 connected set)"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("ORIE_LIGNE: 1 of 4 cells reversed (1 connected set)"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("ORIE_LIGNE: 4 of 4 cells reversed (1 connected set)"), std::string::npos)
      << r.message;
  const Mesh out = readMedMesh(dir / "orie.rmed");
  for (const CellId c : *out.cellGroup("ZMAX")) {
    EXPECT_NEAR(cellNormal(out, c)[2], -0.25, 1e-14); // quarter faces, all facing down
  }
  const CommRun bad =
      runComm(dir, "orie_bad",
              "DEBUT()\nMP = LIRE_MAILLAGE(UNITE=21)\n"
              "MP = MODI_MAILLAGE(reuse=MP, MAILLAGE=MP, DEFORME=_F(OPTION='TRAN', ALEA=0.1))\n"
              "FIN()\n",
              {{21, dir / "plate.med"}});
  EXPECT_NE(bad.message.find("MODI_MAILLAGE/DEFORME/ALEA is not implemented yet"), std::string::npos)
      << bad.message;
}

} // namespace
} // namespace stella
