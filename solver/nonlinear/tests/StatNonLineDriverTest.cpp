// STAT_NON_LINE driver features on the unit cube of testcases/plate_plasticity (HEXA8, E=200000,
// NU=0.3, VMIS_ISOT_LINE SY=200, D_SIGM_EPSI=20000): step cutting (DEFI_LIST_INST ECHEC), ARRET,
// ETAT_INIT / reuse=, ARCHIVAGE, PREDICTION EXTRAPOLE / DEPL_CALCULE, REAC_INCR, RECH_LINEAIRE,
// INCREMENT NUME_INST_*. Uniaxial closed form: eps = 1e-3 RAMP(t), sigma = 200 + 20000 (eps - 1e-3)
// past yield.

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>
#include <regex>

namespace stella {
namespace {

using testing::runStudy;
using testing::StudyRun;

const char* kMesh = "testcases/plate_plasticity/hexa8.msh";

// The cube, its supports and materials; PULL imposes DX = 1e-3 on X1, SIDE adds a shear traction
// FY = 30 on X1 (a non-uniform, bending state); TRAC pulls X1 by a traction of 100 FR(t) (sigma = 200 at
// t = 1, 240 at t = 2: the same strains as PULL with RAMP).
const std::string kPreamble = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
M = DEFI_GROUP(reuse=M, MAILLAGE=M, CREA_GROUP_NO=_F(GROUP_MA='X1'))
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
HARD = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=20000.0, SY=200.0))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=HARD))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
PULL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='X1', DX=1.0e-3))
SIDE = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FY=30.0))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 2.0, 3.0, 3.0, 2.0))
TRAC = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FX=100.0))
FR = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 2.0, 2.0, 2.4, 3.0, 0.4))
)";

double maxAbs(const Field& f) {
  double m = 0.0;
  for (double v : f.values()) {
    m = std::max(m, std::fabs(v));
  }
  return m;
}

double maxDifference(const Field& a, const Field& b) {
  EXPECT_EQ(a.values().size(), b.values().size());
  double m = 0.0;
  for (std::size_t i = 0; i < std::min(a.values().size(), b.values().size()); ++i) {
    m = std::max(m, std::fabs(a.values()[i] - b.values()[i]));
  }
  return m;
}

std::vector<double> storedTimes(const Result& r) {
  std::vector<double> t;
  for (const auto& s : r.steps) {
    t.push_back(s.time);
  }
  return t;
}

// SIXX, the same at every Gauss point for the uniaxial pull.
double sixx(const Result& r, double time) {
  const ResultStep* s = r.stepAtTime(time);
  EXPECT_NE(s, nullptr) << "no step at INST " << time;
  if (s == nullptr) {
    return 0.0;
  }
  const Field* f = s->field("SIEF_ELGA");
  const double v = f->value(0, 0);
  for (std::size_t p = 0; p < f->entityCount(); ++p) {
    EXPECT_NEAR(f->value(p, 0), v, 1e-9 * std::fabs(v));
  }
  return v;
}

int iterations(const Result& r, double time) {
  const ResultStep* s = r.stepAtTime(time);
  return s == nullptr ? -1 : static_cast<int>(s->parameters.at("ITER_GLOB"));
}

// Traction 0 -> 2 (sigma 0 -> 240) in two steps with the elastic matrix: under force control the
// plastic part converges by a factor of about 1 - ET/E = 0.9 per iteration; the step 1 -> 2 needs
// about 125 iterations, each quarter of it 111 or 112 (measured).
std::string cuttingStudy(const std::string& echec, int iterElas) {
  return kPreamble + R"(
LI = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 1.0, 2.0)), ECHEC=_F()" +
         echec + R"())
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                  COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), NEWTON=_F(MATRICE='ELASTIQUE'),
                  CONVERGENCE=_F(ITER_GLOB_ELAS=)" +
         std::to_string(iterElas) + R"(), INCREMENT=_F(LIST_INST=LI))
FIN()
)";
}

