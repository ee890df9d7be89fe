// CONVERGENCE/VERIF and NEWTON/MATR_RIGI_SYME. VERIF is checked by comparing runs of one study:
// with both RESI_GLOB_RELA and RESI_GLOB_MAXI, 'TOUT' must need as many iterations as the later
// of the two criteria alone and 'AU_MOINS_UN' as the earlier (the plastic step of the unit cube
// with the elastic matrix converges linearly, so the two criteria are met at distinct
// iterations). MATR_RIGI_SYME='OUI' must reach the same solution: on the friction block (an
// unsymmetric tangent while sliding) and on a symmetric problem.

#include "solver/nonlinear/ConvergenceVerif.hpp"
#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

TEST(ConvergenceVerif, CombinesTheGivenCriteria) {
  using C = CriteriaCombination;
  EXPECT_TRUE(criteriaHold({{true, true}, {true, true}}, C::All));
  EXPECT_FALSE(criteriaHold({{true, true}, {true, false}}, C::All));
  EXPECT_TRUE(criteriaHold({{true, true}, {true, false}}, C::AtLeastOne));
  EXPECT_TRUE(criteriaHold({{true, false}, {true, true}}, C::AtLeastOne));
  EXPECT_FALSE(criteriaHold({{true, false}, {true, false}}, C::AtLeastOne));
  // A criterion not given takes no part: it neither blocks 'TOUT' nor satisfies 'AU_MOINS_UN'.
  EXPECT_TRUE(criteriaHold({{true, true}, {false, false}}, C::All));
  EXPECT_FALSE(criteriaHold({{true, false}, {false, true}}, C::AtLeastOne));
  EXPECT_FALSE(criteriaHold({{false, true}, {false, true}}, C::All));
}

// The unit cube pulled by a traction 100 FR(t): sigma = 200 (yield) at t = 1, 240 at t = 2.
std::string cubeStudy(const std::string& convergence) {
  return R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
HARD = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=20000.0, SY=200.0))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=HARD))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
TRAC = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FX=100.0))
FR = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 2.0, 2.0, 2.4))
L = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                  COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), NEWTON=_F(MATRICE='ELASTIQUE'),
                  CONVERGENCE=_F(ITER_GLOB_ELAS=300, )" +
         convergence + R"(), INCREMENT=_F(LIST_INST=L))
FIN()
)";
}

int plasticStepIterations(const std::string& name, const std::string& convergence) {
  auto run = runStudy(name, cubeStudy(convergence), "testcases/plate_plasticity/hexa8.msh");
  EXPECT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto r = run->result("R");
  if (!r || r->stepAtTime(2.0) == nullptr) {
    ADD_FAILURE() << "no step at INST 2\n" << run->mess();
    return -1;
  }
  return static_cast<int>(r->stepAtTime(2.0)->parameters.at("ITER_GLOB"));
}

TEST(ConvergenceVerif, ToutWaitsForEveryCriterionAuMoinsUnForOne) {
  const int rela = plasticStepIterations("verif_rela", "RESI_GLOB_RELA=1.0e-8");
  const int maxi = plasticStepIterations("verif_maxi", "RESI_GLOB_MAXI=1.0e-2");
  // The criteria are met at distinct iterations (else the comparison below proves nothing).
  ASSERT_GT(rela, maxi + 10);
  EXPECT_EQ(plasticStepIterations("verif_tout", "RESI_GLOB_RELA=1.0e-8, RESI_GLOB_MAXI=1.0e-2, VERIF='TOUT'"),
            rela);
  EXPECT_EQ(
      plasticStepIterations("verif_un", "RESI_GLOB_RELA=1.0e-8, RESI_GLOB_MAXI=1.0e-2, VERIF='AU_MOINS_UN'"),
      maxi);
  // 'TOUT' is the default.
  EXPECT_EQ(plasticStepIterations("verif_default", "RESI_GLOB_RELA=1.0e-8, RESI_GLOB_MAXI=1.0e-2"), rela);
}

