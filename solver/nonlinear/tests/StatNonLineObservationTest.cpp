// OBSERVATION, MESURE and AFFICHAGE of STAT_NON_LINE, and RECU_TABLE. The study: the elastic unit
// cube of testcases/plate_plasticity (HEXA8, E = 200000, NU = 0.3, symmetry planes X0, Y0, Z0)
// pulled on X1 by a traction 100 t (t = 0, 0.5, 1, 1.5, 2): uniaxial stress SIXX = 100 t, so
// DX = 5e-4 t x and DY = -NU 5e-4 t y = -1.5e-4 t y (closed form, exact for HEXA8).

#include "solver/database/ConceptStore.hpp"
#include "solver/nonlinear/tests/StudyRun.hpp"
#include "solver/post/Table.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>

namespace stella {
namespace {

using testing::runStudy;
using testing::StudyRun;

const char* kMesh = "testcases/plate_plasticity/hexa8.msh";

std::string study(const std::string& extra, const std::string& after = "",
                  const std::string& increment = "INCREMENT=_F(LIST_INST=L)") {
  return R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
STEEL = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=STEEL))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
TRAC = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='X1', FX=100.0))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 2.0, 2.0))
L = DEFI_LIST_REEL(VALE=(0.0, 0.5, 1.0, 1.5, 2.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=RAMP)),
                  CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-10), )" +
         increment + ", " + extra + R"()
)" + after +
         R"(
FIN()
)";
}

std::shared_ptr<Table> table(const StudyRun& run, const std::string& name) {
  return run.session->concepts().findData<Table>(name);
}

// Rows of a table whose text column `column` is `text`.
std::vector<std::size_t> rowsWith(const Table& t, const std::string& column, const std::string& text) {
  std::vector<std::size_t> rows;
  const Table::Column* c = t.column(column);
  for (std::size_t r = 0; c != nullptr && r < c->cells.size(); ++r) {
    if (c->cells[r].isString() && c->cells[r].asString() == text) {
      rows.push_back(r);
    }
  }
  return rows;
}

double real(const Table& t, const std::string& column, std::size_t row) {
  return t.column(column)->cells.at(row).asReal();
}