TEST(StatNonLineDriver, FailedStepIsCutAndTheSubStepsAreStored) {
  auto run = runStudy(
      "cut", cuttingStudy("EVENEMENT='ERREUR', ACTION='DECOUPE', SUBD_PAS=4, SUBD_NIVEAU=2", 118), kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto r = run->result("R");
  ASSERT_TRUE(r);
  // 1 -> 2 fails with 118 iterations; its quarters converge and are archived (PAS_ARCH=1).
  EXPECT_EQ(storedTimes(*r), (std::vector<double>{0.0, 1.0, 1.25, 1.5, 1.75, 2.0})) << run->mess();
  EXPECT_NEAR(sixx(*r, 1.0), 200.0, 1e-3);
  EXPECT_NEAR(sixx(*r, 1.25), 210.0, 1e-3); // FR(1.25) = 2.1
  EXPECT_NEAR(sixx(*r, 2.0), 240.0, 1e-3);
  EXPECT_NE(run->mess().find("step INST 1 -> 2 failed (Newton did not converge in 118 iterations"),
            std::string::npos)
      << run->mess();
  EXPECT_NE(run->mess().find("step cut into 4 sub-steps of 0.25 (subdivision level 1 of SUBD_NIVEAU=2)"),
            std::string::npos);
  EXPECT_NE(run->mess().find("step 2 INST 1.25 (sub-step, level 1): converged"), std::string::npos);
}

TEST(StatNonLineDriver, ArretStopsWithNoConvergenceAndKeepsConvergedSteps) {
  auto run = runStudy("arret", cuttingStudy("EVENEMENT='ERREUR', ACTION='ARRET'", 60), kMesh);
  EXPECT_EQ(run->failure(), FailureKind::NoConvergence) << run->mess();
  EXPECT_NE(run->mess().find("step 1 INST 1: converged in 0 iteration(s), RESI_GLOB_RELA"),
            std::string::npos);
  EXPECT_NE(run->mess().find("no further cut: DEFI_LIST_INST ECHEC ACTION='ARRET'"), std::string::npos)
      << run->mess();
  EXPECT_NE(run->mess().find("R: 1 converged step(s) computed, 2 stored, up to INST 1"), std::string::npos);
}

TEST(StatNonLineDriver, FailureAfterAllCutsNamesTheLimit) {
  // 10 iterations are too few for any sub-step of the plastic range at level 1.
  auto run = runStudy("levels", cuttingStudy("SUBD_PAS=2, SUBD_NIVEAU=1", 10), kMesh);
  EXPECT_EQ(run->failure(), FailureKind::NoConvergence);
  EXPECT_NE(run->mess().find("no further cut: SUBD_NIVEAU=1 levels of subdivision reached"),
            std::string::npos)
      << run->mess();
  // Every converged step kept: the initial state and INST 1.
  EXPECT_NE(run->mess().find("R: 1 converged step(s) computed, 2 stored, up to INST 1"), std::string::npos);
}

TEST(StatNonLineDriver, SubdPasMiniForbidsShortSubSteps) {
  auto run = runStudy("mini", cuttingStudy("SUBD_PAS=4, SUBD_NIVEAU=3, SUBD_PAS_MINI=0.5", 60), kMesh);
  EXPECT_EQ(run->failure(), FailureKind::NoConvergence);
  EXPECT_NE(run->mess().find("a sub-step of 0.25 would be shorter than SUBD_PAS_MINI=0.5"), std::string::npos)
      << run->mess();
}

// A bending, plastic state (DX imposed and FY applied on X1).
std::string bendingRun(const std::string& target, const std::string& extra) {
  return target + " = STAT_NON_LINE(" + extra +
         "MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP), _F(CHARGE=SIDE, "
         "FONC_MULT=RAMP)),\n"
         "    COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-10),\n"
         "    INCREMENT=_F(LIST_INST=TIMES";
}

TEST(StatNonLineDriver, RestartWithReuseEqualsOneRun) {
  const std::string comm =
      kPreamble + "TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.5, NOMBRE=12))\n" +
      bendingRun("ONE", "") + ", INST_FIN=1.0))\n" + bendingRun("TWO", "") + ", INST_FIN=0.5))\n" +
      bendingRun("TWO", "reuse=TWO, RESULTAT=TWO, ETAT_INIT=_F(EVOL_NOLI=TWO), ") + ", INST_FIN=1.0))\n" +
      bendingRun("THREE", "") + ", INST_FIN=0.5))\n" + bendingRun("THREE", "reuse=THREE, ") +
      ", INST_INIT=0.5, INST_FIN=1.0))\nFIN()\n";
  auto run = runStudy("restart", comm, kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto one = run->result("ONE");
  ASSERT_TRUE(one);
  for (const char* name : {"TWO", "THREE"}) {
    auto two = run->result(name);
    ASSERT_TRUE(two);
    ASSERT_EQ(storedTimes(*two), storedTimes(*one)) << name;
    for (std::size_t i = 0; i < one->steps.size(); ++i) {
      EXPECT_EQ(two->steps[i].number, static_cast<int>(i));
      for (const char* field : {"DEPL", "SIEF_ELGA", "VARI_ELGA"}) {
        const Field& a = *one->steps[i].field(field);
        const Field& b = *two->steps[i].field(field);
        EXPECT_LE(maxDifference(a, b), 1e-10 * std::max(maxAbs(a), 1e-300))
            << name << " " << field << " at INST " << one->steps[i].time;
      }
    }
  }
  // The state is plastic by INST 1: the restart carried internal variables.
  EXPECT_GT(maxAbs(*one->steps.back().field("VARI_ELGA")), 1e-4);
}

TEST(StatNonLineDriver, ArchivageSelectsStepsAndAlwaysTheFirstAndLast) {
  const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=2.0, NOMBRE=10))
KEEP = DEFI_LIST_REEL(VALE=(0.6, 1.0))
EVERY = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                      COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), INCREMENT=_F(LIST_INST=TIMES),
                      ARCHIVAGE=_F(PAS_ARCH=3))
