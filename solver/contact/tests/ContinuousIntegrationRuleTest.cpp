// The integration schemes of the continuous contact (INTEGRATION, ORDRE_INT): every rule integrates
// exactly the polynomials of its degree on its reference cell and not those of the next degree
// (the degree is sharp), with code_aster's point counts and a few of its published weights.

#include "solver/contact/ContinuousIntegrationRule.hpp"
#include "solver/contact/tests/ContactStudyRun.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

namespace stella::contact {
namespace {

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}
double segmentMoment(int k) {
  return k % 2 == 0 ? 2.0 / (k + 1) : 0.0;
}

enum class Shape { Segment, Triangle, Quadrangle };

Shape shapeOf(CellType t) {
  if (t == CellType::SEG2 || t == CellType::SEG3) {
    return Shape::Segment;
  }
  return t == CellType::TRIA3 || t == CellType::TRIA6 ? Shape::Triangle : Shape::Quadrangle;
}

// Integral of x^a y^b over the reference cell, exact.
double exact(Shape s, int a, int b) {
  switch (s) {
  case Shape::Segment:
    return b == 0 ? segmentMoment(a) : 0.0;
  case Shape::Triangle:
    return factorial(a) * factorial(b) / factorial(a + b + 2);
  case Shape::Quadrangle:
    return segmentMoment(a) * segmentMoment(b);
  }
  return 0.0;
}

double integrate(const ContactIntegrationRule& r, int a, int b) {
  double sum = 0.0;
  for (int p = 0; p < r.size(); ++p) {
    const auto& x = r.points[static_cast<std::size_t>(p)];
    sum += r.weights[static_cast<std::size_t>(p)] * std::pow(x[0], a) * std::pow(x[1], b);
  }
  return sum;
}

// The monomials of "degree d" of the shape: x^d (SEG), x^a y^(d-a) (TRIA), x^a y^b with
// max(a, b) = d (QUAD, tensor rules).
std::vector<std::pair<int, int>> monomials(Shape s, int d) {
  std::vector<std::pair<int, int>> m;
  if (s == Shape::Segment) {
    m.emplace_back(d, 0);
  } else if (s == Shape::Triangle) {
    for (int a = 0; a <= d; ++a) {
      m.emplace_back(a, d - a);
    }
  } else {
    for (int a = 0; a <= d; ++a) {
      m.emplace_back(a, d);
      m.emplace_back(d, a);
    }
  }
  return m;
}

// Exact to round-off up to the rule's degree, wrong (by more than 1e-8) for some monomial of the
// next one.
void expectDegree(CellType type, const ContactIntegrationRule& r, const std::string& what) {
  const Shape s = shapeOf(type);
  double scale = 0.0;
  for (double w : r.weights) {
    scale += std::fabs(w);
  }
  ASSERT_GT(r.size(), 0) << what;
  for (int d = 0; d <= r.degree; ++d) {
    for (const auto& [a, b] : monomials(s, d)) {
      EXPECT_NEAR(integrate(r, a, b), exact(s, a, b), 1e-14 * scale) << what << " x^" << a << " y^" << b;
    }
  }
  double worst = 0.0;
  for (const auto& [a, b] : monomials(s, r.degree + 1)) {
    worst = std::max(worst, std::fabs(integrate(r, a, b) - exact(s, a, b)));
  }
  EXPECT_GT(worst, 1e-8) << what << ": exact beyond its degree " << r.degree;
}

const std::vector<CellType> slaveTypes{CellType::SEG2,  CellType::SEG3,  CellType::TRIA3, CellType::TRIA6,
                                       CellType::QUAD4, CellType::QUAD8, CellType::QUAD9};

TEST(ContinuousIntegrationRule, GaussIsExactToItsDegreeOnEveryCell) {
  for (CellType t : slaveTypes) {
    for (int n = 1; n <= 6; ++n) {
      const auto r = contactIntegrationRule(t, ContactIntegration::Gauss, n);
      const std::string what = fmt::format("{} GAUSS {}", name(t), n);
      expectDegree(t, r, what);
      const Shape s = shapeOf(t);
      const int triangleCount[] = {1, 3, 4, 6, 7, 12};
      EXPECT_EQ(r.size(), s == Shape::Segment    ? n
                          : s == Shape::Triangle ? triangleCount[n - 1]
                                                 : n * n)
          << what;
      EXPECT_EQ(r.degree, s == Shape::Triangle ? n : 2 * n - 1) << what;
    }
  }
  // the 4-point triangle rule of degree 3 and its negative centroid weight
  const auto r = contactIntegrationRule(CellType::TRIA3, ContactIntegration::Gauss, 3);
  EXPECT_NEAR(r.weights[0], -27.0 / 96.0, 1e-16);
}

TEST(ContinuousIntegrationRule, SimpsonIsExactToItsDegreeOnEveryCell) {
  for (CellType t : slaveTypes) {
    for (int m = 1; m <= 4; ++m) {
      const auto r = contactIntegrationRule(t, ContactIntegration::Simpson, m);
      const std::string what = fmt::format("{} SIMPSON {}", name(t), m);
      expectDegree(t, r, what);
      const Shape s = shapeOf(t);
      EXPECT_EQ(r.size(), s == Shape::Segment    ? 2 * m + 1
                          : s == Shape::Triangle ? (2 * m + 1) * (2 * m + 2) / 2
                                                 : (2 * m + 1) * (2 * m + 1))
          << what;
      EXPECT_EQ(r.degree, s == Shape::Triangle ? 1 : 3) << what;
    }
  }
  // code_aster's weights for 2 subdivisions: triangle x 120 (corners 1, vertices on the edges 3,
  // interior vertex... none; edge midpoints 4, interior midpoints 8), quadrangle x 36
  const auto tri = contactIntegrationRule(CellType::TRIA3, ContactIntegration::Simpson, 2);
  EXPECT_NEAR(tri.weights[0] * 120.0, 1.0, 1e-13); // (0, 0)
  EXPECT_NEAR(tri.weights[1] * 120.0, 4.0, 1e-13); // (1/4, 0)
  EXPECT_NEAR(tri.weights[2] * 120.0, 3.0, 1e-13); // (1/2, 0)
  EXPECT_NEAR(tri.weights[6] * 120.0, 8.0, 1e-13); // (1/4, 1/4)
  const auto quad = contactIntegrationRule(CellType::QUAD4, ContactIntegration::Simpson, 2);
  EXPECT_NEAR(quad.weights[6] * 36.0, 16.0, 1e-13); // (-1/2, -1/2)
  EXPECT_NEAR(quad.weights[12] * 36.0, 4.0, 1e-13); // (0, 0)
}

TEST(ContinuousIntegrationRule, NewtonCotesIsExactToItsDegreeOnEveryCell) {
  for (CellType t : slaveTypes) {
    for (int p = 3; p <= 8; ++p) {
      const auto r = contactIntegrationRule(t, ContactIntegration::NewtonCotes, p);
      const std::string what = fmt::format("{} NCOTES {}", name(t), p);
      expectDegree(t, r, what);
      const Shape s = shapeOf(t);
      EXPECT_EQ(r.size(), s == Shape::Segment    ? p + 1
                          : s == Shape::Triangle ? (p + 1) * (p + 2) / 2
                                                 : (p + 1) * (p + 1))
          << what;
    }
  }
  // Boole's rule (p = 4): 7 32 12 32 7 / 45 on [-1, 1]; the triangle's (x 90): corners 0, quarter
  // points 4, edge midpoints -1, interior 8 (code_aster's table)
  const auto seg = contactIntegrationRule(CellType::SEG2, ContactIntegration::NewtonCotes, 4);
  const double boole[] = {7, 32, 12, 32, 7};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(seg.weights[static_cast<std::size_t>(i)] * 45.0, boole[i], 1e-12);
  }
  const auto tri = contactIntegrationRule(CellType::TRIA3, ContactIntegration::NewtonCotes, 4);
  EXPECT_NEAR(tri.weights[0] * 90.0, 0.0, 1e-12);  // (0, 0)
  EXPECT_NEAR(tri.weights[1] * 90.0, 4.0, 1e-12);  // (1/4, 0)
  EXPECT_NEAR(tri.weights[2] * 90.0, -1.0, 1e-12); // (1/2, 0)
  EXPECT_NEAR(tri.weights[6] * 90.0, 8.0, 1e-12);  // (1/4, 1/4)
}