TEST(StatNonLineObservation, DyAtANodeMatchesTheClosedFormAtEachInstant) {
  // N3 is the node (1, 1, 0): DY = -1.5e-4 t. TEST_TABLE checks each instant in the command file.
  std::string tests;
  for (double t : {0.0, 0.5, 1.0, 1.5, 2.0}) {
    const double dy = -1.5e-4 * t;
    tests += fmt::format(
        "TEST_TABLE(TABLE=T, NOM_PARA='VALE', FILTRE=(_F(NOM_PARA='NOM_OBSERVATION', VALE_K='DY_N3'), "
        "_F(NOM_PARA='INST', VALE={0}, CRITERE='ABSOLU', PRECISION=1.0e-9)), VALE_CALC={1:.17g}, "
        "CRITERE='ABSOLU', TOLE_MACHINE=1.0e-12, REFERENCE='ANALYTIQUE', VALE_REFE={1:.17g}, "
        "PRECISION=1.0e-12)\n",
        t, dy);
  }
  auto run = runStudy("obs_dy",
                      study("OBSERVATION=(_F(NOM_CHAM='DEPL', NOM_CMP='DY', NOEUD='N3', TITRE='DY_N3'),"
                            " _F(NOM_CHAM='DEPL', NOM_CMP=('DX', 'DY'), GROUP_MA='X1', EVAL_CHAM='MAX',"
                            " PAS_OBSE=2, OBSE_ETAT_INIT='NON'),"
                            " _F(NOM_CHAM='SIEF_ELGA', NOM_CMP='SIXX', GROUP_MA='ALL', EVAL_ELGA='MAX',"
                            " EVAL_CHAM='MIN', INST=1.0),"
                            " _F(NOM_CHAM='SIEF_ELGA', NOM_CMP='SIYY', TOUT='OUI', POINT=(1, 8),"
                            " LIST_INST=L, OBSE_ETAT_INIT='NON', TITRE='SIYY'))",
                            "T = RECU_TABLE(CO=R, NOM_TABLE='OBSERVATION')\n" + tests),
                      kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_EQ(run->session->counts().testsNook, 0) << run->mess();
  EXPECT_EQ(run->session->counts().testsOk, 10) << run->mess(); // VALE_CALC and ANALYTIQUE lines
  auto t = table(*run, "T");
  ASSERT_TRUE(t);
  // DY_N3: the initial state and the 4 steps.
  const auto dy = rowsWith(*t, "NOM_OBSERVATION", "DY_N3");
  ASSERT_EQ(dy.size(), 5u);
  EXPECT_EQ(t->column("NOEUD")->cells[dy[0]].asString(), "N3");
  EXPECT_EQ(t->column("NUME_REUSE")->cells[dy[0]].asInt(), 0);
  // The second occurrence: steps 2 and 4 (PAS_OBSE=2, no initial state), MAX of DX and DY on X1:
  // DX = 5e-4 t everywhere on X1, DY = -1.5e-4 t y is largest (0) at y = 0.
  const auto mx = rowsWith(*t, "NOM_OBSERVATION", "OBSERVATION_2");
  ASSERT_EQ(mx.size(), 4u);
  EXPECT_DOUBLE_EQ(real(*t, "INST", mx[0]), 1.0);
  EXPECT_EQ(t->column("NOM_CMP")->cells[mx[0]].asString(), "DX");
  EXPECT_NEAR(real(*t, "VALE", mx[0]), 5.0e-4, 1.0e-14);
  EXPECT_NEAR(real(*t, "VALE", mx[1]), 0.0, 1.0e-14);
  EXPECT_DOUBLE_EQ(real(*t, "INST", mx[2]), 2.0);
  EXPECT_NEAR(real(*t, "VALE", mx[2]), 1.0e-3, 1.0e-14);
  EXPECT_EQ(t->column("EVAL_CHAM")->cells[mx[0]].asString(), "MAX");
  // The third: SIXX = 100 t at every point, observed at INST 1 only (and the initial state).
  const auto sx = rowsWith(*t, "NOM_OBSERVATION", "OBSERVATION_3");
  ASSERT_EQ(sx.size(), 2u);
  EXPECT_NEAR(real(*t, "VALE", sx[0]), 0.0, 1.0e-9);
  EXPECT_NEAR(real(*t, "VALE", sx[1]), 100.0, 1.0e-8);
  EXPECT_EQ(t->column("EVAL_ELGA")->cells[sx[1]].asString(), "MAX");
  // The fourth: SIYY = 0 at points 1 and 8 of each volume cell, at the 4 instants of L after 0.
  const Field& sief = *run->result("R")->steps.back().field("SIEF_ELGA");
  std::size_t volumeCells = 0;
  for (std::size_t c = 0; c < sief.cellCount(); ++c) {
    volumeCells += sief.pointCount(c) > 0 ? 1 : 0;
  }
  const auto sy = rowsWith(*t, "NOM_OBSERVATION", "SIYY");
  ASSERT_EQ(sy.size(), 4u * volumeCells * 2u);
  EXPECT_EQ(t->column("POINT")->cells[sy[1]].asInt(), 8);
  for (std::size_t r : sy) {
    EXPECT_NEAR(real(*t, "VALE", r), 0.0, 1.0e-8);
  }
}

TEST(StatNonLineObservation, ContinuationAppendsWithTheNextNumeReuse) {
  // 0 -> 1, then reuse= 1 -> 2: DX at N3 (x = 1) is 5e-4 t; the continuation's rows have NUME_REUSE 1.
  auto run =
      runStudy("obs_reuse",
               study("OBSERVATION=_F(NOM_CHAM='DEPL', NOM_CMP='DX', NOEUD='N3')",
                     "R = STAT_NON_LINE(reuse=R, RESULTAT=R, MODELE=MO, CHAM_MATER=CM,"
                     " EXCIT=(_F(CHARGE=BC), _F(CHARGE=TRAC, FONC_MULT=RAMP)), INCREMENT=_F(LIST_INST=L),"
                     " OBSERVATION=_F(NOM_CHAM='DEPL', NOM_CMP='DX', NOEUD='N3', OBSE_ETAT_INIT='NON'))\n"
                     "T = RECU_TABLE(CO=R, NOM_TABLE='OBSERVATION')\n",
                     "INCREMENT=_F(LIST_INST=L, INST_FIN=1.0)"),
               kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto t = table(*run, "T");
  ASSERT_TRUE(t);
  ASSERT_EQ(t->rowCount(), 5u);
  const std::vector<double> times{0.0, 0.5, 1.0, 1.5, 2.0};
  for (std::size_t r = 0; r < 5; ++r) {
    EXPECT_DOUBLE_EQ(real(*t, "INST", r), times[r]);
    EXPECT_NEAR(real(*t, "VALE", r), 5.0e-4 * times[r], 1.0e-14);
    EXPECT_EQ(t->column("NUME_REUSE")->cells[r].asInt(), r < 3 ? 0 : 1);
    EXPECT_EQ(t->column("NUME_OBSE")->cells[r].asInt(), static_cast<std::int64_t>(r + 1));
  }
}

// CONT_NOEU of the friction block of testcases/friction_block: every slave node sticks (CONT = 1)
// at t = 1.5 and slides (CONT = 2) at t = 3 (the closed form of that case's README).
TEST(StatNonLineObservation, ContactStatusOfTheFrictionBlock) {
  const std::string comm = R"(
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
                            E_N=1.0e4, ALGO_FROT='PENALISATION', E_T=1.0e4, COULOMB=0.2))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT,
                  EXCIT=(_F(CHARGE=SOL), _F(CHARGE=PRESSE, FONC_MULT=F_N), _F(CHARGE=CISAILLE, FONC_MULT=F_T)),
                  INCREMENT=_F(LIST_INST=L_INST), CONVERGENCE=_F(ITER_GLOB_MAXI=30),
                  OBSERVATION=(_F(NOM_CHAM='CONT_NOEU', NOM_CMP='CONT', GROUP_MA='BLOC_BAS', EVAL_CHAM='MIN',
                                  INST=(1.5, 3.0), TITRE='MIN'),
                               _F(NOM_CHAM='CONT_NOEU', NOM_CMP='CONT', GROUP_MA='BLOC_BAS', EVAL_CHAM='MAX',
                                  INST=(1.5, 3.0), TITRE='MAX')))
