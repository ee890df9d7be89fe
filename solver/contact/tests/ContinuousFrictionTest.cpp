// Coulomb friction with DEFI_CONTACT FORMULATION='CONTINUE' (D_PLAN, C_PLAN), run end to end on command
// files: an elastic block pressed on a rigid plane (a block whose nodes are all fixed) by its top,
// then sheared by it. The block's sides are periodic (LIAISON_DDL between the nodes of x = 0 and
// x = 1 at the same height), so the state is uniform and the closed form exact:
//   pressing:  N = M d L / H,   M = E (1 - nu) / ((1 + nu) (1 - 2 nu))  (oedometric, eps_xx = 0)
//   shearing:  stick while G u L / H < mu N: T = G u L / H and zero slip (the constraint s = 0 is
//              exact with the augmented Lagrangian: round-off only); then slip: T = mu N, slip
//              s = u - mu N H / (G L), N unchanged.
// The corner x = 1 of the contact surface is the periodic copy of x = 0: it is not a slave node
// (SANS_GROUP_NO, else its slip condition repeats the one of x = 0 through the tie), so the slave
// node x = 0 carries both ends' share (its LAGS_C is twice the pressure; LAGS_F1, the ratio to
// the Coulomb threshold, is the same on every node). ALGO_FROT STANDARD (the stick rows in the
// Schur complement) and PENALISATION (COEF_PENA_FROT: a penalised stick; only its sliding is
// uniform here, see checks()), ALGO_RESO_FROT NEWTON and POINT_FIXE, mu = 0.3 and 1.0. Numbers
// asserted by TEST_RESU / TEST_TABLE against ANALYTIQUE references inside the command files.

#include "solver/contact/tests/ContactStudyRun.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/job/BatchJob.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace stella::contact {
namespace {

namespace fs = std::filesystem;

StudyRun runStudy(const std::string& name, const Mesh& mesh, const std::string& comm, bool quiet = false) {
  return runStudyIn("stella_friction_continue", name, mesh, comm, quiet);
}

// RESI_GLOB_RELA of the iteration 0 of each step, from the convergence tables of the message file.
std::vector<double> firstIterationResiduals(const std::string& message) {
  std::vector<double> values;
  std::istringstream in(message);
  std::string line;
  while (std::getline(in, line)) {
    const auto bar = line.find("|    0 |");
    if (bar != std::string::npos && line.find_first_not_of(' ') == bar) {
      values.push_back(std::stod(line.substr(bar + 8)));
    }
  }
  return values;
}

constexpr double young = 1000.0;
constexpr double nu = 0.3;
constexpr double press = 0.01;  // d: DY of the top
constexpr double shear = 0.025; // u = shear x (t - 1), t in [1, 3]
constexpr int divisions = 4;

double oedometric() {
  return young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}
double shearModulus() {
  return young / (2.0 * (1.0 + nu));
}
double normalForce() {
  return oedometric() * press;
} // L = H = 1

// The periodic ties of the block B: the nodes of B_XMIN and B_XMAX at the same height, but the
// top row (driven on both sides).
std::string periodicTies(const Mesh& mesh) {
  std::map<long long, NodeId> left;
  std::map<long long, NodeId> right;
  const auto key = [&](NodeId n) { return std::llround(mesh.point(n)[1] * 1e6); };
  for (NodeId n : *mesh.nodeGroup("B_XMIN")) {
    left[key(n)] = n;
  }
  for (NodeId n : *mesh.nodeGroup("B_XMAX")) {
    right[key(n)] = n;
  }
  std::string ties;
  const long long top = left.rbegin()->first;
  for (const auto& [y, n] : left) {
    if (y == top) {
      continue;
    }
    for (const char* c : {"DX", "DY"}) {
      ties += fmt::format("_F(NOEUD=('{}', '{}'), DDL=('{}', '{}'), COEF_MULT=(1.0, -1.0), COEF_IMPO=0.0), ",
                          mesh.nodeName(n), mesh.nodeName(right.at(y)), c, c);
    }
  }
  return ties;
}

struct Shear {
  double mu = 0.3;
  bool fixedPoint = false;
  double penalty = 0.0; // COEF_PENA_FROT (0: ALGO_FROT='STANDARD')
  // RESI_FROT of POINT_FIXE: the threshold's relative error, hence that of the sliding force
  // after the normal pressure changed (from a step to the next); tight for 1e-8 assertions
  double frictionResidual = 1e-10;
  // LAGS_F1 is along the pairing's tangent, in 2D t1 = (-n_y, n_x) with n the master's outward
  // normal: n = +y for A_YMAX, t1 = -x; the friction on the block's bottom is along -x (it resists
  // the top pulled along +x) = +t1; the force on a slave node is -w mu |LAGS_C| LAGS_F1 t1 (as
  // -w LAGS_C n for the normal), so LAGS_F1 = -T / (mu N).
  double lagsF1Sign = -1.0;
  // F_N(t): 0 -> 1 on [0, 1], then 1 -> pressEnd at t = 3 (pressed further while sheared)
  double pressEnd = 1.0;
  double pressing(double t) const { return t <= 1.0 ? t : 1.0 + (pressEnd - 1.0) * (t - 1.0) / 2.0; }
  // C_PLAN: sigma_zz = 0, the strip's modulus under eps_xx = 0 is E / (1 - nu^2)
  std::string modelling = "D_PLAN";
  double pressedForce() const {
    return modelling == "C_PLAN" ? young / (1.0 - nu * nu) * press : normalForce();
  }
  double normal(double t) const { return pressedForce() * pressing(t); }
  double onset(double t) const { return mu * normal(t) / shearModulus(); }
  static double sheared(double t) { return shear * std::max(0.0, t - 1.0); }
  // the uniform state sticks while G u < mu N(t) (it does not stick again once sliding: the
  // tests' u grows faster than mu N / G)
  bool sticking(double t) const { return sheared(t) < onset(t); }
  double force(double t) const { return sticking(t) ? sheared(t) * shearModulus() : mu * normal(t); }
  double slip(double t) const { return sticking(t) ? 0.0 : sheared(t) - force(t) / shearModulus(); }