TEST(ContinuousIntegrationRule, AutoIsTheNodesOfTheLinearCellsAndOfSeg3Quad9) {
  for (CellType t : slaveTypes) {
    const auto r = contactIntegrationRule(t, ContactIntegration::Auto, 0);
    const std::string what = fmt::format("{} AUTO", name(t));
    expectDegree(t, r, what);
    const bool nodal = t != CellType::TRIA6 && t != CellType::QUAD8;
    EXPECT_EQ(r.atNodes(), nodal) << what;
    for (double w : r.weights) {
      EXPECT_GT(w, 0.0) << what;
    }
  }
  EXPECT_EQ(contactIntegrationRule(CellType::TRIA6, ContactIntegration::Auto, 0).size(), 6);
  EXPECT_EQ(contactIntegrationRule(CellType::TRIA6, ContactIntegration::Auto, 0).degree, 4);
  // QUAD8: Simpson's 3 x 3 points, the centre not a node
  const auto quad8 = contactIntegrationRule(CellType::QUAD8, ContactIntegration::Auto, 0);
  EXPECT_EQ(quad8.size(), 9);
  EXPECT_EQ(std::count(quad8.node.begin(), quad8.node.end(), -1), 1);
  // the node map of the nodal rules: SEG3 Simpson's 1/3 4/3 1/3, QUAD4's unit weights
  const auto seg3 = contactIntegrationRule(CellType::SEG3, ContactIntegration::Auto, 0);
  for (int p = 0; p < 3; ++p) {
    EXPECT_NEAR(seg3.weights[static_cast<std::size_t>(p)],
                seg3.node[static_cast<std::size_t>(p)] == 2 ? 4.0 / 3.0 : 1.0 / 3.0, 1e-15);
  }
}