T = RECU_TABLE(CO=R, NOM_TABLE='OBSERVATION')
FIN()
)";
  auto run = runStudy("obs_contact", comm, "testcases/friction_block/friction_block.msh");
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto t = table(*run, "T");
  ASSERT_TRUE(t);
  for (const char* kind : {"MIN", "MAX"}) {
    const auto rows = rowsWith(*t, "NOM_OBSERVATION", kind);
    // the initial state (OBSE_ETAT_INIT='OUI': no contact yet, CONT = 0), t = 1.5, t = 3
    ASSERT_EQ(rows.size(), 3u) << kind;
    EXPECT_DOUBLE_EQ(real(*t, "INST", rows[1]), 1.5);
    EXPECT_DOUBLE_EQ(real(*t, "VALE", rows[0]), 0.0) << kind;
    EXPECT_DOUBLE_EQ(real(*t, "VALE", rows[1]), 1.0) << kind;
    EXPECT_DOUBLE_EQ(real(*t, "VALE", rows[2]), 2.0) << kind;
  }
}

TEST(StatNonLineObservation, RefusesWhatIsNotImplementedByName) {
  auto vari =
      runStudy("obs_vari",
               study("OBSERVATION=_F(NOM_CHAM='VARI_ELGA', NOM_VARI='EPSPEQ', TOUT='OUI', POINT=1)"), kMesh);
  EXPECT_EQ(vari->failure(), FailureKind::Error);
  EXPECT_NE(vari->mess().find("keyword NOM_VARI of OBSERVATION of STAT_NON_LINE is not implemented yet"),
            std::string::npos)
      << vari->mess();
  auto vite = runStudy("obs_vite", study("OBSERVATION=_F(NOM_CHAM='VITE', NOM_CMP='DX', TOUT='OUI')"), kMesh);
  EXPECT_NE(vite->mess().find("NOM_CHAM='VITE' in OBSERVATION of STAT_NON_LINE is not implemented yet"),
            std::string::npos)
      << vite->mess();
  auto cmp = runStudy("obs_cmp", study("OBSERVATION=_F(NOM_CHAM='DEPL', NOM_CMP='DRX', NOEUD='N3')"), kMesh);
  EXPECT_EQ(cmp->failure(), FailureKind::Error);
  EXPECT_NE(cmp->mess().find("SNL_20"), std::string::npos) << cmp->mess();
  EXPECT_NE(cmp->mess().find("available: DX, DY, DZ"), std::string::npos) << cmp->mess();
  auto none = runStudy("obs_none", study("", "T = RECU_TABLE(CO=R, NOM_TABLE='OBSERVATION')\n"), kMesh);
  EXPECT_EQ(none->failure(), FailureKind::Error);
  EXPECT_NE(none->mess().find("TABLE_7"), std::string::npos) << none->mess();
}

