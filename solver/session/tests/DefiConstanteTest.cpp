// DEFI_CONSTANTE: a constant function, called from the command file and used as FONC_MULT,
// against the closed form of a bar in tension (mesh: tests/data/two_quads.msh, 3 x 0.5).

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

// The bar (3 x 0.5, E = 100, NU = 0) pulled on HAUT by FY = 4 per unit length x FONC_MULT: with
// BAS held (NU = 0: holding DX makes no stress) the stress is uniform, sigma_yy = 4 f, and the top moves by
// DY = sigma_yy / E x 0.5 = 0.02 f. f = DEFI_CONSTANTE(VALE=1.5) at every instant: DY = 0.03.
TEST(DefiConstante, ConstantMultiplierOfALoad) {
  const std::string comm = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=100.0, NU=0.0))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=MAT))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='BAS', DX=0.0, DY=0.0))
PULL = AFFE_CHAR_MECA(MODELE=MO, FORCE_CONTOUR=_F(GROUP_MA='HAUT', FY=4.0))
F = DEFI_CONSTANTE(VALE=1.5, NOM_RESU='COEF', TITRE='constant multiplier')
assert F(0.0) == 1.5 and F(-1.0e9) == 1.5 and F(TOUTPARA=7.0) == 1.5
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=F)),
                  COMPORTEMENT=_F(RELATION='ELAS', TOUT='OUI'), INCREMENT=_F(LIST_INST=TIMES))
FIN()
)";
  auto run = runStudy("defi_constante", comm, "solver/session/tests/data/two_quads.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const Result& r = *run->result("R");
  for (double t : {1.0, 2.0}) {
    const ResultStep* s = r.stepAtTime(t);
    ASSERT_NE(s, nullptr);
    for (const char* node : {"N4", "N5", "N6"}) {
      EXPECT_NEAR(s->field("DEPL")->value(static_cast<std::size_t>(*r.mesh->findNode(node)), 1), 0.03, 1e-12)
          << node << " at INST " << t;
    }
  }
  EXPECT_NE(
      run->mess().find("constant function F: COEF = 1.5 for any value of TOUTPARA (constant multiplier)"),
      std::string::npos)
      << run->mess();
}

} // namespace
} // namespace stella