SOME = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                     COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), INCREMENT=_F(LIST_INST=TIMES),
                     ARCHIVAGE=_F(LIST_INST=KEEP))
ONE = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                    COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), INCREMENT=_F(LIST_INST=TIMES),
                    ARCHIVAGE=_F(INST=1.4000001, CRITERE='ABSOLU', PRECISION=1.0e-6))
FIN()
)";
  auto run = runStudy("archive", comm, kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto every = run->result("EVERY");
  ASSERT_TRUE(every);
  ASSERT_EQ(every->steps.size(), 5u); // 0, steps 3, 6, 9, and the last (10)
  EXPECT_NEAR(every->steps[1].time, 0.6, 1e-12);
  EXPECT_NEAR(every->steps[3].time, 1.8, 1e-12);
  EXPECT_NEAR(every->steps[4].time, 2.0, 1e-12);
  EXPECT_EQ(every->steps[4].number, 4);
  EXPECT_NEAR(sixx(*every, 2.0), 240.0, 1e-6);
  auto some = run->result("SOME");
  ASSERT_TRUE(some);
  ASSERT_EQ(some->steps.size(), 4u); // 0, 0.6, 1.0, 2.0
  EXPECT_NEAR(some->steps[2].time, 1.0, 1e-12);
  EXPECT_NEAR(sixx(*some, 1.0), 200.0, 1e-6);
  auto one = run->result("ONE");
  ASSERT_TRUE(one);
  ASSERT_EQ(one->steps.size(), 3u); // 0, 1.4 (within 1e-6 absolute), 2.0
  EXPECT_NEAR(one->steps[1].time, 1.4, 1e-12);
  EXPECT_NE(run->mess().find("not stored (ARCHIVAGE)"), std::string::npos);
}

TEST(StatNonLineDriver, ExtrapolatedAndComputedPredictions) {
  const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=2.0, NOMBRE=8))
BASE = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP), _F(CHARGE=SIDE, FONC_MULT=RAMP)),
                     COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), INCREMENT=_F(LIST_INST=TIMES),
                     CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-10))
ELAS = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP), _F(CHARGE=SIDE, FONC_MULT=RAMP)),
                     INCREMENT=_F(LIST_INST=TIMES, INST_FIN=1.0), NEWTON=_F(PREDICTION='EXTRAPOLE'))
COPY = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP), _F(CHARGE=SIDE, FONC_MULT=RAMP)),
                     COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), INCREMENT=_F(LIST_INST=TIMES),
                     CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-8),
                     NEWTON=_F(PREDICTION='DEPL_CALCULE', EVOL_NOLI=BASE))