TEST(StatNonLineMesure, TableHasOneRowPerStepWhosePartsAddUp) {
  auto run = runStudy(
      "mesure", study("MESURE=_F(TABLE='OUI', UNITE=38)", "T = RECU_TABLE(CO=R, NOM_TABLE='STAT')\n"), kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  auto t = table(*run, "T");
  ASSERT_TRUE(t);
  ASSERT_EQ(t->rowCount(), 4u);
  auto r = run->result("R");
  for (std::size_t row = 0; row < 4; ++row) {
    const double step = real(*t, "Time_Time_Step", row);
    EXPECT_DOUBLE_EQ(real(*t, "INST", row), 0.5 * static_cast<double>(row + 1));
    EXPECT_GT(step, 0.0);
    double parts = 0.0;
    for (const char* c : {"Time_Integrate", "Time_Factor", "Time_Solve", "Time_Other"}) {
      EXPECT_GE(real(*t, c, row), 0.0) << c;
      parts += real(*t, c, row);
    }
    EXPECT_NEAR(parts, step, 1.0e-9 * step + 1.0e-12);
    EXPECT_GT(real(*t, "Time_Integrate", row), 0.0);
    EXPECT_EQ(t->column("Count_Newt_Iter")->cells[row].asInt(),
              static_cast<std::int64_t>(r->steps[row + 1].parameters.at("ITER_GLOB")));
  }
  // The unit file has the table too.
  const auto path = run->session->unitPath(38, SourceLocation{}, false);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path); // the units append: the next run starts afresh
  EXPECT_NE(text.str().find("Time_Time_Step"), std::string::npos) << text.str();
  EXPECT_NE(run->mess().find("MESURE: the table of the step times (4 rows) written to unit 38"),
            std::string::npos);
}

// The instants whose convergence table a text has ("   INST <t>" at the head of each table).
std::vector<std::string> tableInstants(const std::string& text) {
  std::vector<std::string> out;
  const std::regex head("^   INST (\\S+)\\s*$");
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, head)) {
      out.push_back(m[1]);
    }
  }
  return out;
}

