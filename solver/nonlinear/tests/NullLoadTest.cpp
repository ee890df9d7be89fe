// STAT_NON_LINE when the external forces and the reactions vanish: RESI_GLOB_RELA has no
// reference, so the residual is tested in absolute (RESI_GLOB_RELA x the reference of the last
// step converged under load, or RESI_GLOB_MAXI when given), RESI_GLOB_RELA is shown as -1 and
// the relative test resumes when the load returns; without any earlier reference the run stops
// (SNL_11), as code_aster documents (U4.51.04 §6).
//
// 1) Cube of testcases/plate_plasticity (HEXA8, E = 200000, NU = 0.3, VMIS_ISOT_LINE SY = 200,
//    D_SIGM_EPSI = 20000) on symmetry planes, traction 100 FR(t) on x = 1 with FR = 2.4, 0, 0, 1
//    at t = 1, 2, 3, 4: uniaxial, sigma = 240 then 0 (the reactions vanish with the stress), then
//    100. Closed form: eps = 200/E + 40/ET = 3e-3 at t = 1, eps_p = 3e-3 - 240/E = 1.8e-3 after
//    unloading (DX = 1.8e-3 x, DY = -eps_p/2 y), DX(1) = 1.8e-3 + 100/E = 2.3e-3 at t = 4.
// 2) The cube of testcases/spring_held_body held by DIS_T springs only (no reaction at all),
//    continued from a loaded state with the load removed: no earlier reference -> SNL_11; with
//    RESI_GLOB_MAXI the springs bring it back to rest.

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

double nodeValue(const Result& r, double time, const std::string& node, int c) {
  const ResultStep* s = r.stepAtTime(time);
  EXPECT_NE(s, nullptr) << "no step at INST " << time;
  if (s == nullptr) {
    return 0.0;
  }
  return s->field("DEPL")->value(static_cast<std::size_t>(*r.mesh->findNode(node)),
                                 static_cast<std::size_t>(c));
}

TEST(NullLoad, UnloadedStepsConvergeOnTheAbsoluteCriterion) {
  const std::string comm = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
HARD = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=20000.0, SY=200.0))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=HARD))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
TRAC = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FX=100.0))
FR = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 2.4, 2.0, 0.0, 3.0, 0.0, 4.0, 1.0))
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0, 3.0, 4.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                  COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI'), NEWTON=_F(PREDICTION='ELASTIQUE'),
                  INCREMENT=_F(LIST_INST=TIMES))
R2 = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                   COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI'), NEWTON=_F(PREDICTION='ELASTIQUE'),
                   ETAT_INIT=_F(EVOL_NOLI=R, INST=1.0), INCREMENT=_F(LIST_INST=TIMES, INST_FIN=2.0))
FIN()
)";
  auto run = runStudy("null_load", comm, "testcases/plate_plasticity/hexa8.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const Result& r = *run->result("R");
  // No step cut: every instant of the list is stored once.
  EXPECT_EQ(r.steps.size(), 5u);
  EXPECT_NEAR(nodeValue(r, 1.0, "N8", 0), 3.0e-3, 1e-12);
  for (double t : {2.0, 3.0}) {
    EXPECT_NEAR(nodeValue(r, t, "N8", 0), 1.8e-3, 1e-12) << "INST " << t;
    EXPECT_NEAR(nodeValue(r, t, "N8", 1), -0.9e-3, 1e-12) << "INST " << t;
  }
  EXPECT_NEAR(nodeValue(r, 4.0, "N8", 0), 2.3e-3, 1e-12);
  const std::string mess = run->mess();
  // t = 2 and t = 3 for R, t = 2 for R2 (its reference comes from the initial state, 240 x 1/8).
  std::size_t notes = 0;
  for (auto p = mess.find("zero load and reactions"); p != std::string::npos;
       p = mess.find("zero load and reactions", p + 1)) {
    ++notes;
  }
  EXPECT_EQ(notes, 3u) << mess;
  EXPECT_NE(mess.find("step 2 INST 2: converged in 0 iteration(s), RESI_GLOB_RELA = -1.000e+00"),
            std::string::npos)
      << mess;
  EXPECT_NE(mess.find("RESI_GLOB_MAXI <= 3.000e-05 = RESI_GLOB_RELA x 3.000e+01"), std::string::npos) << mess;
  // The relative criterion is back at t = 4.
  const auto at = mess.find("step 4 INST 4: converged");
  ASSERT_NE(at, std::string::npos);
  const std::string last = mess.substr(at, mess.find('\n', at) - at);
  EXPECT_EQ(last.find("RESI_GLOB_RELA = -1"), std::string::npos) << last;
  EXPECT_NEAR(nodeValue(*run->result("R2"), 2.0, "N8", 0), 1.8e-3, 1e-12);
}

const std::string kSprings = R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'),
                                    _F(GROUP_MA='CORNERS', PHENOMENE='MECANIQUE', MODELISATION='DIS_T')))