// The friction block of testcases/friction_block: pressed, then sheared until it slides; with
// COEF_MATR_FROT=1 the unsymmetric sliding term of the penalised Coulomb tangent is in the matrix.
std::string frictionStudy(const std::string& newton) {
  return R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('BLOC_BAS', 'SOL_HAUT')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
RIGIDE = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=RIGIDE))
SOL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='SOL', DX=0.0, DY=0.0))
PRESSE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='BLOC_HAUT', DY=-0.01))
CISAILLE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='BLOC_HAUT', DX=3.0e-3))
F_N = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 3.0, 1.0))
F_T = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 0.0, 3.0, 2.0))
L_INST = DEFI_LIST_REEL(VALE=(0.0, 1.0, 1.5, 2.0, 3.0))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', FROTTEMENT='COULOMB',
                    ZONE=_F(GROUP_MA_MAIT='SOL_HAUT', GROUP_MA_ESCL='BLOC_BAS', ALGO_CONT='PENALISATION',
                            E_N=1.0e4, ALGO_FROT='PENALISATION', E_T=1.0e4, COULOMB=0.2,
                            COEF_MATR_FROT=1.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT,
                  EXCIT=(_F(CHARGE=SOL), _F(CHARGE=PRESSE, FONC_MULT=F_N), _F(CHARGE=CISAILLE, FONC_MULT=F_T)),
                  INCREMENT=_F(LIST_INST=L_INST), NEWTON=_F()" +
         newton + R"(), CONVERGENCE=_F(ITER_GLOB_MAXI=60, RESI_GLOB_RELA=1.0e-8))
FIN()
)";
}

// max |a - b| over the DEPL of every stored step, and max |a|.
std::pair<double, double> displacementGap(const Result& a, const Result& b) {
  EXPECT_EQ(a.steps.size(), b.steps.size());
  double gap = 0.0;
  double size = 0.0;
  for (std::size_t s = 0; s < std::min(a.steps.size(), b.steps.size()); ++s) {
    const auto& u = a.steps[s].field("DEPL")->values();
    const auto& v = b.steps[s].field("DEPL")->values();
    for (std::size_t i = 0; i < u.size(); ++i) {
      gap = std::max(gap, std::fabs(u[i] - v[i]));
      size = std::max(size, std::fabs(u[i]));
    }
  }
  return {gap, size};
}

TEST(MatrRigiSyme, SymmetrisedFrictionTangentReachesTheSameSolution) {
  auto plain = runStudy("syme_no", frictionStudy("MATR_RIGI_SYME='NON'"),
                        "testcases/friction_block/friction_block.msh");
  auto syme = runStudy("syme_yes", frictionStudy("MATR_RIGI_SYME='OUI'"),
                       "testcases/friction_block/friction_block.msh");
  ASSERT_EQ(plain->failure(), FailureKind::None) << plain->mess();
  ASSERT_EQ(syme->failure(), FailureKind::None) << syme->mess();
  EXPECT_NE(syme->mess().find("symmetric (MATR_RIGI_SYME: (K + K^T) / 2)"), std::string::npos)
      << syme->mess();
  // The sliding steps' tangent is unsymmetric: its symmetric part is another matrix, and Newton
  // takes another path to the same solution (measured: 11 iterations in all instead of 10).
  int plainIterations = 0;
  int symeIterations = 0;
  for (const auto& s : plain->result("R")->steps) {
    plainIterations += static_cast<int>(s.parameters.at("ITER_GLOB"));
  }
  for (const auto& s : syme->result("R")->steps) {
    symeIterations += static_cast<int>(s.parameters.at("ITER_GLOB"));
  }
  EXPECT_GT(symeIterations, plainIterations);
  // Both converged to RESI_GLOB_RELA = 1e-8: the same displacements to about that.
  const auto [gap, size] = displacementGap(*plain->result("R"), *syme->result("R"));
  EXPECT_GT(size, 1.0e-3);
  EXPECT_LT(gap, 1.0e-8 * size) << "gap " << gap << " size " << size;
}

TEST(MatrRigiSyme, SymmetricProblemIsUnchanged) {
  const std::string base = cubeStudy("RESI_GLOB_RELA=1.0e-8");
  std::string syme = base;
  syme.replace(syme.find("MATRICE='ELASTIQUE'"), 19, "MATRICE='ELASTIQUE', MATR_RIGI_SYME='OUI'");
  auto a = runStudy("syme_cube_no", base, "testcases/plate_plasticity/hexa8.msh");
  auto b = runStudy("syme_cube_yes", syme, "testcases/plate_plasticity/hexa8.msh");
  ASSERT_EQ(a->failure(), FailureKind::None) << a->mess();
  ASSERT_EQ(b->failure(), FailureKind::None) << b->mess();
  const auto [gap, size] = displacementGap(*a->result("R"), *b->result("R"));
  EXPECT_GT(size, 1.0e-4);
  EXPECT_LE(gap, 1.0e-14 * size);
  EXPECT_EQ(a->result("R")->steps.back().parameters.at("ITER_GLOB"),
            b->result("R")->steps.back().parameters.at("ITER_GLOB"));
}

} // namespace
} // namespace stella
