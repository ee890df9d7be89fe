// STAT_NON_LINE with DEFI_CONTACT FORMULATION='CONTINUE' (frictionless, LAGS_C on the slave
// nodes) run end to end on command files: two elastic blocks with matching meshes pressed
// together (patch test: a uniform contact pressure, LAGS_C = -p on every slave node), in plane
// strain (QUAD4 and QUAD8 with SEG3 contact cells) and 3D (HEXA8); ALGO_CONT STANDARD and
// PENALISATION (against the closed form of blocks in series with the penalty), the status loop
// NEWTON and POINT_FIXE, CONTACT_INIT; the gap open at the first instants (LAGS_C = 0); and the
// refusals of what is not implemented yet. The numbers are asserted by TEST_RESU against
// ANALYTIQUE references inside the command files.

#include "solver/contact/tests/ContactStudyRun.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/job/BatchJob.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace stella::contact {
namespace {

namespace fs = std::filesystem;

StudyRun runStudy(const std::string& name, const Mesh& mesh, const std::string& comm, bool quiet = false) {
  return runStudyIn("stella_contact_continue", name, mesh, comm, quiet);
}

// Block A = [0,1]^d fixed on its bottom face, block B above it with an initial gap, its top face
// pushed down by push x t; symmetry planes x = 0 (and y = 0 in 3D): uniaxial compression once in
// contact. With an exact contact (STANDARD): sigma = E' (push t - gap) / 2; with a penalty rho
// (PENALISATION, lambda = rho g) in series: sigma = (push t - gap) / (2 / E' + 1 / rho).
// E' = E / (1 - nu^2) in plane strain, E in 3D. LAGS_C = -sigma on every slave node.
struct Blocks {
  bool threeD = false;
  CellType cell = CellType::QUAD4;
  double gap = 0.002;
  double push = 0.01;
  double young = 1000.0;
  double nu = 0.3;
  double penalty = 0.0;  // COEF_PENA_CONT (0: STANDARD)
  std::string modelling; // 2D: D_PLAN unless given (C_PLAN, AXIS: uniaxial stress, E' = E)
  std::string zone;      // extra ZONE keywords
  std::string global;    // extra DEFI_CONTACT keywords
  std::string tests;
  std::string instants = "0.0, 0.1, 0.3, 1.0";
  double modulus() const {
    return threeD || modelling == "C_PLAN" || modelling == "AXIS" ? young : young / (1.0 - nu * nu);
  }
  double stress(double t) const {
    const double closing = std::max(0.0, push * t - gap);
    return penalty > 0.0 ? closing / (2.0 / modulus() + 1.0 / penalty) : modulus() * closing / 2.0;
  }
  std::string comm() const {
    const std::string up = threeD ? "Z" : "Y";
    const std::string d = threeD ? "DZ" : "DY";
    const std::string sym = testing::blockSymmetries(threeD);
    const std::string algo =
        penalty > 0.0 ? fmt::format(", ALGO_CONT='PENALISATION', COEF_PENA_CONT={}", penalty) : std::string();
    return fmt::format(
        "DEBUT()\n"
        "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{}'))\n"
        "MAT = DEFI_MATERIAU(ELAS=_F(E={}, NU={}))\n"
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
        "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=({}))\n"
        "PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_{}MAX', {}=-{}))\n"
        "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
        "L = DEFI_LIST_REEL(VALE=({}))\n"
        "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE'{},\n"
        "                    ZONE=_F(GROUP_MA_MAIT='A_{}MAX', GROUP_MA_ESCL='B_{}MIN'{}{}))\n"
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PUSH, "
        "FONC_MULT=F)), INCREMENT=_F(LIST_INST=L), CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9))\n"
        "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, FORCE=('FORC_NODA', 'REAC_NODA'))\n"
        "{}"
        "FIN()\n",
        threeD              ? "3D"
        : modelling.empty() ? "D_PLAN"
                            : modelling,
        young, nu, sym, up, d, push, instants, global, up, up, algo, zone, tests);
  }
  Mesh mesh(int divisions) const { return testing::twoBlocks(cell, divisions, divisions, gap); }
};

// LAGS_C = -sigma on every slave node (MIN and MAX), the sum of RN and the support's reaction
// equal to sigma x the contact area (1); at t = 0.1 the gap is still open: LAGS_C = RN = 0.
std::string patchChecks(const Blocks& b, double precision) {
  const std::string up = b.threeD ? "Z" : "Y";
  const std::string d = b.threeD ? "DZ" : "DY";
  std::string s;
  s += testResu(0.1, "DEPL", "LAGS_C", "B_" + up + "MIN", "MIN", 0.0, 1e-12);
  s += testResu(0.1, "DEPL", "LAGS_C", "B_" + up + "MIN", "MAX", 0.0, 1e-12);
  s += testResu(0.1, "CONT_NOEU", "RN", "B_" + up + "MIN", "SOMM", 0.0, 1e-12);
  s += testResu(0.1, "CONT_NOEU", "JEU", "B_" + up + "MIN", "MIN", b.gap - 0.1 * b.push, 1e-9);
  for (double t : {0.3, 1.0}) {
    s += testResu(t, "DEPL", "LAGS_C", "B_" + up + "MIN", "MIN", -b.stress(t), precision);
    s += testResu(t, "DEPL", "LAGS_C", "B_" + up + "MIN", "MAX", -b.stress(t), precision);
    // the contact area: 1, or the integral of r dr over [0, 1] per radian in AXIS
    const double area = b.modelling == "AXIS" ? 0.5 : 1.0;
    s += testResu(t, "CONT_NOEU", "RN", "B_" + up + "MIN", "SOMM", area * b.stress(t), precision);
    s += testResu(t, "REAC_NODA", d, "A_" + up + "MIN", "SOMM", area * b.stress(t), precision);
  }
  return s;
}

TEST(ContinuousContact, PlaneStrainPatchTestStandard) {
  Blocks b;
  b.tests = patchChecks(b, 1e-8);
  const StudyRun r = runStudy("patch_standard", b.mesh(4), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("contact CONTINUE STANDARD COEF_CONT=100"), std::string::npos);
  EXPECT_NE(r.message.find("Nombre de liaisons de contact : 5"), std::string::npos);
  EXPECT_NE(r.message.find("Nombre de liaisons de contact : 0"), std::string::npos);
}

TEST(ContinuousContact, PlaneStrainPatchTestWithStatusFixedPoint) {
  Blocks b;
  b.global = ", ALGO_RESO_CONT='POINT_FIXE'";
  b.tests = patchChecks(b, 1e-8);
  const StudyRun r = runStudy("patch_point_fixe", b.mesh(4), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("ALGO_RESO_CONT=POINT_FIXE"), std::string::npos);
  EXPECT_NE(r.message.find("contact status changed"), std::string::npos);
}

TEST(ContinuousContact, PlaneStressAndAxisymmetricPatchTests) {
  // AXIS: x is the radius, the blocks are cylinders in uniaxial compression (u_r = nu sigma r /
  // E); the weights w_i = integral of N_i r over the slave edges (per radian) are the consistent
  // forces of a uniform pressure, the node on the axis included, so LAGS_C is uniform there too.
  for (const char* modelling : {"C_PLAN", "AXIS"}) {
    Blocks b;
    b.modelling = modelling;
    b.tests = patchChecks(b, 1e-8);
    const StudyRun r = runStudy(fmt::format("patch_{}", modelling), b.mesh(4), b.comm());
    EXPECT_TRUE(passed(r)) << modelling;
  }
}

TEST(ContinuousContact, ContactInitDoesNotChangeTheSolution) {
  for (const char* init : {"OUI", "NON"}) {
    Blocks b;
    b.zone = fmt::format(", CONTACT_INIT='{}'", init);
    b.tests = patchChecks(b, 1e-8);
    const StudyRun r = runStudy(fmt::format("patch_init_{}", init), b.mesh(3), b.comm());
    EXPECT_TRUE(passed(r)) << init;
  }
}

TEST(ContinuousContact, QuadraticCellsWithSeg3ContactCells) {
  // SEG3 slave cells: Simpson weights L/6, 2L/3, L/6 are the consistent nodal forces of a uniform
  // pressure: LAGS_C is uniform on the end and middle nodes alike.
  Blocks b;
  b.cell = CellType::QUAD8;
  b.tests = patchChecks(b, 1e-8);
  const StudyRun r = runStudy("patch_quad8", b.mesh(3), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("Nombre de liaisons de contact : 7"), std::string::npos);
}

TEST(ContinuousContact, PenaltyMatchesTheBlocksInSeriesWithThePenalty) {
  // lambda = rho g: the closed form includes the penalty (its pressure is short of the exact
  // contact's by about E' / (2 rho): 5 % for rho = 1e4, 0.05 % for 1e6), to 1e-8 for both.
  for (double rho : {1.0e4, 1.0e6}) {
    Blocks b;
    b.penalty = rho;
    b.tests = patchChecks(b, 1e-8);
    const StudyRun r = runStudy(fmt::format("patch_penalty_{:g}", rho), b.mesh(4), b.comm());
    EXPECT_TRUE(passed(r)) << rho;
    EXPECT_NE(r.message.find(fmt::format("PENALISATION COEF_PENA_CONT={}", rho)), std::string::npos);
  }
}

TEST(ContinuousContact, ThreeDimensionalHexa8PatchTest) {
  Blocks b;
  b.threeD = true;
  b.cell = CellType::HEXA8;
  b.tests = patchChecks(b, 1e-8);
  // 8 x 8 cells: 81 slave nodes in contact, more than one block (64) of Schur columns
  const StudyRun r = runStudy("patch_3d", b.mesh(8), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("Nombre de liaisons de contact : 81"), std::string::npos);
}

TEST(ContinuousContact, ThreeDimensionalQuadraticAndTriangularContactCells) {
  // HEXA27 blocks: QUAD9 slave cells (weights = integrals of the biquadratic shape functions,
  // 1/36, 1/9, 4/9 of a cell); TETRA4 blocks: TRIA3 slave cells. Coincident slave and master
  // nodes: the pressure is uniform.
  for (const CellType cell : {CellType::HEXA27, CellType::TETRA4}) {
    Blocks b;
    b.threeD = true;
    b.cell = cell;
    b.tests = patchChecks(b, 1e-8);
    std::string comm = b.comm();
    if (cell == CellType::HEXA27) {
      // MUMPS reports a null pivot at a DDL_IMPO multiplier at the prediction of the third step
      // (the matrix is regular: MULT_FRONT factorises it and the results are exact): the known
      // defect of MUMPS's null-pivot detection on this saddle system (doc/contact.md).
      const std::string convergence = "CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9)";
      comm.replace(comm.find(convergence), convergence.size(),
                   convergence + ", SOLVEUR=_F(METHODE='MULT_FRONT')");
    }
    const StudyRun r = runStudy(fmt::format("patch_3d_{}", name(cell)), b.mesh(2), comm);
    EXPECT_TRUE(passed(r)) << name(cell);
  }
}

TEST(ContinuousContact, BodyHeldOnlyByContactIsHeldOnceInContact) {
  // Block B pushed by a pressure p = 1 and held by nothing but the contact (gap 0): without
  // contact status at the first iteration its stiffness is singular (SOLVE_1 with the note on
  // CONTACT_INIT); with CONTACT_INIT='OUI' the augmented term of the nodes in contact holds it
  // and the pressure is transmitted exactly: LAGS_C = -1.
  for (const bool init : {false, true}) {
    Blocks b;
    b.gap = 0.0;
    b.zone = init ? ", CONTACT_INIT='OUI'" : "";
    b.instants = "0.0, 1.0";
    b.tests = init ? testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MIN", -1.0, 1e-8) +
                         testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MAX", -1.0, 1e-8)
                   : std::string();
    std::string comm = b.comm();
    const std::string push = "PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_YMAX', DY=-0.01))";
    comm.replace(comm.find(push), push.size(),
                 "PUSH = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='B_YMAX', PRES=1.0))");
    const StudyRun r = runStudy(init ? "held_init_oui" : "held_singular", b.mesh(2), comm, !init);
    if (init) {
      EXPECT_TRUE(passed(r));
    } else {
      EXPECT_EQ(r.diagnostic, JobDiagnostic::Error);
      EXPECT_NE(r.message.find("SOLVE_1"), std::string::npos);
      EXPECT_NE(r.message.find("CONTACT_INIT='OUI'"), std::string::npos);
    }
  }
}

TEST(ContinuousContact, PatchTestsWithTheGeometryInTheNewtonIterations) {
  // ALGO_RESO_GEOM='NEWTON' (ContinuousGeometricTangent.hpp): the same closed forms as the geometric
  // loop, in plane strain (SEG2 and SEG3 contact cells), AXIS, 3D (QUAD4) and with PENALISATION.
  struct Case {
    const char* name;
    bool threeD;
    CellType cell;
    const char* modelling;
    double penalty;
  };
  for (const Case& c :
       {Case{"quad4", false, CellType::QUAD4, "", 0.0}, Case{"quad8", false, CellType::QUAD8, "", 0.0},
        Case{"axis", false, CellType::QUAD4, "AXIS", 0.0}, Case{"hexa8", true, CellType::HEXA8, "", 0.0},
        Case{"penalty", false, CellType::QUAD4, "", 1.0e6}}) {
    Blocks b;
    b.threeD = c.threeD;
    b.cell = c.cell;
    b.modelling = c.modelling;
    b.penalty = c.penalty;
    b.global = ", ALGO_RESO_GEOM='NEWTON'";
    b.tests = patchChecks(b, 1e-8);
    const StudyRun r = runStudy(fmt::format("patch_geometry_newton_{}", c.name), b.mesh(3), b.comm());
    EXPECT_TRUE(passed(r)) << c.name;
    EXPECT_NE(
        r.message.find("ALGO_RESO_GEOM=NEWTON (pairing and geometric tangent in the Newton iterations)"),
        std::string::npos)
        << c.name;
    EXPECT_EQ(r.message.find("2 geometric iteration(s)"), std::string::npos) << c.name; // no outer loop
  }
}

TEST(ContinuousContact, WhatIsNotImplementedIsRefusedNamingTheKeyword) {
  const struct {
    std::string global;
    std::string zone;
    std::string named;
    bool threeD = false;
  } cases[] = {
      {", FROTTEMENT='COULOMB'",
       ", COULOMB=0.2, ALGO_FROT='PENALISATION', ADAPTATION='ADAPT_COEF', GLIS_MAXI=0.1", "GLIS_MAXI"},
      {", ALGO_RESO_GEOM='NEWTON', LISSAGE='OUI'", "", "ALGO_RESO_GEOM='NEWTON' and LISSAGE='OUI'"},
      {", FROTTEMENT='COULOMB', ALGO_RESO_GEOM='NEWTON'", ", COULOMB=0.2, INTEGRATION='GAUSS'",
       "ALGO_RESO_GEOM='NEWTON' and contact points that are not slave nodes (INTEGRATION other than 'AUTO', "
       "or 'AUTO' on TRIA6 and QUAD8 slave cells)"},
      {", FROTTEMENT='COULOMB', ALGO_RESO_GEOM='NEWTON'",
       ", COULOMB=0.2, SANS_GROUP_NO_FR='B_ZMIN', DIRE_EXCL_FROT=(1.0, 0.0, 0.0)",
       "ALGO_RESO_GEOM='NEWTON' and DIRE_EXCL_FROT in 3D", true},
      {"", ", RESOLUTION='NON', TOLE_INTERP=0.1", "TOLE_INTERP (other than its default 0)"},
  };
  for (const auto& c : cases) {
    Blocks b;
    b.global = c.global;
    b.zone = c.zone;
    b.threeD = c.threeD;
    b.cell = c.threeD ? CellType::HEXA8 : CellType::QUAD4;
    const StudyRun r = runStudy("refused", b.mesh(2), b.comm(), true);
    EXPECT_FALSE(passed(r)) << c.named;
    EXPECT_NE(r.message.find("CONTACT_20"), std::string::npos) << c.named;
    EXPECT_NE(r.message.find(c.named + " with FORMULATION='CONTINUE' is not implemented yet"),
              std::string::npos)
        << c.named << "\n"
        << r.message;
  }
}

} // namespace
} // namespace stella::contact