CARA = AFFE_CARA_ELEM(MODELE=MO, DISCRET=_F(GROUP_MA='CORNERS', CARA='K_T_D_N', VALE=(100.0, 200.0, 400.0)))
MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
FORCES = AFFE_CHAR_MECA(MODELE=MO, FORCE_NODALE=_F(GROUP_NO='CORNERS', FX=2.0, FY=-3.0, FZ=5.0))
ONOFF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 1.5, 0.0, 2.0, 0.0))
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, EXCIT=_F(CHARGE=FORCES, FONC_MULT=ONOFF),
                  INCREMENT=_F(LIST_INST=TIMES, INST_FIN=1.0))
)";

TEST(NullLoad, WithoutAnyReferenceTheRunStops) {
  auto run =
      runStudy("null_load_stop",
               kSprings + "R = STAT_NON_LINE(reuse=R, MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, "
                          "EXCIT=_F(CHARGE=FORCES, FONC_MULT=ONOFF), ETAT_INIT=_F(EVOL_NOLI=R, INST=1.0), "
                          "INCREMENT=_F(LIST_INST=TIMES, INST_INIT=1.0))\nFIN()\n",
               "testcases/spring_held_body/cube.msh");
  // The initial state has a load (FONC_MULT = 1 at t = 1): it gives the reference, and the
  // released springs bring the body back to rest.
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_NEAR(nodeValue(*run->result("R"), 2.0, "N1", 0), 0.0, 1e-12);
  // Continued with the load already gone from the initial state: no reference at all.
  auto stop =
      runStudy("null_load_stop2",
               kSprings + "OFF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 2.0, 0.0))\n"
                          "R2 = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, "
                          "EXCIT=_F(CHARGE=FORCES, FONC_MULT=OFF), ETAT_INIT=_F(EVOL_NOLI=R, INST=1.0), "
                          "INCREMENT=_F(LIST_INST=TIMES, INST_INIT=1.0))\nFIN()\n",
               "testcases/spring_held_body/cube.msh");
  EXPECT_EQ(stop->failure(), FailureKind::Error);
  EXPECT_NE(stop->mess().find("SNL_11"), std::string::npos) << stop->mess();
  EXPECT_NE(stop->mess().find("RESI_GLOB_MAXI"), std::string::npos);
  // With RESI_GLOB_MAXI beside RESI_GLOB_RELA the absolute criterion is the user's.
  auto maxi = runStudy(
      "null_load_maxi",
      kSprings +
          "OFF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 2.0, 0.0))\n"
          "R2 = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, "
          "EXCIT=_F(CHARGE=FORCES, FONC_MULT=OFF), ETAT_INIT=_F(EVOL_NOLI=R, INST=1.0), "
          "CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-6, RESI_GLOB_MAXI=1.0e-8), INCREMENT=_F(LIST_INST=TIMES, "
          "INST_INIT=1.0))\nFIN()\n",
      "testcases/spring_held_body/cube.msh");
  ASSERT_EQ(maxi->failure(), FailureKind::None) << maxi->mess();
  EXPECT_NEAR(nodeValue(*maxi->result("R2"), 2.0, "N1", 2), 0.0, 1e-12);
  EXPECT_NE(maxi->mess().find("RESI_GLOB_MAXI <= 1.000e-08 (given)"), std::string::npos) << maxi->mess();
}

// 3) A stiff cube (E = 2.1e7) moved rigidly by DX = 0.2 t imposed on one face, nothing else: no
//    force anywhere, so the reference of RESI_GLOB_RELA is the round-off of the internal forces
//    (eps x K x u, about 1e-9 here, above machine epsilon). Before the round-off floor of
//    relativeTest the steps never converged (a round-off residual against 1e-6 of a round-off
//    reference), as in the first steps of testcases/ssnv506_indentation/ssnv506_h25_lac before
//    its first LAC patch comes into contact.
TEST(NullLoad, ARigidMotionWithoutLoadConvergesAtTheRoundOffOfTheInternalForces) {
  const std::string comm = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
STIFF = DEFI_MATERIAU(ELAS=_F(E=2.1e7, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=STIFF))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='Y0', DY=0.0), _F(GROUP_MA='Z0', DZ=0.0)))
MOVE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='X0', DX=0.2))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=2))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=MOVE, FONC_MULT=RAMP)),
                  INCREMENT=_F(LIST_INST=TIMES))
FIN()
)";
  auto run = runStudy("null_load_rigid", comm, "testcases/plate_plasticity/hexa8.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const Result& r = *run->result("R");
  EXPECT_EQ(r.steps.size(), 3u); // no step cut
  EXPECT_NEAR(nodeValue(r, 0.5, "N8", 0), 0.1, 1e-12);
  EXPECT_NEAR(nodeValue(r, 1.0, "N8", 0), 0.2, 1e-12);
  EXPECT_NEAR(nodeValue(r, 1.0, "N8", 1), 0.0, 1e-12);
  EXPECT_NE(run->mess().find("the round-off of the internal forces, 1e-12 x max K_ii x max |u|"),
            std::string::npos)
      << run->mess();
}

} // namespace
} // namespace stella