  std::string checks(const std::vector<double>& instants) const {
    std::string s;
    const auto table = [&](double t, const char* cmp, double value) {
      s += fmt::format("TEST_TABLE(TABLE=HAUT, NOM_PARA='{}', FILTRE=_F(NOM_PARA='INST', VALE={}), "
                       "VALE_CALC={:.17g}, TOLE_MACHINE=1e-6, REFERENCE='ANALYTIQUE', VALE_REFE={:.17g}, "
                       "PRECISION=1e-8)\n",
                       cmp, t, value, value);
    };
    const auto resu = [&](double t, const char* field, const char* cmp, const char* group, const char* kind,
                          double value, double precision, bool absolute) {
      s +=
          fmt::format("TEST_RESU(RESU=_F(RESULTAT=RESU, INST={}, NOM_CHAM='{}', NOM_CMP='{}', GROUP_NO='{}', "
                      "TYPE_TEST='{}', VALE_CALC={:.17g}, TOLE_MACHINE={}, CRITERE='{}', "
                      "REFERENCE='ANALYTIQUE', VALE_REFE={:.17g}, PRECISION={}))\n",
                      t, field, cmp, group, kind, value, absolute ? 1.0 : 1e-6,
                      absolute ? "ABSOLU" : "RELATIF", value, precision);
    };
    for (double t : instants) {
      table(t, "DY", -normal(t));
      // The penalised stick is not uniform here: the slave node of x = 0 carries its periodic
      // copy's normal force (multiplier) but only its own penalty spring, so its stick limit is
      // reached later; asserted: stick (status) well below the onset, everything once every node
      // slides (beyond twice the onset)
      const bool uniform = penalty == 0.0 || sheared(t) >= 2.0 * onset(t);
      if (uniform || sheared(t) <= 0.5 * onset(t)) {
        for (const char* kind : {"MIN", "MAX"}) {
          resu(t, "CONT_NOEU", "CONT", "ESCL", kind, sticking(t) ? 1.0 : 2.0, 0.0, true);
        }
      }
      if (!uniform) {
        continue;
      }
      table(t, "DX", force(t));
      for (const char* kind : {"MIN", "MAX"}) {
        // stick: zero slip to round-off (1e-12 absolute: 1e-10 of u); slip: 1e-8 relative
        resu(t, "DEPL", "DX", "B_YMIN", kind, slip(t), sticking(t) ? 1e-12 : 1e-8, sticking(t));
        // LAGS_F1 = T / (mu N) on every slave node, 1 sliding
        const double ratio = force(t) / (mu * normal(t));
        resu(t, "DEPL", "LAGS_F1", "ESCL", kind, lagsF1Sign * ratio, 1e-8, ratio == 0.0);
      }
    }
    return s;
  }