FIN()
)";
  auto run = runStudy("predict", comm, kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  // Linear elasticity, proportional loading: the extrapolated increment is the solution, so
  // every step but the first converges at the prediction (iteration 0).
  auto elas = run->result("ELAS");
  ASSERT_TRUE(elas);
  ASSERT_EQ(elas->steps.size(), 5u);
  EXPECT_EQ(iterations(*elas, 0.25), 0); // first step: tangent prediction, linear problem
  for (double t : {0.5, 0.75, 1.0}) {
    EXPECT_EQ(iterations(*elas, t), 0) << t;
  }
  // The displacement of a converged plastic run predicts every step of the same run exactly; one
  // correction finds the reactions (the stored DEPL carries no multipliers).
  auto base = run->result("BASE");
  auto copy = run->result("COPY");
  ASSERT_TRUE(base && copy);
  int baseIterations = 0;
  for (std::size_t i = 1; i < copy->steps.size(); ++i) {
    EXPECT_LE(static_cast<int>(copy->steps[i].parameters.at("ITER_GLOB")), 1) << copy->steps[i].time;
    baseIterations += static_cast<int>(base->steps[i].parameters.at("ITER_GLOB"));
    const Field& a = *base->steps[i].field("SIEF_ELGA");
    EXPECT_LE(maxDifference(a, *copy->steps[i].field("SIEF_ELGA")), 1e-6 * maxAbs(a));
  }
  EXPECT_GT(baseIterations, 8); // the plastic run itself needed more than one correction a step
}

// The number of matrices the driver had factorised for the last STAT_NON_LINE, as its message
// file reports them: the factorisations plus the times the factors of an unchanged matrix were
// kept ("the factors kept N time(s)").
int factorisations(const std::string& mess) {
  std::smatch m;
  int last = -1;
  std::string::const_iterator from = mess.begin();
  static const std::regex re(
      "linear solver: [A-Z_]+, ([0-9]+) factorisation\\(s\\)( \\(the factors kept ([0-9]+) time)?");
  while (std::regex_search(from, mess.end(), m, re)) {
    last = std::stoi(m[1]) + (m[3].matched ? std::stoi(m[3]) : 0);
    from = m[0].second;
  }
  return last;
}

// The factorisations actually done (the factors of an unchanged matrix are kept).
int factorisationsDone(const std::string& mess) {
  std::smatch m;
  int last = -1;
  std::string::const_iterator from = mess.begin();
  static const std::regex re("linear solver: [A-Z_]+, ([0-9]+) factorisation");
  while (std::regex_search(from, mess.end(), m, re)) {
    last = std::stoi(m[1]);
    from = m[0].second;
  }
  return last;
}

TEST(StatNonLineDriver, ReacIncrCountsThePredictionMatrices) {
  // Linear elasticity in 8 steps, no update during the iterations (REAC_ITER=0): the prediction
  // matrix is factorised every REAC_INCR steps, or once with REAC_INCR=0.
  for (auto [reacIncr, expected] : {std::pair{1, 8}, std::pair{3, 3}, std::pair{0, 1}}) {
    const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=8))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP), _F(CHARGE=SIDE, FONC_MULT=RAMP)),
                  INCREMENT=_F(LIST_INST=TIMES), NEWTON=_F(REAC_ITER=0, REAC_INCR=)" +
                             std::to_string(reacIncr) + R"())
FIN()
)";
    auto run = runStudy("reacincr", comm, kMesh);
    ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
    EXPECT_EQ(factorisations(run->mess()), expected) << "REAC_INCR=" << reacIncr;
    // linear elasticity: every prediction matrix is the first one, factorised once
    EXPECT_EQ(factorisationsDone(run->mess()), 1) << "REAC_INCR=" << reacIncr;
    // the phase line of the command: its phases add up to the command's time
    std::smatch m;
    const std::string mess = run->mess();
    ASSERT_TRUE(std::regex_search(mess, m,
                                  std::regex("phases \\(s\\): numbering ([0-9.]+), assembly ([0-9.]+), "
                                             "factorisation ([0-9.]+) \\(1 analysis\\), solve ([0-9.]+), "
                                             "post ([0-9.]+)(, other ([0-9.]+))?; total ([0-9.]+)")))
        << mess;
    double sum = 0.0;
    for (int i : {1, 2, 3, 4, 5, 7}) {
      sum += m[i].matched ? std::stod(m[i]) : 0.0;
    }
    EXPECT_NEAR(sum, std::stod(m[8]), 0.006); // each printed with 3 decimals
  }
}

