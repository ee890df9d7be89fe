// MODI_REPERE, CALC_PRESSION and IMPR_RESU FORMAT='ASTER' on a small elastic result: what is not
// implemented is refused by name ("not implemented yet"), bad input gets a located error with
// the keyword, and a wrong frame is never applied silently.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <string>

namespace stella {
namespace {

using testing::CommRun;
using testing::runComm;

// A 2 x 2 QUAD4 square in D_PLAN, pulled on XMAX: result R with DEPL, SIEF_ELGA and SIGM_NOEU.
const char* const kStudy =
    "DEBUT()\n"
    "MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
    "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
    "MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.25))\n"
    "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
    "CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='XMIN', DX=0.0), _F(GROUP_NO='ORIGIN', DY=0.0)),\n"
    "                    PRES_REP=_F(GROUP_MA='XMAX', PRES=-10.0))\n"
    "R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))\n"
    "R = CALC_CHAMP(reuse=R, RESULTAT=R, CONTRAINTE='SIGM_NOEU')\n";

struct Case {
  std::string call;
  const char* code;
  const char* text;
};

TEST(FrameAndPressureErrors, RefusedByNameOrLocated) {
  const auto dir = testing::tempDir("frame_errors");
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}});
  m.setDimension(2);
  writeMedMesh(dir / "m.med", m, "MA");
  const std::string tens = "MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', TYPE_CHAM='TENS_2D', "
                           "NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY'))";
  const Case cases[] = {
      {"X = MODI_REPERE(RESULTAT=R, REPERE='COQUE', AFFE=_F(ANGL_NAUT=30.0), "
       "MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', "
       "TYPE_CHAM='TENS_2D', NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY')))",
       "MODI_REPERE_1", "REPERE='COQUE' is not implemented yet"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=30.0), "
       "MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', "
       "TYPE_CHAM='COQUE_GENE', NOM_CMP=('SIXX', 'SIYY')))",
       "MODI_REPERE_1", "TYPE_CHAM='COQUE_GENE' is not implemented yet"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='CYLINDRIQUE', AFFE=_F(ORIGINE=(0.0, 0.0), AXE_Z=(0.0, 0.0, "
       "1.0)), " +
           std::string(tens) + ")",
       "MODI_REPERE_2", "AXE_Z is given on a 2D mesh"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=(30.0, 10.0, 0.0)), " +
           std::string(tens) + ")",
       "MODI_REPERE_2", "ANGL_NAUT takes one angle"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(VECT_X=(1.0, 0.0, 0.0), VECT_Y=(0.0, 1.0, "
       "0.0)), " +
           std::string(tens) + ")",
       "MODI_REPERE_2", "VECT_X / VECT_Y define a frame of a 3D mesh"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=30.0), "
       "MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', "
       "TYPE_CHAM='TENS_2D', NOM_CMP=('SIXX', 'SIYY')))",
       "MODI_REPERE_2", "needs 4 components in NOM_CMP, 2 given"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=30.0), "
       "MODI_CHAM=_F(NOM_CHAM='DEPL', "
       "TYPE_CHAM='VECT_2D', NOM_CMP=('DX', 'DZ')))",
       "MODI_REPERE_2", "has no component DZ"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='UTILISATEUR', AFFE=_F(ANGL_NAUT=30.0), "
       "MODI_CHAM=_F(NOM_CHAM='EPSI_NOEU', "
       "TYPE_CHAM='TENS_2D', NOM_CMP=('EPXX', 'EPYY', 'EPZZ', 'EPXY')))",
       "MODI_REPERE_2", "has no field EPSI_NOEU at NUME_ORDRE 1"},
      {"X = MODI_REPERE(RESULTAT=R, REPERE='CYLINDRIQUE', AFFE=_F(ORIGINE=(0.0, 0.0), GROUP_NO='ORIGIN'), "
       "MODI_CHAM=_F(NOM_CHAM='SIEF_ELGA', TYPE_CHAM='TENS_2D', NOM_CMP=('SIXX', 'SIYY', 'SIZZ', 'SIXY')))",
       "MODI_REPERE_1", "AFFE GROUP_NO on a field that is not nodal (SIEF_ELGA of R) is not implemented yet"},
      {"R = CALC_PRESSION(reuse=R, MAILLAGE=MA, RESULTAT=R, GROUP_MA='SURFACE', TOUT_ORDRE='OUI')",
       "CALC_PRESSION_1", "is not a skin cell of this 2D mesh"},
      {"IMPR_RESU(FORMAT='ASTER', RESU=_F(RESULTAT=R))", "IMPR_RESU_1",
       "FORMAT='ASTER' with RESULTAT is not implemented yet"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const CommRun r = runComm(dir, "case" + std::to_string(k++), std::string(kStudy) + c.call + "\nFIN()\n",
                              {{20, dir / "m.med"}, {26, dir / "out.mail"}});
    EXPECT_EQ(r.diagnostic, JobDiagnostic::Error) << c.call << "\n" << r.message;
    EXPECT_NE(r.message.find(c.code), std::string::npos) << c.call << "\n" << r.message;
    EXPECT_NE(r.message.find(c.text), std::string::npos) << c.call << "\n" << r.message;
  }
}

// The frame of a point on the axis: the centre of the first cell that holds it (code_aster's
// rule), so a node at ORIGINE still gets a rotation (no NaN, no error). LIRE_MAILLAGE reads the
// MED cells by type, edges first: ORIGIN's first cell is the YMIN edge (0, 0)-(0.5, 0), centre
// (0.25, 0), e_r = X: sigma_xx = 10 stays sigma_rr = 10, sigma_tt = sigma_rt = 0.
TEST(FrameAndPressureErrors, NodeOnTheAxisTakesItsCellCentre) {
  const auto dir = testing::tempDir("frame_axis");
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}});
  m.setDimension(2);
  writeMedMesh(dir / "m.med", m, "MA");
  const CommRun r = runComm(
      dir, "axis",
      std::string(kStudy) +
          "C = MODI_REPERE(RESULTAT=R, REPERE='CYLINDRIQUE', AFFE=_F(ORIGINE=(0.0, 0.0)),\n"
          "    MODI_CHAM=_F(NOM_CHAM='SIGM_NOEU', TYPE_CHAM='TENS_2D', NOM_CMP=('SIXX', 'SIYY', 'SIZZ', "
          "'SIXY')))\n"
          "TEST_RESU(RESU=(_F(RESULTAT=C, NUME_ORDRE=1, NOM_CHAM='SIGM_NOEU', NOM_CMP='SIXX', "
          "GROUP_NO='ORIGIN',\n"
          "    VALE_CALC=10.0, VALE_REFE=10.0, REFERENCE='ANALYTIQUE', PRECISION=1.0e-9),\n"
          "    _F(RESULTAT=C, NUME_ORDRE=1, NOM_CHAM='SIGM_NOEU', NOM_CMP='SIZZ', GROUP_NO='ORIGIN',\n"
          "    VALE_CALC=0.0, VALE_REFE=0.0, CRITERE='ABSOLU', REFERENCE='ANALYTIQUE', PRECISION=1.0e-9),\n"
          "    _F(RESULTAT=C, NUME_ORDRE=1, NOM_CHAM='SIGM_NOEU', NOM_CMP='SIXY', GROUP_NO='ORIGIN',\n"
          "    VALE_CALC=0.0, VALE_REFE=0.0, CRITERE='ABSOLU', REFERENCE='ANALYTIQUE', PRECISION=1.0e-9)))\n"
          "FIN()\n",
      {{20, dir / "m.med"}});
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
}

} // namespace
} // namespace stella
