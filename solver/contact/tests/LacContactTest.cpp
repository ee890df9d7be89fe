// LAC contact in STAT_NON_LINE (contact/lac/LacContactConstraint): what it refuses, named, and a
// closing gap on the blocks of ContactTestMeshes (QUAD4 slave cut by DECOUPE_LAC): LAGS_C and
// CONT_ELEM PRES = -E' (d - g) / 2 once closed, against the closed form. The patch tests over
// every cell pair are testcases/lac_patch_2d.

#include "solver/contact/tests/ContactStudyRun.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace stella::contact {
namespace {

struct LacBlocks {
  bool threeD = false;
  bool cut = true;
  std::string global; // extra DEFI_CONTACT keywords
  std::string zone;   // extra ZONE keywords
  std::string tests;
  std::string comm() const {
    const std::string up = threeD ? "Z" : "Y";
    const std::string d = threeD ? "DZ" : "DY";
    const std::string sym = testing::blockSymmetries(threeD);
    return fmt::format(
        "DEBUT()\n"
        "M0 = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
        "{}"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{}'))\n"
        "MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))\n"
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
        "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=({}))\n"
        "PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_{}MAX', {}=-0.01))\n"
        "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
        "L = DEFI_LIST_REEL(VALE=(0.0, 0.1, 1.0))\n"
        "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE'{},\n"
        "                    ZONE=_F(ALGO_CONT='LAC', GROUP_MA_MAIT='A_{}MAX', GROUP_MA_ESCL='B_{}MIN'{}))\n"
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PUSH, "
        "FONC_MULT=F)), INCREMENT=_F(LIST_INST=L), CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9))\n"
        "{}"
        "FIN()\n",
        // not cut: the master side is cut instead, so the slave group carries no patch
        fmt::format("MA = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='{}'))\n",
                    cut ? fmt::format("B_{}MIN", up) : fmt::format("A_{}MAX", up)),
        threeD ? "3D" : "D_PLAN", sym, up, d, global, up, up, zone, tests);
  }
  Mesh mesh() const { return testing::twoBlocks(threeD ? CellType::HEXA8 : CellType::QUAD4, 4, 3, 0.002); }
};

std::string cellTest(double inst, const std::string& cmp, const std::string& kind, double value,
                     double precision, const std::string& group = "B_YMIN") {
  const bool absolute = value == 0.0;
  return fmt::format(
      "TEST_RESU(RESU=_F(RESULTAT=RESU, INST={}, NOM_CHAM='CONT_ELEM', NOM_CMP='{}', GROUP_MA='{}', "
      "TYPE_TEST='{}', VALE_CALC={:.17g}, TOLE_MACHINE={}, CRITERE='{}', REFERENCE='ANALYTIQUE', "
      "VALE_REFE={:.17g}, PRECISION={}))\n",
      inst, cmp, group, kind, value, absolute ? 1.0 : std::max(precision, 1e-6),
      absolute ? "ABSOLU" : "RELATIF", value, precision);
}

TEST(LacContact, ClosingGapOnNonMatchingBlocks) {
  // two unit blocks (4 and 3 QUAD4 along x), gap 0.002, top pushed 0.01 t: open at t = 0.1 (JEU
  // 0.001), closed at t = 1 with sigma = E' (0.01 - 0.002) / 2, E' = E / (1 - nu^2)
  const double sigma = 1000.0 / (1.0 - 0.09) * 0.008 / 2.0;
  LacBlocks b;
  b.zone = ", CONTACT_INIT='NON'";
  b.tests = cellTest(0.1, "JEU", "MIN", 0.001, 1e-9) + cellTest(0.1, "JEU", "MAX", 0.001, 1e-9) +
            cellTest(0.1, "PRES", "MIN", 0.0, 1e-12) + cellTest(1.0, "PRES", "MIN", -sigma, 1e-9) +
            cellTest(1.0, "PRES", "MAX", -sigma, 1e-9) + cellTest(1.0, "CONT", "MIN", 1.0, 1e-12) +
            testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MIN", -sigma, 1e-9) +
            testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MAX", -sigma, 1e-9);
  const StudyRun r = runStudyIn("lac", "closing", b.mesh(), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("contact CONTINUE LAC"), std::string::npos);
  EXPECT_NE(r.message.find("Nombre de patchs LAC en contact : 3"), std::string::npos);
}

TEST(LacContact, ClosingGapWithSmoothedNormals) {
  // LISSAGE='OUI' on the same blocks, both ALGO_RESO_GEOM: the slave is flat, so the averaged
  // nodal normals are the cells' normals and the closed form holds as without smoothing
  const double sigma = 1000.0 / (1.0 - 0.09) * 0.008 / 2.0;
  for (const std::string geometry : {"", ", ALGO_RESO_GEOM='NEWTON'"}) {
    LacBlocks b;
    b.global = ", LISSAGE='OUI'" + geometry;
    b.zone = ", CONTACT_INIT='NON'";
    b.tests = cellTest(0.1, "JEU", "MIN", 0.001, 1e-9) + cellTest(1.0, "PRES", "MIN", -sigma, 1e-9) +
              cellTest(1.0, "PRES", "MAX", -sigma, 1e-9) +
              testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MIN", -sigma, 1e-9) +
              testResu(1.0, "DEPL", "LAGS_C", "B_YMIN", "MAX", -sigma, 1e-9);
    const StudyRun r = runStudyIn("lac", "smoothed", b.mesh(), b.comm());
    EXPECT_TRUE(passed(r)) << geometry;
  }
}

TEST(LacContact, ClosingGapOnNonMatchingHexahedra) {
  // 3D: HEXA8 blocks (4 and 3 cells along x and y), the slave faces cut into TRIA3 fans by
  // DECOUPE_LAC; uniaxial stress sigma = E (0.01 - 0.002) / 2 once closed
  const double sigma = 1000.0 * 0.008 / 2.0;
  LacBlocks b;
  b.threeD = true;
  b.zone = ", CONTACT_INIT='NON'";
  b.tests = cellTest(0.1, "JEU", "MIN", 0.001, 1e-9, "B_ZMIN") +
            cellTest(1.0, "PRES", "MIN", -sigma, 1e-9, "B_ZMIN") +
            cellTest(1.0, "PRES", "MAX", -sigma, 1e-9, "B_ZMIN") +
            testResu(1.0, "DEPL", "LAGS_C", "B_ZMIN", "MIN", -sigma, 1e-9);
  const StudyRun r = runStudyIn("lac", "closing_3d", b.mesh(), b.comm());
  EXPECT_TRUE(passed(r));
  EXPECT_NE(r.message.find("Nombre de patchs LAC en contact : 9"), std::string::npos);
}

TEST(LacContact, WhatIsNotImplementedIsRefusedNamingIt) {
  const struct {
    LacBlocks blocks;
    std::string id;
    std::string named;
  } cases[] = {
      {{true, true, ", LISSAGE='OUI'", "", ""}, "CONTACT_20", "LISSAGE='OUI' with ALGO_CONT='LAC' in 3D"},
      {{true, true, ", FROTTEMENT='COULOMB', ALGO_RESO_FROT='POINT_FIXE'", ", COULOMB=0.1", ""},
       "CONTACT_20",
       "ALGO_RESO_FROT='POINT_FIXE' with ALGO_CONT='LAC'"},
      {{false, true, ", FROTTEMENT='COULOMB', ALGO_RESO_FROT='POINT_FIXE'", ", COULOMB=0.1", ""},
       "CONTACT_20",
       "ALGO_RESO_FROT='POINT_FIXE' with ALGO_CONT='LAC'"},
      {{false, true, ", FROTTEMENT='COULOMB'", ", COULOMB=0.1, ALGO_FROT='PENALISATION'", ""},
       "CONTACT_20",
       "ALGO_FROT='PENALISATION' with ALGO_CONT='LAC'"},
      {{false, true, ", FROTTEMENT='COULOMB'", ", COULOMB=0.1, SEUIL_INIT=1.0", ""},
       "CONTACT_20",
       "SEUIL_INIT with ALGO_CONT='LAC'"},
      {{false, false, "", "", ""}, "CONTACT_LAC_1", "carries no LAC patch"},
      {{false, true, "", ", RESI_APPA=1e-6", ""}, "CATALOG_17", "RESI_APPA"},
  };
  for (const auto& c : cases) {
    const StudyRun r = runStudyIn("lac", "refused", c.blocks.mesh(), c.blocks.comm(), true);
    EXPECT_FALSE(passed(r)) << c.named;
    EXPECT_NE(r.message.find(c.id), std::string::npos) << c.named << "\n" << r.message;
    EXPECT_NE(r.message.find(c.named), std::string::npos) << c.named << "\n" << r.message;
  }
}

} // namespace
} // namespace stella::contact