  std::string comm(const Mesh& mesh, const std::vector<double>& instants) const {
    const std::string algo =
        penalty > 0.0 ? fmt::format("ALGO_FROT='PENALISATION', COEF_PENA_FROT={}, ", penalty) : std::string();
    std::string list;
    for (std::size_t i = 1; i < instants.size(); ++i) {
      list += fmt::format("{}, ", instants[i]);
    }
    return fmt::format(
        "DEBUT()\n"
        "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{}'))\n"
        "MAT = DEFI_MATERIAU(ELAS=_F(E={}, NU={}))\n"
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
        "SOL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='A_SURFACE', DX=0.0, DY=0.0))\n"
        "PERIODE = AFFE_CHAR_MECA(MODELE=MO, LIAISON_DDL=({}))\n"
        "PRESSE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_YMAX', DY=-{}))\n"
        "CISAILLE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_YMAX', DX={}))\n"
        "F_N = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 3.0, {}))\n"
        "F_T = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 0.0, 3.0, 2.0))\n"
        "L = DEFI_LIST_REEL(VALE=(0.0, {}))\n"
        "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', ALGO_RESO_FROT='{}', "
        "RESI_FROT={},\n"
        "                    ZONE=_F(GROUP_MA_MAIT='A_YMAX', GROUP_MA_ESCL='B_YMIN', SANS_GROUP_NO='COIN', "
        "CONTACT_INIT='OUI', {}COULOMB={}))\n"
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=SOL), "
        "_F(CHARGE=PERIODE), "
        "_F(CHARGE=PRESSE, FONC_MULT=F_N), _F(CHARGE=CISAILLE, FONC_MULT=F_T)), INCREMENT=_F(LIST_INST=L), "
        "CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9, ITER_GLOB_MAXI=30))\n"
        "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, FORCE='REAC_NODA')\n"
        "HAUT = POST_RELEVE_T(ACTION=_F(OPERATION='EXTRACTION', INTITULE='HAUT', RESULTAT=RESU, "
        "NOM_CHAM='REAC_NODA', GROUP_NO='B_YMAX', RESULTANTE=('DX', 'DY'), TOUT_ORDRE='OUI'))\n"
        "{}"
        "FIN()\n",
        modelling, young, nu, periodicTies(mesh), press, shear, pressEnd, list,
        fixedPoint ? "POINT_FIXE" : "NEWTON", frictionResidual, algo, mu,
        checks(std::vector<double>(instants.begin() + 1, instants.end())));
  }
};

// Block A (the rigid plane, every node fixed) below block B, touching; node group COIN = the
// corner (1, 1) of B's contact surface.
Mesh blockOnPlane() {
  Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, divisions, 0.0);
  std::vector<NodeId> corner;
  for (NodeId n : *mesh.nodeGroup("B_YMIN")) {
    if (mesh.point(n)[0] > 0.5 &&
        std::find(mesh.nodeGroup("B_XMAX")->begin(), mesh.nodeGroup("B_XMAX")->end(), n) !=
            mesh.nodeGroup("B_XMAX")->end()) {
      corner.push_back(n);
    }
  }
  mesh.setNodeGroup("COIN", corner);
  std::vector<NodeId> slaves;
  for (NodeId n : *mesh.nodeGroup("B_YMIN")) {
    if (std::find(corner.begin(), corner.end(), n) == corner.end()) {
      slaves.push_back(n);
    }
  }
  mesh.setNodeGroup("ESCL", slaves);
  return mesh;
}