TEST(ContinuousIntegrationRule, RefusesOrdersOutsideTheCatalogueRangeAndOtherCells) {
  EXPECT_THROW(contactIntegrationRule(CellType::SEG2, ContactIntegration::Gauss, 7), std::invalid_argument);
  EXPECT_THROW(contactIntegrationRule(CellType::TRIA3, ContactIntegration::Simpson, 5),
               std::invalid_argument);
  EXPECT_THROW(contactIntegrationRule(CellType::QUAD4, ContactIntegration::NewtonCotes, 2),
               std::invalid_argument);
  EXPECT_THROW(contactIntegrationRule(CellType::HEXA8, ContactIntegration::Auto, 0), std::invalid_argument);
}

// Two blocks [0,1]^d, B above A with a gap 0.002 closed by pushing B's top by 0.01 t; A held on its
// bottom, symmetry planes at x = 0 (and y = 0): uniaxial compression sigma = E' (0.01 t - 0.002) / 2
// once in contact (E' = E / (1 - nu^2) in plane strain, E in 3D), E = 1000, nu = 0.3. The
// continuous formulation at the contact points of `zone` must give LAGS_C = -sigma on every slave
// node (the interpolated pressure is uniform), sum RN = the support's reaction = sigma x area.
std::string pointPatchComm(bool threeD, const std::string& zone, double precision) {
  const std::string up = threeD ? "Z" : "Y";
  const std::string d = threeD ? "DZ" : "DY";
  const double modulus = threeD ? 1000.0 : 1000.0 / (1.0 - 0.09);
  std::string tests;
  for (double t : {0.3, 1.0}) {
    const double sigma = modulus * (0.01 * t - 0.002) / 2.0;
    tests += testResu(t, "DEPL", "LAGS_C", "B_" + up + "MIN", "MIN", -sigma, precision);
    tests += testResu(t, "DEPL", "LAGS_C", "B_" + up + "MIN", "MAX", -sigma, precision);
    // RN is a norm (|RN|): the signed normal component adds up (QUAD8 corners carry negative forces)
    tests += testResu(t, "CONT_NOEU", "RN" + up, "B_" + up + "MIN", "SOMM", sigma, precision);
    tests += testResu(t, "REAC_NODA", d, "A_" + up + "MIN", "SOMM", sigma, precision);
  }
  tests += testResu(0.1, "DEPL", "LAGS_C", "B_" + up + "MIN", "MIN", 0.0, 1e-12);
  const std::string sym =
      threeD ? "_F(GROUP_MA=('A_XMIN', 'B_XMIN'), DX=0.0), _F(GROUP_MA=('A_YMIN', 'B_YMIN'), "
               "DY=0.0), _F(GROUP_MA='A_ZMIN', DZ=0.0)"
             : "_F(GROUP_MA=('A_XMIN', 'B_XMIN'), DX=0.0), _F(GROUP_MA='A_YMIN', DY=0.0)";
  return fmt::format(
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
      "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{}'))\n"
      "MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))\n"
      "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
      "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=({}))\n"
      "PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_{}MAX', {}=-0.01))\n"
      "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
      "L = DEFI_LIST_REEL(VALE=(0.0, 0.1, 0.3, 1.0))\n"
      "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE',\n"
      "                    ZONE=_F(GROUP_MA_MAIT='A_{}MAX', GROUP_MA_ESCL='B_{}MIN'{}))\n"
      "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PUSH, "
      "FONC_MULT=F)), INCREMENT=_F(LIST_INST=L), CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9), "
      "SOLVEUR=_F(METHODE='MULT_FRONT'))\n"
      "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, FORCE=('FORC_NODA', 'REAC_NODA'))\n"
      "{}"
      "FIN()\n",
      threeD ? "3D" : "D_PLAN", sym, up, d, up, up, zone, tests);
}