TEST(StatNonLineDriver, LineSearchConvergesWherePlainModifiedNewtonDoesNot) {
  // The elastic matrix in the plastic range under force control converges slowly (about 125
  // iterations for 1 -> 2); the secant line search along the correction needs 6 (measured).
  const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
LI = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=TIMES), ECHEC=_F(ACTION='ARRET'))
PLAIN = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                      COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), NEWTON=_F(MATRICE='ELASTIQUE'),
                      CONVERGENCE=_F(ITER_GLOB_ELAS=25), INCREMENT=_F(LIST_INST=LI))
)";
  auto plain = runStudy("plain", comm + "FIN()\n", kMesh);
  EXPECT_EQ(plain->failure(), FailureKind::NoConvergence) << plain->mess();
  const std::string searched = kPreamble + R"(
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
LI = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=TIMES), ECHEC=_F(ACTION='ARRET'))
LS = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=FR)),
                   COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'), NEWTON=_F(MATRICE='ELASTIQUE'),
                   CONVERGENCE=_F(ITER_GLOB_ELAS=25), INCREMENT=_F(LIST_INST=LI),
                   RECH_LINEAIRE=_F(METHODE='CORDE', ITER_LINE_MAXI=3))
FIN()
)";
  auto ls = runStudy("linesearch", searched, kMesh);
  ASSERT_EQ(ls->failure(), FailureKind::None) << ls->mess();
  auto r = ls->result("LS");
  EXPECT_NEAR(sixx(*r, 2.0), 240.0, 1e-3);
  EXPECT_LE(iterations(*r, 2.0), 12) << ls->mess();
  EXPECT_NE(ls->mess().find("| RHO      |"), std::string::npos);
}

TEST(StatNonLineDriver, LineSearchMethodsOtherThanCordeAreRefused) {
  const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                  INCREMENT=_F(LIST_INST=TIMES), RECH_LINEAIRE=_F(METHODE='MIXTE'))
FIN()
)";
  auto run = runStudy("mixte", comm, kMesh);
  EXPECT_EQ(run->failure(), FailureKind::Error);
  EXPECT_NE(run->mess().find("METHODE='MIXTE' in RECH_LINEAIRE of STAT_NON_LINE is not implemented yet"),
            std::string::npos)
      << run->mess();
}

// A relation whose material lacks its parameters is refused at the RELATION keyword (line 20,
// column 35), not at STAT_NON_LINE's name (line 18).
TEST(StatNonLineDriver, RelationWithoutItsMaterialParametersIsLocatedAtRelation) {
  const std::string comm = kPreamble +
                           "SOFT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))\n"
                           "CS = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=SOFT))\n"
                           "TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0))\n"
                           "R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CS, EXCIT=_F(CHARGE=BC),\n"
                           "                  INCREMENT=_F(LIST_INST=TIMES),\n"
                           "                  COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI'))\n"
                           "FIN()\n";
  auto run = runStudy("no_ecro", comm, kMesh);
  EXPECT_EQ(run->failure(), FailureKind::Error);
  EXPECT_NE(run->mess().find("MATER_8"), std::string::npos) << run->mess();
  EXPECT_NE(run->mess().find(":20:35: error: RELATION='VMIS_ISOT_LINE' on cell"), std::string::npos)
      << run->mess();
}

// GROT_GDEP on a mean-dilatation (3D_SI) cell: not implemented, refused at DEFORMATION (line 18,
// column 52) with SNL_13, before anything is computed.
TEST(StatNonLineDriver, GrotGdepOnMeanDilatationCellsIsRefusedAtDeformation) {
  const std::string comm =
      kPreamble +
      "MOSI = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', "
      "MODELISATION='3D_SI'))\n"
      "TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0))\n"
      "R = STAT_NON_LINE(MODELE=MOSI, CHAM_MATER=CM, EXCIT=_F(CHARGE=BC), INCREMENT=_F(LIST_INST=TIMES),\n"
      "                  COMPORTEMENT=_F(RELATION='ELAS', DEFORMATION='GROT_GDEP', TOUT='OUI'))\n"
      "FIN()\n";
  auto run = runStudy("grot_si", comm, kMesh);
  EXPECT_EQ(run->failure(), FailureKind::Error);
  EXPECT_NE(run->mess().find("SNL_13"), std::string::npos) << run->mess();
  EXPECT_NE(run->mess().find(":18:52: error: DEFORMATION='GROT_GDEP' on the mean-dilatation cell"),
            std::string::npos)
      << run->mess();
}