const std::vector<double> instants{0.0, 0.5, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0};

TEST(ContinuousFriction, BlockPressedThenShearedStickThenSlipNewton) {
  const Mesh mesh = blockOnPlane();
  for (double mu : {0.3, 1.0}) {
    Shear s;
    s.mu = mu;
    // both regimes are exercised: mu = 0.3 slides from t = 1.5, mu = 1.0 sticks at t = 2
    ASSERT_FALSE(s.sticking(1.5) && mu < 0.5);
    ASSERT_TRUE(s.sticking(2.0) || mu < 0.5);
    ASSERT_FALSE(s.sticking(3.0));
    const StudyRun r = runStudy(fmt::format("shear_newton_{:g}", mu), mesh, s.comm(mesh, instants));
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << mu;
  }
}

TEST(ContinuousFriction, BlockPressedThenShearedStickThenSlipFixedPoint) {
  const Mesh mesh = blockOnPlane();
  for (double mu : {0.3, 1.0}) {
    Shear s;
    s.mu = mu;
    s.fixedPoint = true;
    const StudyRun r = runStudy(fmt::format("shear_point_fixe_{:g}", mu), mesh, s.comm(mesh, instants));
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << mu;
  }
}

// Plane stress: the same with N = E d L / ((1 - nu^2) H).
TEST(ContinuousFriction, PlaneStressStickThenSlip) {
  const Mesh mesh = blockOnPlane();
  for (bool fixedPoint : {false, true}) {
    Shear s;
    s.mu = 0.3;
    s.modelling = "C_PLAN";
    s.fixedPoint = fixedPoint;
    const StudyRun r = runStudy(fmt::format("plane_stress_{}", fixedPoint ? "point_fixe" : "newton"), mesh,
                                s.comm(mesh, instants));
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok);
  }
}

// Pressed further while sliding (N doubles from t = 1 to 3): the sliding force follows LAGS_C, which
// ALGO_RESO_FROT='NEWTON' linearises (the non-symmetric Schur complement) and POINT_FIXE iterates
// (friction loops). mu = 0.3: stick until t = 1.53, then T = mu N(t) with N(t) growing.
TEST(ContinuousFriction, PressedFurtherWhileSliding) {
  const Mesh mesh = blockOnPlane();
  for (bool fixedPoint : {false, true}) {
    Shear s;
    s.mu = 0.3;
    s.pressEnd = 2.0;
    s.fixedPoint = fixedPoint;
    ASSERT_TRUE(s.sticking(1.5));
    ASSERT_FALSE(s.sticking(2.0));
    const StudyRun r = runStudy(fmt::format("pressed_sliding_{}", fixedPoint ? "point_fixe" : "newton"), mesh,
                                s.comm(mesh, instants));
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok);
    if (!fixedPoint) {
      // NEWTON linearises the sliding force in LAGS_C: once every node slides (t = 2.5 and 3, the
      // status of the previous step), the first iteration solves the (linear, uniform) step exactly;
      // without that coupling it used the previous LAGS_C (measured: RESI_GLOB_RELA 4.3e-2 and 3.8e-2)
      const std::vector<double> first = firstIterationResiduals(r.message);
      ASSERT_EQ(first.size(), instants.size() - 1) << r.message;
      EXPECT_LT(first[first.size() - 2], 1e-12);
      EXPECT_LT(first.back(), 1e-12);
    }
  }
}

// The rows of the convergence tables of a message file: per INST, each iteration's cells (split at
// '|') and the continuation line that follows it, if any.
struct TableRow {
  double inst = 0.0;
  std::vector<std::string> cells; // [0] ITER ... [5] the first contact column
  std::string continuation;
};

