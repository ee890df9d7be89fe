// CALC_CHAMP FORC_NODA / REAC_NODA count the forces of DIS_T / 2D_DIS_T springs (k u at the
// spring's node), as code_aster does: on the bodies of testcases/spring_held_body, held by
// nothing but corner springs, the sum of FORC_NODA balances the applied load exactly and
// REAC_NODA vanishes (there is no support). 3D: unit cube (E = 1000, NU = 0.3), springs
// (100, 200, 400) at the 8 corners, pressure 10 on x = 1 (resultant -10 along x) and corner forces
// (2, -3, 5) each (resultant (16, -24, 40)); 2D: unit square, springs (100, 200), pressure 10 on
// x = 1 (resultant -10 per unit thickness).

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

// Sum of a component of a nodal field over every node, and max |value|.
std::pair<double, double> sumAndMax(const Result& r, const std::string& field, const std::string& cmp) {
  const Field* f = r.steps.back().field(field);
  EXPECT_NE(f, nullptr) << field;
  if (f == nullptr) {
    return {0.0, 0.0};
  }
  const std::size_t c = *f->componentIndex(cmp);
  double sum = 0.0;
  double max = 0.0;
  for (std::size_t n = 0; n < f->entityCount(); ++n) {
    sum += f->value(n, c);
    max = std::max(max, std::fabs(f->value(n, c)));
  }
  return {sum, max};
}

TEST(SpringForces, ForcNodaOfASpringHeldCubeBalancesTheLoad) {
  const std::string comm = R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU='XMAX'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'),
                                    _F(GROUP_MA='CORNERS', PHENOMENE='MECANIQUE', MODELISATION='DIS_T')))
CARA = AFFE_CARA_ELEM(MODELE=MO, DISCRET=_F(GROUP_MA='CORNERS', CARA='K_T_D_N', VALE=(100.0, 200.0, 400.0)))
MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
FORCES = AFFE_CHAR_MECA(MODELE=MO, FORCE_NODALE=_F(GROUP_NO='CORNERS', FX=2.0, FY=-3.0, FZ=5.0))
PRESS = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='XMAX', PRES=10.0))
R2 = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, EXCIT=_F(CHARGE=PRESS))
R2 = CALC_CHAMP(reuse=R2, RESULTAT=R2, FORCE=('FORC_NODA', 'REAC_NODA'))
L_INST = DEFI_LIST_REEL(VALE=(0.0, 1.0))
R3 = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, EXCIT=(_F(CHARGE=FORCES), _F(CHARGE=PRESS)),
                   INCREMENT=_F(LIST_INST=L_INST))
R4 = CALC_CHAMP(RESULTAT=R3, FORCE=('FORC_NODA', 'REAC_NODA'))
TEST_RESU(RESU=(
    _F(RESULTAT=R2, NUME_ORDRE=1, NOM_CHAM='FORC_NODA', NOM_CMP='DX', TYPE_TEST='SOMM', VALE_CALC=-10.0,
       REFERENCE='ANALYTIQUE', VALE_REFE=-10.0, PRECISION=1.0e-10),
    _F(RESULTAT=R4, INST=1.0, NOM_CHAM='FORC_NODA', NOM_CMP='DZ', TYPE_TEST='SOMM', VALE_CALC=40.0,
       REFERENCE='ANALYTIQUE', VALE_REFE=40.0, PRECISION=1.0e-10),
))
FIN()
)";
  auto run = runStudy("spring_forces_3d", comm, "testcases/spring_held_body/cube.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_EQ(run->session->counts().testsOk, 4);
  const Result& r2 = *run->result("R2");
  EXPECT_NEAR(sumAndMax(r2, "FORC_NODA", "DX").first, -10.0, 1e-10);
  for (const char* cmp : {"DY", "DZ"}) {
    EXPECT_NEAR(sumAndMax(r2, "FORC_NODA", cmp).first, 0.0, 1e-10) << cmp;
  }
  for (const char* cmp : {"DX", "DY", "DZ"}) {
    EXPECT_LT(sumAndMax(r2, "REAC_NODA", cmp).second, 1e-10) << cmp; // no support, no reaction
  }
  // STAT_NON_LINE through a CALC_CHAMP without reuse (the springs travel with the new result).
  const Result& r4 = *run->result("R4");
  const double expected[] = {16.0 - 10.0, -24.0, 40.0};
  int c = 0;
  for (const char* cmp : {"DX", "DY", "DZ"}) {
    EXPECT_NEAR(sumAndMax(r4, "FORC_NODA", cmp).first, expected[c++], 1e-9) << cmp;
    EXPECT_LT(sumAndMax(r4, "REAC_NODA", cmp).second, 1e-9) << cmp;
  }
  // A corner node's FORC_NODA holds its spring force k u.
  const Field* u = r2.steps.back().field("DEPL");
  const Field* f = r2.steps.back().field("FORC_NODA");
  const auto corner = static_cast<std::size_t>(r2.mesh->nodeGroup("CORNERS")->front());
  const auto reac = r2.steps.back().field("REAC_NODA");
  EXPECT_NEAR(f->value(corner, 0) - reac->value(corner, 0), f->value(corner, 0), 1e-10);
  EXPECT_NE(u->value(corner, 0), 0.0);
}

TEST(SpringForces, ForcNodaOfASpringHeldSquareBalancesTheLoad) {
  const std::string comm = R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'),
                                    _F(GROUP_MA='CORNERS', PHENOMENE='MECANIQUE', MODELISATION='2D_DIS_T')))
CARA = AFFE_CARA_ELEM(MODELE=MO, DISCRET_2D=_F(GROUP_MA='CORNERS', CARA='K_T_D_N', VALE=(100.0, 200.0)))
MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
PRESS = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='XMAX', PRES=10.0))
R2 = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CARA, EXCIT=_F(CHARGE=PRESS))
R5 = CALC_CHAMP(RESULTAT=R2, CARA_ELEM=CARA, FORCE='FORC_NODA')
FIN()
)";
  auto run = runStudy("spring_forces_2d", comm, "testcases/spring_held_body/square.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const Result& r5 = *run->result("R5");
  EXPECT_NEAR(sumAndMax(r5, "FORC_NODA", "DX").first, -10.0, 1e-10);
  EXPECT_NEAR(sumAndMax(r5, "FORC_NODA", "DY").first, 0.0, 1e-10);
}

} // namespace
} // namespace stella
