// CALC_PRESSION and MODI_REPERE in 3D on a closed form: a HEXA8 cube (2 x 2 x 2 cells) on
// rollers (DX = 0 on XMIN, DY = 0 on YMIN, DZ = 0 on ZMIN) under a pressure p = 10 on ZMAX has
// sigma_zz = -p everywhere and the other components 0. Then PRES = p on ZMAX and on ZMIN, 0 on
// XMAX (one group per call, GEOMETRIE='DEFORMEE'); asked on ZMAX and XMAX together, the nodes of
// their common edge get the mean of the two faces' values, p / 2 (what the mean nodal normal
// (1, 0, 1)/sqrt2 gives too), the others p and 0; ANGL_NAUT=(0, 90, 0) and VECT_X=Z, VECT_Y=Y both make
// x' = +-Z, so SIXX' = -p and SIZZ' = sigma_xx = 0; the cylindrical frame of axis X through
// (0, 0, 0) has e_r = Z on the edge y = 0, z = 1: SIXX' = sigma_rr = -p, SIYY' = sigma_(axis) =
// sigma_xx = 0, SIZZ' = sigma_tt = 0.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace stella {
namespace {

using testing::CommRun;
using testing::runComm;

std::string test(const std::string& result, const std::string& field, const std::string& cmp,
                 const std::string& where, const std::string& kind, double value) {
  const std::string v = std::to_string(value);
  return "    _F(RESULTAT=" + result + ", NUME_ORDRE=1, NOM_CHAM='" + field + "', NOM_CMP='" + cmp + "', " +
         where + ", TYPE_TEST='" + kind + "', VALE_CALC=" + v + ", VALE_REFE=" + v +
         ", REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1.0e-9),\n";
}

TEST(FrameAndPressure3D, CubeUnderPressure) {
  const auto dir = testing::tempDir("frame3d");
  writeMedMesh(dir / "m.med", buildStructuredMesh({CellType::HEXA8, {2, 2, 2}, {1, 1, 1}, {0, 0, 0}}), "MA");
  std::string comm =
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
      "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(NOM='EDGE', INTERSEC=('YMIN', 'ZMAX')))\n"
      "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))\n"
      "MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.25))\n"
      "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
      "CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='XMIN', DX=0.0), _F(GROUP_MA='YMIN', DY=0.0),\n"
      "    _F(GROUP_MA='ZMIN', DZ=0.0)), PRES_REP=_F(GROUP_MA='ZMAX', PRES=10.0))\n"
      "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))\n"
      "R = CALC_CHAMP(reuse=R, RESULTAT=R, CONTRAINTE='SIGM_NOEU')\n"
      "R = CALC_PRESSION(reuse=R, MAILLAGE=MA, RESULTAT=R, GROUP_MA=('ZMAX', 'ZMIN', 'XMAX'), "
      "TOUT_ORDRE='OUI')\n"
      "T = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=(0.0, 90.0, 0.0)), INFO=2,\n"
      "    TITRE='cube seen from Z',\n"
      "    MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', TYPE_CHAM='TENS_3D',\n"
      "                 NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ')))\n"
      "V = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(VECT_X=(0.0, 0.0, 1.0), VECT_Y=(0.0, 1.0, "
      "0.0)),\n"
      "    MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', TYPE_CHAM='TENS_3D',\n"
      "                 NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ')))\n"
      "C = MODI_REPERE(RESULTAT=R, REPERE='CYLINDRIQUE', AFFE=_F(ORIGINE=(0.0, 0.0, 0.0), AXE_Z=(2.0, 0.0, "
      "0.0)),\n"
      "    MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', TYPE_CHAM='TENS_3D',\n"
      "                 NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ')))\n"
      "TEST_RESU(RESU=(\n";
  for (const char* kind : {"MIN", "MAX"}) {
    for (const char* r : {"T", "V"}) {
      comm += test(r, "SIGM_NOEU", "SIXX", "GROUP_MA='VOLUME'", kind, -10.0);
      comm += test(r, "SIGM_NOEU", "SIZZ", "GROUP_MA='VOLUME'", kind, 0.0);
      comm += test(r, "SIGM_NOEU", "SIXZ", "GROUP_MA='VOLUME'", kind, 0.0);
    }
    comm += test("C", "SIGM_NOEU", "SIXX", "GROUP_NO='EDGE'", kind, -10.0);
    comm += test("C", "SIGM_NOEU", "SIYY", "GROUP_NO='EDGE'", kind, 0.0);
    comm += test("C", "SIGM_NOEU", "SIZZ", "GROUP_NO='EDGE'", kind, 0.0);
  }
  comm += "))\n";
  // (groups, tested group, MIN, MAX)
  const std::tuple<const char*, const char*, double, double> pressures[] = {
      {"'ZMAX'", "ZMAX", 10.0, 10.0},         {"'ZMIN'", "ZMIN", 10.0, 10.0},
      {"'XMAX'", "XMAX", 0.0, 0.0},           {"('ZMAX', 'XMAX')", "ZMAX", 5.0, 10.0},
      {"('ZMAX', 'XMAX')", "XMAX", 0.0, 5.0},
  };
  for (const auto& [groups, group, low, high] : pressures) {
    comm += std::string("R = CALC_PRESSION(reuse=R, MAILLAGE=MA, RESULTAT=R, GROUP_MA=") + groups +
            ", TOUT_ORDRE='OUI', INFO=2)\nTEST_RESU(RESU=(\n";
    comm += test("R", "PRES_NOEU", "PRES", std::string("GROUP_MA='") + group + "'", "MIN", low);
    comm += test("R", "PRES_NOEU", "PRES", std::string("GROUP_MA='") + group + "'", "MAX", high);
    comm += "))\n";
  }
  comm += "FIN()\n";
  const CommRun r = runComm(dir, "cube", comm, {{20, dir / "m.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  // TITRE, and INFO=2: the frame's rows (x' = -Z, y' = Y, z' = X) and the range of PRES.
  EXPECT_NE(r.message.find("MODI_REPERE: TITRE cube seen from Z"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("0.000000000  0.000000000 -1.000000000"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("1.000000000  0.000000000  0.000000000"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("PRES on 9 node(s)"), std::string::npos) << r.message;
}

} // namespace
} // namespace stella
