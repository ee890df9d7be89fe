// Dualised conditions repeated on the same DOF (a node in two groups, a face blocked by two loads,
// a DDL_IMPO over an AFFE_CHAR_CINE) keep one multiplier, so the study runs as if each DOF were
// imposed once; conditions imposing different values are refused (LOAD_11) naming the node and DOF.
// Cube of testcases/plate_plasticity (HEXA8, E = 200000, NU = 0.3), symmetry planes x = 0, y = 0,
// z = 0, traction FX = 100 on x = 1: uniform uniaxial stress, DX = 5e-4 x, DY = -1.5e-4 y; N8 is
// (1, 1, 1).

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>
#include <regex>

namespace stella {
namespace {

using testing::runStudy;

const char* kMesh = "testcases/plate_plasticity/hexa8.msh";

const std::string kPreamble = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
M = DEFI_GROUP(reuse=M, MAILLAGE=M, CREA_GROUP_NO=(_F(GROUP_MA='X0'), _F(GROUP_MA='Y0')))
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=MAT))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
TRAC = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FX=100.0))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
STEP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 1.0, 1.0, 1.0))
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0))
)";

// The same DOFs imposed again: within BC2 (X0 by DDL_IMPO and by FACE_IMPO, Y0 by its node group
// and its cell group), by a second load under another FONC_MULT (zero values), and by an eliminated
// MECA_IMPO on Z0 that BC also dualises.
const std::string kRepeated = R"(
BC2 = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_NO='Y0', DY=0.0), _F(GROUP_MA='Y0', DY=0.0)),
                     FACE_IMPO=_F(GROUP_MA='X0', DX=0.0))
CINE = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=_F(GROUP_MA='Z0', DZ=0.0))
)";

double nodeValue(const Result& r, const Mesh& mesh, const std::string& node, int c) {
  const Field* u = r.steps.back().field("DEPL");
  return u->value(static_cast<std::size_t>(*mesh.findNode(node)), static_cast<std::size_t>(c));
}

// The number of Lagrange multipliers the first analysis of the message file reports.
int multipliers(const std::string& mess) {
  std::smatch m;
  if (!std::regex_search(mess, m, std::regex("(\\d+) Lagrange multiplier"))) {
    return -1;
  }
  return std::stoi(m[1]);
}

TEST(RepeatedConditions, RepeatedZeroConditionsAreMerged) {
  auto once = runStudy("rep_once",
                       kPreamble + "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), "
                                   "_F(CHARGE=TRAC)))\nFIN()\n",
                       kMesh);
  ASSERT_EQ(once->failure(), FailureKind::None) << once->mess();
  auto twice =
      runStudy("rep_twice",
               kPreamble + kRepeated +
                   "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=BC2, "
                   "FONC_MULT=STEP), _F(CHARGE=CINE), _F(CHARGE=TRAC)))\n"
                   "S = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC2, FONC_MULT=RAMP), "
                   "_F(CHARGE=BC), _F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=RAMP)), "
                   "INCREMENT=_F(LIST_INST=TIMES))\nFIN()\n",
               kMesh);
  ASSERT_EQ(twice->failure(), FailureKind::None) << twice->mess();
  const Mesh& mesh = *once->result("R")->mesh;
  for (const auto* run : {once.get(), twice.get()}) {
    EXPECT_NEAR(nodeValue(*run->result("R"), mesh, "N8", 0), 5.0e-4, 1e-15);
    EXPECT_NEAR(nodeValue(*run->result("R"), mesh, "N8", 1), -1.5e-4, 1e-15);
    EXPECT_NEAR(nodeValue(*run->result("R"), mesh, "N8", 2), -1.5e-4, 1e-15);
  }
  EXPECT_NEAR(nodeValue(*twice->result("S"), mesh, "N8", 0), 5.0e-4, 1e-15);
  // The eliminated Z0 takes the place of BC's multipliers there; the rest is one multiplier per
  // DOF. STAT_NON_LINE (BC twice in EXCIT) has exactly the multipliers of BC once.
  const int once1 = multipliers(once->mess());
  const auto z0 = static_cast<int>(mesh.nodesOfCells(*mesh.cellGroup("Z0")).size());
  EXPECT_GT(once1, z0);
  EXPECT_EQ(multipliers(twice->mess()), once1 - z0);
  const std::string mess = twice->mess();
  const std::string snl = mess.substr(mess.find("S = STAT_NON_LINE"));
  EXPECT_EQ(multipliers(snl), once1) << snl;
}

std::string failureOf(const std::string& name, const std::string& body) {
  auto run = runStudy(name, kPreamble + body + "\nFIN()\n", kMesh);
  EXPECT_EQ(run->failure(), FailureKind::Error);
  return run->mess();
}

TEST(RepeatedConditions, DifferentValuesOnOneDofAreRefused) {
  // N1 (0, 0, 0) is on X0: DX = 0 by BC, DX = 0.001 by MOVE.
  std::string m =
      failureOf("rep_conflict", "MOVE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(NOEUD='N1', DX=1.0e-3))\n"
                                "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), "
                                "_F(CHARGE=MOVE)))");
  EXPECT_NE(m.find("LOAD_11"), std::string::npos) << m;
  EXPECT_NE(m.find("node N1, DOF DX: imposed twice with different values (DX = 0 by DDL_IMPO of load BC, "
                   "and DX = 0.001 by DDL_IMPO of load MOVE)"),
            std::string::npos)
      << m;
  // Within one load.
  m = failureOf(
      "rep_conflict_one",
      "MOVE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(NOEUD='N1', DX=2.0)))\n"
      "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=MOVE), _F(CHARGE=TRAC)))");
  EXPECT_NE(m.find("node N1, DOF DX"), std::string::npos) << m;
  // The same non-zero value under different FONC_MULT differs at some instant.
  m = failureOf(
      "rep_conflict_fonc",
      "A = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='X1', DX=1.0e-3))\n"
      "S = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=A, FONC_MULT=RAMP), "
      "_F(CHARGE=A, FONC_MULT=STEP)), INCREMENT=_F(LIST_INST=TIMES))");
  EXPECT_NE(m.find("LOAD_11"), std::string::npos) << m;
  EXPECT_NE(m.find("different FONC_MULT"), std::string::npos) << m;
  // Against an eliminated DOF.
  m = failureOf("rep_conflict_cine",
                "CINE = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=_F(NOEUD='N1', DZ=1.0))\n"
                "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=CINE)))");
  EXPECT_NE(m.find("DZ = 1 by MECA_IMPO of load CINE"), std::string::npos) << m;
}

TEST(RepeatedConditions, SameNonZeroValueUnderOneMultiplierIsMerged) {
  auto run =
      runStudy("rep_same",
               kPreamble + "A = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X1', DX=1.0e-3), "
                           "_F(NOEUD='N8', DX=1.0e-3)))\n"
                           "S = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=A, "
                           "FONC_MULT=RAMP)), INCREMENT=_F(LIST_INST=TIMES))\nFIN()\n",
               kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const Result& s = *run->result("S");
  EXPECT_NEAR(nodeValue(s, *s.mesh, "N8", 0), 1.0e-3, 1e-15);
  EXPECT_NEAR(nodeValue(s, *s.mesh, "N8", 1), -3.0e-4, 1e-15);
}

} // namespace
} // namespace stella