std::vector<TableRow> convergenceRows(const std::string& message, std::vector<std::string>& headers) {
  std::vector<TableRow> rows;
  std::istringstream in(message);
  std::string line;
  double inst = 0.0;
  while (std::getline(in, line)) {
    if (line.rfind("   INST ", 0) == 0) {
      inst = std::stod(line.substr(8));
      continue;
    }
    if (line.rfind("   | ITER |", 0) == 0) {
      headers.push_back(line);
      continue;
    }
    if (line.rfind("   |      | ", 0) == 0 && !rows.empty()) {
      rows.back().continuation = line.substr(12);
      continue;
    }
    if (line.rfind("   | ", 0) != 0 || line.size() < 10 ||
        std::isdigit(static_cast<unsigned char>(line[8])) == 0) {
      continue;
    }
    TableRow row;
    row.inst = inst;
    std::string cell;
    std::istringstream cells(line.substr(4));
    while (std::getline(cells, cell, '|')) {
      row.cells.push_back(cell);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

double cellValue(const TableRow& row, std::size_t column) {
  const std::string& c = row.cells.at(column);
  return c.find('-') != std::string::npos && c.find_first_of("0123456789") == std::string::npos
             ? -1.0
             : std::stod(c);
}

// The number printed in a continuation line after `before` ("moved by 1.43e-01 of").
double numberAfter(const std::string& text, const std::string& before) {
  const auto at = text.find(before);
  return at == std::string::npos ? -1.0 : std::stod(text.substr(at + before.size()));
}

// The contact columns of the continuous formulation (CONT_NEWT, RESI_GEOM, FROT_NEWT / BOUC_FROT) against
// what the constraint decided with them and against the closed form of the block pressed further while
// sliding. Once every node slides (t = 2.5 and 3: N(t) = N0 (1 + (t - 1) / 2), u_top = 0.025 (t - 1)), the
// first correction of a step is exact (PressedFurtherWhileSliding), so:
//  - the threshold |LAGS_C| moved from N(t - 0.5) to N(t) at it: FROT_NEWT = BOUC_FROT = 1 - N(t - 0.5)
//    / N(t) (1/7 and 1/8: uniform, LAGS_C is proportional to N on every node);
//  - the contact nodes moved by the slip increment du - mu dN / G since the pairing of the step's start,
//    the structure by at most du (the top): RESI_GEOM = 1 - mu dN / (G du) = 0.79 (ALGO_RESO_FROT=
//    'NEWTON'); with POINT_FIXE the threshold is frozen at N(t - 0.5) there, the force too, and the
//    slip takes the whole du: RESI_GEOM = 1;
//  - the status did not change: CONT_NEWT = 0 (ALGO_RESO_CONT='NEWTON', the default, in both).
// Every continuation line (status changed on n nodes, threshold moved by c, pairing recomputed) follows
// a row whose columns say so, and the last row of each step holds the criteria (0 changes, FROT_NEWT <=
// RESI_FROT, RESI_GEOM <= 0.01 or '-'). Printed to 4 digits: compared to 1e-3.
TEST(ContinuousFriction, ConvergenceTableHasTheContinuousContactColumns) {
  const Mesh mesh = blockOnPlane();
  for (bool fixedPoint : {false, true}) {
    Shear s;
    s.mu = 0.3;
    s.pressEnd = 2.0;
    s.fixedPoint = fixedPoint;
    const StudyRun r = runStudy(fmt::format("columns_{}", fixedPoint ? "point_fixe" : "newton"), mesh,
                                s.comm(mesh, instants));
    ASSERT_EQ(r.diagnostic, JobDiagnostic::Ok);
    std::vector<std::string> headers;
    const std::vector<TableRow> rows = convergenceRows(r.message, headers);
    ASSERT_EQ(headers.size(), instants.size() - 1) << r.message;
    const std::string status = "CONT_NEWT"; // ALGO_RESO_CONT='NEWTON' (the default) in both
    const std::string frot = fixedPoint ? "BOUC_FROT" : "FROT_NEWT";
    for (const std::string& h : headers) {
      EXPECT_NE(h.find(fmt::format("| {:<10} | RESI_GEOM  | {:<10} |", status, frot)), std::string::npos)
          << h;
    }
    constexpr std::size_t cont = 5;
    constexpr std::size_t geom = 6;
    constexpr std::size_t fric = 7;
    int frictionNotes = 0;
    int geometryNotes = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const TableRow& row = rows[i];
      ASSERT_GT(row.cells.size(), fric + 1) << r.message;
      const bool last = i + 1 == rows.size() || rows[i + 1].inst != row.inst;
      if (row.continuation.find("friction threshold") != std::string::npos) {
        ++frictionNotes;
        const double said = numberAfter(row.continuation, fixedPoint ? "change " : "moved by ");
        EXPECT_NEAR(cellValue(row, fric), said, 5e-3 * said) << row.continuation;
        EXPECT_GT(cellValue(row, fric), s.frictionResidual);
      }
      if (row.continuation.find("contact status changed on") != std::string::npos) {
        EXPECT_EQ(cellValue(row, cont), numberAfter(row.continuation, "changed on ")) << row.continuation;
      }
      if (row.continuation.find("pairing recomputed") != std::string::npos) {
        ++geometryNotes;
        EXPECT_GT(cellValue(row, geom), 0.01);
      }
      if (last) {
        EXPECT_TRUE(row.continuation.empty()) << row.continuation;
        EXPECT_EQ(cellValue(row, cont), 0.0);
        EXPECT_LE(cellValue(row, geom), 0.01);
        EXPECT_LE(cellValue(row, fric), s.frictionResidual);
      }
    }
    EXPECT_GT(frictionNotes, 0);
    EXPECT_GT(geometryNotes, 0);
    for (double t : {2.5, 3.0}) {
      const auto first =
          std::find_if(rows.begin(), rows.end(), [&](const TableRow& x) { return x.inst == t; });
      ASSERT_NE(first, rows.end());
      const double dN = s.normal(t) - s.normal(t - 0.5);
      EXPECT_NEAR(cellValue(*first, fric), dN / s.normal(t), 1e-3 * dN / s.normal(t)) << t;
      const double du = Shear::sheared(t) - Shear::sheared(t - 0.5);
      // POINT_FIXE: the threshold frozen at N(t - 0.5) holds the force, the slip takes the whole du
      const double geometric = fixedPoint ? 1.0 : 1.0 - s.mu * dN / (shearModulus() * du);
      EXPECT_NEAR(cellValue(*first, geom), geometric, 1e-3 * geometric) << t;
      EXPECT_EQ(cellValue(*first, cont), 0.0) << t;
    }
  }
}

TEST(ContinuousFriction, PenalisedFrictionAddsTheElasticSlipOfThePenalty) {
  const Mesh mesh = blockOnPlane();
  for (bool fixedPoint : {false, true}) {
    Shear s;
    s.mu = 0.3;
    s.fixedPoint = fixedPoint;
    s.penalty = 1e4;
    const StudyRun r = runStudy(fmt::format("shear_penalised_{}", fixedPoint ? "point_fixe" : "newton"), mesh,
                                s.comm(mesh, instants));
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok);
  }
}

// The tangential force DX of table HAUT at INST t, printed by IMPR_TABLE in the message file.
double printedForce(const std::string& message, double t) {
  std::istringstream in(message);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string title;
    std::string result;
    std::string field;
    std::string order;
    double inst = 0.0;
    double dx = 0.0;
    if (row >> title >> result >> field >> order >> inst >> dx && title == "HAUT" &&
        std::fabs(inst - t) < 1e-12) {
      return dx;
    }
  }
  ADD_FAILURE() << "no row INST " << t << " in table HAUT";
  return 0.0;
}

