// Penalised friction without its tangent (COEF_MATR_FROT = 0) on testcases/stability/plate_slide
// (E_N = 1e18, E_T = 1e11, COULOMB = 1): once the plate slides, the friction force follows the
// normal forces as a fixed point that converges linearly (about 0.4 per iteration), beyond
// ITER_GLOB_MAXI = 10 and every cut; SNL_3 then names COEF_MATR_FROT, whose tangent converges in 5
// iterations (testcases/stability/plate_slide.comm).

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

std::string plateSlide(const std::string& coefficient) {
  return R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('PLAQ_BAS', 'PLAQ_HAUT', 'SOL_HAUT')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
SOL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='SOL', DX=0.0, DY=0.0))
PRESSION = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='PLAQ_HAUT', PRES=1.0e6))
GLISSE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='PLAQ_HAUT', DX=1.0e-5))
F_N = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 2.0, 1.0))
F_T = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 0.0, 2.0, 1.0))
L_INST = DEFI_LIST_REEL(VALE=(0.0, 0.5, 1.0, 1.5, 2.0))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', FROTTEMENT='COULOMB',
                    ZONE=_F(GROUP_MA_MAIT='SOL_HAUT', GROUP_MA_ESCL='PLAQ_BAS', ALGO_CONT='PENALISATION',
                            E_N=1.0e18, ALGO_FROT='PENALISATION', E_T=1.0e11, COULOMB=1.0)" +
         coefficient + R"())
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT,
                     EXCIT=(_F(CHARGE=SOL), _F(CHARGE=PRESSION, FONC_MULT=F_N), _F(CHARGE=GLISSE, FONC_MULT=F_T)),
                     INCREMENT=_F(LIST_INST=L_INST))
FIN()
)";
}

TEST(PenaltyFrictionAdvice, NoConvergenceWithoutTheFrictionTangentNamesCoefMatrFrot) {
  const auto run =
      testing::runStudy("plate_slide_coef0", plateSlide(""), "testcases/stability/plate_slide.msh");
  EXPECT_EQ(run->failure(), FailureKind::NoConvergence) << run->mess();
  EXPECT_NE(run->mess().find("SNL_3"), std::string::npos) << run->mess();
  EXPECT_NE(run->mess().find("COEF_MATR_FROT = 1 adds its derivative"), std::string::npos) << run->mess();
}

TEST(PenaltyFrictionAdvice, TheFrictionTangentConverges) {
  const auto run = testing::runStudy("plate_slide_coef1", plateSlide(", COEF_MATR_FROT=1.0"),
                                     "testcases/stability/plate_slide.msh");
  EXPECT_EQ(run->failure(), FailureKind::None) << run->mess();
  const auto resu = run->result("RESU");
  ASSERT_NE(resu, nullptr);
  ASSERT_EQ(resu->steps.size(), 5U); // no cut
  // 5 Newton iterations per sliding step when every link entering contact was condensed, 6 since a
  // link closing for the first time in a step takes the penalised law at the next iterate (the
  // condensation is kept for links that reopen, where the cycling was): bounded, not cycling.
  for (const auto& step : resu->steps) {
    EXPECT_LE(step.parameters.count("ITER_GLOB") ? step.parameters.at("ITER_GLOB") : 0.0, 6.0) << step.time;
  }
}

} // namespace
} // namespace stella