StudyRun runPatch(const std::string& name, CellType cell, int na, int nb, const std::string& zone,
                  double precision) {
  const bool threeD = info(cell).dimension == 3;
  Mesh mesh = testing::twoBlocks(cell, na, nb, 0.002);
  return runStudyIn("stella_contact_integration", name, mesh, pointPatchComm(threeD, zone, precision));
}

// Matching meshes: every scheme reproduces the uniform pressure to round-off (the slave and
// master shape functions agree on the interface, so the point rows are exact).
TEST(ContinuousIntegrationRule, PatchTestWithEverySchemeOnQuad4Blocks) {
  for (const std::string zone :
       {", INTEGRATION='GAUSS', ORDRE_INT=2", ", INTEGRATION='GAUSS'", ", INTEGRATION='GAUSS', ORDRE_INT=6",
        ", INTEGRATION='SIMPSON'", ", INTEGRATION='SIMPSON', ORDRE_INT=4", ", INTEGRATION='NCOTES'",
        ", INTEGRATION='NCOTES', ORDRE_INT=8"}) {
    const StudyRun r = runPatch("patch_quad4", CellType::QUAD4, 4, 4, zone, 1e-8);
    EXPECT_TRUE(passed(r)) << zone << "\n" << r.message;
  }
}

TEST(ContinuousIntegrationRule, PatchTestAtPointsOnQuadraticAnd3DSlaveCells) {
  const struct {
    CellType cell;
    std::string zone;
  } cases[] = {
      {CellType::QUAD8, ", INTEGRATION='GAUSS'"},               // SEG3 slave cells
      {CellType::HEXA8, ", INTEGRATION='GAUSS'"},               // QUAD4
      {CellType::HEXA20, ""},                                   // QUAD8, AUTO: 3 x 3 Simpson points
      {CellType::HEXA20, ", INTEGRATION='GAUSS'"},              // QUAD8
      {CellType::TETRA10, ""},                                  // TRIA6, AUTO: 6 Gauss points
      {CellType::TETRA10, ", INTEGRATION='GAUSS', ORDRE_INT=5"} // TRIA6, 7 points per cell
  };
  for (const auto& c : cases) {
    const StudyRun r = runPatch(fmt::format("patch_{}", name(c.cell)), c.cell, 2, 2, c.zone, 1e-8);
    EXPECT_TRUE(passed(r)) << name(c.cell) << c.zone << "\n" << r.message;
  }
}