TEST(StatNonLineAffichage, PasSelectsTheTablesAndUniteCopiesThemAll) {
  auto every = runStudy("affi_all", study("AFFICHAGE=_F(INFO_RESIDU='OUI')"), kMesh);
  ASSERT_EQ(every->failure(), FailureKind::None) << every->mess();
  EXPECT_EQ(tableInstants(every->mess()), (std::vector<std::string>{"0.5", "1", "1.5", "2"}));
  EXPECT_NE(every->mess().find("WHERE (MAXI)"), std::string::npos);
  auto pas = runStudy("affi_pas", study("AFFICHAGE=_F(PAS=2, UNITE=39)"), kMesh);
  ASSERT_EQ(pas->failure(), FailureKind::None) << pas->mess();
  EXPECT_EQ(tableInstants(pas->mess()), (std::vector<std::string>{"0.5", "1.5"})) << pas->mess();
  // Every step is still reported on its line.
  EXPECT_NE(pas->mess().find("step 4 INST 2: converged"), std::string::npos);
  const auto path = pas->session->unitPath(39, SourceLocation{}, false);
  std::ifstream in(path);
  std::stringstream unit;
  unit << in.rdbuf();
  std::filesystem::remove(path); // the units append: the next run starts afresh
  EXPECT_EQ(tableInstants(unit.str()), (std::vector<std::string>{"0.5", "1", "1.5", "2"})) << unit.str();
}

// The last iteration row of each convergence table: INST -> the cells after the fixed columns.
std::map<std::string, std::vector<std::string>> lastRows(const std::string& text) {
  std::map<std::string, std::vector<std::string>> out;
  const std::regex head("^   INST (\\S+)\\s*$");
  const std::regex row("^   \\| +\\d+ \\|.*$");
  std::string inst;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, head)) {
      inst = m[1];
    } else if (std::regex_match(line, row)) {
      std::vector<std::string> cells;
      std::istringstream cellText(line);
      for (std::string cell; std::getline(cellText, cell, '|');) {
        cells.push_back(cell);
      }
      // "   ", ITER, RELA, MAXI, WHERE, MATRIX, then the SUIVI_DDL columns
      out[inst] = std::vector<std::string>(cells.begin() + std::min<std::ptrdiff_t>(6, std::ssize(cells)),
                                           cells.end());
    }
  }
  return out;
}

TEST(StatNonLineSuiviDdl, ColumnsShowTheConvergedValues) {
  auto run = runStudy("suivi",
                      study("SUIVI_DDL=(_F(NOM_CHAM='DEPL', NOM_CMP='DY', NOEUD='N3'),"
                            " _F(NOM_CHAM='SIEF_ELGA', NOM_CMP='SIXX', TOUT='OUI', EVAL_ELGA='MAX',"
                            " EVAL_CHAM='MAX', TITRE='SIXX max'))"),
                      kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_NE(run->mess().find("| DY N3          | SIXX max       |"), std::string::npos) << run->mess();
  const auto rows = lastRows(run->mess());
  auto r = run->result("R");
  const auto node = static_cast<std::size_t>(*r->mesh->findNode("N3"));
  for (const auto& step : r->steps) {
    if (step.time == 0.0) {
      continue;
    }
    const auto it = rows.find(fmt::format("{:g}", step.time));
    ASSERT_NE(it, rows.end()) << step.time << "\n" << run->mess();
    ASSERT_EQ(it->second.size(), 2u) << run->mess();
    // The printed DY (6 digits) is the stored DEPL, and the closed form -1.5e-4 t.
    const double dy = std::stod(it->second[0]);
    const double stored = step.field("DEPL")->value(node, 1);
    EXPECT_NEAR(dy, stored, 1.0e-6 * std::fabs(stored));
    EXPECT_NEAR(dy, -1.5e-4 * step.time, 1.0e-6 * 1.5e-4 * step.time);
    EXPECT_NEAR(std::stod(it->second[1]), 100.0 * step.time, 1.0e-5 * 100.0 * step.time);
  }
}

} // namespace
} // namespace stella