// ALGO_FROT='PENALISATION' sticking over several steps: the penalty spring keeps its force (the
// return mapping starts from the tangential pressure of the step's start), so the sticking state at
// t = 2 (elastic, path-independent) is the same reached in 4 steps from t = 1 as in one.
TEST(ContinuousFriction, PenalisedStickKeepsItsForceAcrossSteps) {
  const Mesh mesh = blockOnPlane();
  Shear s;
  s.mu = 1.0;
  s.penalty = 1e3; // the spring in series takes ~30 % of u: the history matters
  std::vector<double> forces;
  for (const std::vector<double>& list :
       {std::vector<double>{0.0, 0.5, 1.0, 1.25, 1.5, 1.75, 2.0}, std::vector<double>{0.0, 1.0, 2.0}}) {
    std::string comm = s.comm(mesh, list);
    comm.insert(comm.rfind("FIN()"), "IMPR_TABLE(TABLE=HAUT, UNITE=6, FORMAT_R='E24.16')\n");
    const StudyRun r = runStudy(fmt::format("penalised_stick_{}", list.size()), mesh, comm);
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok);
    forces.push_back(printedForce(r.message, 2.0));
  }
  const double exact = Shear::sheared(2.0) * shearModulus(); // the exact stick's force
  EXPECT_NEAR(forces[0], forces[1], 1e-9 * forces[1]);
  EXPECT_LT(forces[1], 0.9 * exact); // the penalty's compliance shows
  EXPECT_GT(forces[1], 0.5 * exact);
  EXPECT_LT(forces[1], s.mu * normalForce()); // sticking
}