TEST(StatNonLineDriver, NumeInstWindow) {
  const std::string comm = kPreamble + R"(
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=2.0, NOMBRE=8))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                  COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE'),
                  INCREMENT=_F(LIST_INST=TIMES, NUME_INST_INIT=0, NUME_INST_FIN=4))
BAD = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                    INCREMENT=_F(LIST_INST=TIMES, NUME_INST_FIN=9))
FIN()
)";
  auto run = runStudy("nume", comm, kMesh);
  auto r = run->result("R");
  ASSERT_TRUE(r);
  EXPECT_EQ(storedTimes(*r), (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_NE(run->mess().find("INCREMENT NUME_INST_FIN=9 is outside the list of instants (0 to 8)"),
            std::string::npos)
      << run->mess();
}

} // namespace
} // namespace stella

namespace stella {
namespace {

// The ssnv506-like indentation with the mean-dilatation AXIS_SI cells on a coarse mesh (contact
// cells of 50 mm): perfectly plastic cells that flow freely leave the prediction tangent of a
// later step singular (a null pivot at a free surface node by the contact). A shorter step
// cannot change that matrix (the tangent of the last converged state), so the run stops with
// SOLVE_1, results kept; its first note says that the plastic state is the likely cause and
// what to do (MATRICE='ELASTIQUE'), before the notes on free motions.
TEST(StatNonLineDriver, SingularPredictionAfterPlasticFlowNamesThePlasticState) {
  const std::string comm = R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('S_CONT', 'M_CONT')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='AXIS_SI'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.1e7, NU=0.3))
MASSIF = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.3), ECRO_LINE=_F(SY=50.0, D_SIGM_EPSI=0.0))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=(_F(GROUP_MA='SPHERE', MATER=ACIER), _F(GROUP_MA='MASSIF', MATER=MASSIF)))
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(NOM='M_AXE_L', DIFFE=('M_AXE', 'M_BASE')))
APPUIS = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='M_BASE', DX=0.0, DY=0.0),
                                              _F(GROUP_NO=('M_AXE_L', 'S_AXE'), DX=0.0)))
ENFONCE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='S_TOP', DY=-100.0))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=(_F(JUSQU_A=0.01, NOMBRE=5), _F(JUSQU_A=0.15, NOMBRE=24),
                                               _F(JUSQU_A=1.0, NOMBRE=17)))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='S_CONT', GROUP_MA_ESCL='M_CONT'))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT,
                     EXCIT=(_F(CHARGE=APPUIS), _F(CHARGE=ENFONCE, FONC_MULT=RAMPE)),
                     COMPORTEMENT=(_F(RELATION='VMIS_ISOT_LINE', GROUP_MA='MASSIF'),
                                   _F(RELATION='ELAS', GROUP_MA='SPHERE')),
                     INCREMENT=_F(LIST_INST=L_INST), CONVERGENCE=_F(ITER_GLOB_MAXI=30))
FIN()
)";
  auto run =
      testing::runStudy("singular_prediction", comm, "solver/nonlinear/tests/data/indentation_h50.msh");
  const std::string mess = run->mess();
  EXPECT_EQ(run->failure(), FailureKind::Error) << mess.substr(mess.size() > 3000 ? mess.size() - 3000 : 0);
  const auto solve = mess.find("[SOLVE_1]");
  ASSERT_NE(solve, std::string::npos);
  const auto plastic = mess.find("the matrix is the tangent of the last converged state", solve);
  const auto freeMotion = mess.find("block the free motions", solve);
  ASSERT_NE(plastic, std::string::npos);
  EXPECT_LT(plastic, freeMotion); // the likely cause first
  EXPECT_NE(mess.find("MATRICE='ELASTIQUE'", solve), std::string::npos);
  // the converged steps are kept, and the session says so (the end of the message file of a job)
  const auto& kept = run->session->keptResults();
  ASSERT_EQ(kept.size(), 1u);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(kept[0], m, std::regex("RESU: ([0-9]+) step\\(s\\) stored, up to INST")))
      << kept[0];
  EXPECT_GT(std::stoi(m[1]), 30);
}

} // namespace
} // namespace stella