// What the contact points do not implement yet is refused at the keyword (CONTACT_20).
TEST(ContinuousIntegrationRule, WhatThePointsDoNotImplementIsRefused) {
  const struct {
    std::string global;
    std::string zone;
    std::string named;
  } cases[] = {
      {"", ", NORMALE='ESCL', INTEGRATION='NCOTES'", "NORMALE other than 'MAIT'"},
      {"", ", INTEGRATION='GAUSS', ORDRE_INT=1",
       "gives 2 contact points on the slave cells of zone 1, fewer "
       "than their 3 slave nodes"},
  };
  for (const auto& c : cases) {
    std::string comm = pointPatchComm(false, c.zone, 1e-8);
    const std::string formulation = "FORMULATION='CONTINUE',";
    comm.replace(comm.find(formulation), formulation.size(), formulation + c.global);
    const StudyRun r = runStudyIn("stella_contact_integration", "refused",
                                  testing::twoBlocks(CellType::QUAD4, 2, 2, 0.002), comm, true);
    EXPECT_FALSE(passed(r)) << c.named;
    EXPECT_NE(r.message.find(c.named), std::string::npos) << r.message;
    const bool illPosed = c.named.find("fewer") != std::string::npos;
    EXPECT_NE(r.message.find(illPosed ? "CONTACT_INTEG_1" : "CONTACT_20"), std::string::npos) << r.message;
    if (!illPosed) {
      EXPECT_NE(r.message.find("not implemented yet"), std::string::npos) << r.message;
    }
  }
}

// Coulomb friction at points in 3D against symmetry planes (notice §4.7): the slave block's faces
// x = 0 and y = 0 hold DX and DY of both blocks, so the weighted slip conditions of the slave nodes
// there (coupled through their cells' points) repeat the symmetry: CONTACT_11 (redundant). With those
// nodes in SANS_GROUP_NO_FR the points of their cells carry no friction, the conditions left are
// independent, and the two blocks of one material, expanding alike under the uniform pressure (no
// relative slip), reproduce the frictionless patch test exactly.
TEST(ContinuousIntegrationRule, FrictionAtPointsAgainstSymmetryPlanesNeedsSansGroupNoFr) {
  for (const bool excluded : {true, false}) {
    const std::string zone = std::string(", COULOMB=0.2, INTEGRATION='GAUSS'") +
                             (excluded ? ", SANS_GROUP_NO_FR=('B_XMIN', 'B_YMIN')" : "");
    std::string comm = pointPatchComm(true, zone, 1e-8);
    const std::string formulation = "FORMULATION='CONTINUE',";
    comm.replace(comm.find(formulation), formulation.size(), formulation + " FROTTEMENT='COULOMB',");
    const StudyRun r =
        runStudyIn("stella_contact_integration", excluded ? "symmetry_fr" : "symmetry_redundant",
                   testing::twoBlocks(CellType::HEXA8, 4, 4, 0.002), comm, !excluded);
    if (excluded) {
      EXPECT_TRUE(passed(r)) << r.message;
    } else {
      EXPECT_FALSE(passed(r));
      EXPECT_NE(r.message.find("CONTACT_11"), std::string::npos) << r.message;
    }
  }
}

} // namespace
} // namespace stella::contact