TEST(ContinuousFriction, WhatIsNotDoneIsRefusedNamingTheKeyword) {
  const Mesh mesh = blockOnPlane();
  Shear s;
  std::string comm = s.comm(mesh, {0.0, 1.0});
  const auto replace = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  struct Case {
    std::string from;
    std::string to;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{
           {"CONTACT_INIT='OUI', ", "CONTACT_INIT='OUI', GRAND_GLIS='OUI', ", "GRAND_GLIS='OUI'"},
           {"CONTACT_INIT='OUI', ", "CONTACT_INIT='OUI', ALGO_CONT='PENALISATION', COEF_PENA_CONT=1e6, ",
            "ALGO_CONT='PENALISATION'"},
       }) {
    const StudyRun r = runStudy("refused", mesh, replace(comm, c.from, c.to), true);
    EXPECT_FALSE(passed(r)) << c.to;
    EXPECT_NE(r.message.find("CONTACT_20"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(c.expected), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("not implemented yet"), std::string::npos) << r.message;
  }
}

// SANS_GROUP_NO_FR naming no node group, and DIRE_EXCL_FROT normal to the contact surface (it would
// exclude no direction), are refused at their keyword, naming the group or the slave node.
TEST(ContinuousFriction, BadFrictionExclusionIsRefusedWhereItIsWritten) {
  const Mesh mesh = blockOnPlane();
  Shear s;
  const std::string comm = s.comm(mesh, {0.0, 1.0});
  const std::string at = "SANS_GROUP_NO='COIN', ";
  ASSERT_NE(comm.find(at), std::string::npos);
  const struct {
    std::string added;
    std::string id;
    std::string said;
  } cases[] = {
      {"SANS_GROUP_NO_FR='NOPE', ", "CONTACT_1", "SANS_GROUP_NO_FR: the mesh has no node group 'NOPE'"},
      {"SANS_GROUP_NO_FR='B_YMIN', DIRE_EXCL_FROT=(0.0, 1.0, 0.0), ", "CONTACT_30",
       "DIRE_EXCL_FROT (0, 1, 0) is normal to the contact surface at slave node"},
  };
  for (const auto& c : cases) {
    std::string text = comm;
    text.insert(text.find(at) + at.size(), c.added);
    const StudyRun r = runStudy("bad_exclusion", mesh, text, true);
    EXPECT_FALSE(passed(r)) << c.added;
    EXPECT_NE(r.message.find(c.id), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(c.said), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(".comm:"), std::string::npos) << r.message; // located
  }
}

} // namespace
} // namespace stella::contact
