// Penalised friction on testcases/stability/plate_slide (E_N = 1e18, E_T = 1e11, COULOMB = 1).
// With COEF_MATR_FROT = 0 the sliding links' tangent is left out while RESI_GLOB_RELA >= 1e-3 and
// the statuses change: the friction force then follows the normal forces as a fixed point that
// converges linearly (about 0.4 per iteration); once the statuses settle the whole tangent takes
// over (before that rule: NO_CONVERGENCE beyond ITER_GLOB_MAXI = 10 and every cut). With too few
// iterations SNL_3 names COEF_MATR_FROT, whose tangent from the first iteration converges in 5.

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

std::string plateSlide(const std::string& coefficient, const std::string& convergence = "") {
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
SANS_COUPE = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L_INST), ECHEC=_F(EVENEMENT='ERREUR', ACTION='ARRET'))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', FROTTEMENT='COULOMB',
                    ZONE=_F(GROUP_MA_MAIT='SOL_HAUT', GROUP_MA_ESCL='PLAQ_BAS', ALGO_CONT='PENALISATION',
                            E_N=1.0e18, ALGO_FROT='PENALISATION', E_T=1.0e11, COULOMB=1.0)" +
         coefficient + R"())
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT,
                     EXCIT=(_F(CHARGE=SOL), _F(CHARGE=PRESSION, FONC_MULT=F_N), _F(CHARGE=GLISSE, FONC_MULT=F_T)),
                     INCREMENT=_F(LIST_INST=)" +
         (convergence.empty() ? "L_INST)" : "SANS_COUPE)") + convergence + R"()
FIN()
)";
}

TEST(PenaltyFrictionAdvice, TheDefaultCoefficientConvergesOnceTheStatusesSettle) {
  const auto run =
      testing::runStudy("plate_slide_coef0", plateSlide(""), "testcases/stability/plate_slide.msh");
  EXPECT_EQ(run->failure(), FailureKind::None) << run->mess();
  const auto resu = run->result("RESU");
  ASSERT_NE(resu, nullptr);
  ASSERT_EQ(resu->steps.size(), 5U); // no cut
  // 8 and 12 iterations in the sliding steps (12: a geometric update after 10): bounded by
  // ITER_GLOB_MAXI = 10 per pairing.
  for (const auto& step : resu->steps) {
    EXPECT_LE(step.parameters.count("ITER_GLOB") ? step.parameters.at("ITER_GLOB") : 0.0, 13.0) << step.time;
  }
  // a symmetric prediction at least once per step (the coefficient 0 as given), unsymmetric
  // factorisations only from the settled iterations
  EXPECT_NE(run->mess().find(" symmetric, "), std::string::npos) << run->mess();
}

TEST(PenaltyFrictionAdvice, NoConvergenceWithoutTheFrictionTangentNamesCoefMatrFrot) {
  const auto run =
      // ITER_GLOB_MAXI = 4 and no step cutting (ECHEC ACTION='ARRET'): not enough for the fixed point
      testing::runStudy("plate_slide_coef0_iter4", plateSlide("", ", CONVERGENCE=_F(ITER_GLOB_MAXI=4)"),
                        "testcases/stability/plate_slide.msh");
  EXPECT_EQ(run->failure(), FailureKind::NoConvergence) << run->mess();
  EXPECT_NE(run->mess().find("SNL_3"), std::string::npos) << run->mess();
  EXPECT_NE(run->mess().find("COEF_MATR_FROT = 1 adds it from the first iteration"), std::string::npos)
      << run->mess();
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
