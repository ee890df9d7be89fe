// CREA_CHAMP OPERATION='EXTR' and TEST_RESU CHAM_NO / CHAM_ELEM on the unit cube of
// testcases/plate_plasticity (HEXA8, ELAS E = 200000, NU = 0.3), pulled by DX = 1e-3 RAMP(t) on
// x = 1 with symmetry planes x = 0, y = 0, z = 0. The state is uniform and exact for the element:
// DX = e x, DY = -NU e y, DZ = -NU e z, SIXX = E e, the other stresses 0, with e = 1e-3 RAMP(t)
// (RAMP(1) = 1, RAMP(2) = 3). Node N8 is (1, 1, 1); cell M83 is a HEXA8 with node N5.

#include "solver/database/ConceptStore.hpp"
#include "solver/nonlinear/tests/StudyRun.hpp"
#include "solver/post/FieldConcept.hpp"
#include "solver/post/tests/PulledCube.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::kCubeMesh;
using testing::runStudy;

const std::string kPreamble =
    testing::kCubeModel +
    R"(BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0)))
PULL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='X1', DX=1.0e-3))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 2.0, 3.0))
TIMES = DEFI_LIST_REEL(VALE=(0.0, 1.0, 2.0))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                  COMPORTEMENT=_F(RELATION='ELAS', TOUT='OUI'), INCREMENT=_F(LIST_INST=TIMES))
R = CALC_CHAMP(reuse=R, RESULTAT=R, CONTRAINTE=('SIEF_ELNO', 'SIEF_NOEU'))
)";

TEST(CreaChamp, ExtractsFieldsThatTestResuChecks) {
  const std::string comm = kPreamble + R"(
U1 = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=R, NOM_CHAM='DEPL', NUME_ORDRE=1)
U2 = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=R, NOM_CHAM='DEPL', INST=2.0 + 1.0e-9,
                CRITERE='ABSOLU', PRECISION=1.0e-6)
SG = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELGA_SIEF_R', RESULTAT=R, NOM_CHAM='SIEF_ELGA', INST=1.0)
SE = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELNO_SIEF_R', RESULTAT=R, NOM_CHAM='SIEF_ELNO', INST=1.0)
SN = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_SIEF_R', RESULTAT=R, NOM_CHAM='SIEF_NOEU', INST=1.0)
TEST_RESU(CHAM_NO=(
    _F(CHAM_GD=U1, NOEUD='N8', NOM_CMP='DX', VALE_CALC=1.0e-3, REFERENCE='ANALYTIQUE', VALE_REFE=1.0e-3,
       PRECISION=1.0e-9),
    _F(CHAM_GD=U1, NOEUD='N8', NOM_CMP='DY', VALE_CALC=-3.0e-4, REFERENCE='ANALYTIQUE', VALE_REFE=-3.0e-4,
       PRECISION=1.0e-9),
    _F(CHAM_GD=U1, GROUP_NO='X1', NOM_CMP='DX', TYPE_TEST='MIN', VALE_CALC=1.0e-3, REFERENCE='ANALYTIQUE',
       VALE_REFE=1.0e-3, PRECISION=1.0e-9),
    _F(CHAM_GD=U1, TYPE_TEST='MAX', VALE_CALC=1.0e-3, REFERENCE='ANALYTIQUE', VALE_REFE=1.0e-3,
       PRECISION=1.0e-9),
    _F(CHAM_GD=U2, NOEUD='N8', NOM_CMP='DZ', VALE_CALC=-9.0e-4, REFERENCE='ANALYTIQUE', VALE_REFE=-9.0e-4,
       PRECISION=1.0e-9),
    _F(CHAM_GD=SN, NOM_CMP='SIXX', TYPE_TEST='MIN', VALE_CALC=200.0, REFERENCE='ANALYTIQUE',
       VALE_REFE=200.0, PRECISION=1.0e-9),
))
TEST_RESU(CHAM_ELEM=(
    _F(CHAM_GD=SG, MAILLE='M83', POINT=1, SOUS_POINT=1, NOM_CMP='SIXX', VALE_CALC=200.0,
       REFERENCE='ANALYTIQUE', VALE_REFE=200.0, PRECISION=1.0e-9),
    _F(CHAM_GD=SG, GROUP_MA='ALL', NOM_CMP='SIYY', TYPE_TEST='MAX', VALE_CALC=0.0, REFERENCE='ANALYTIQUE',
       VALE_REFE=0.0, CRITERE='ABSOLU', PRECISION=1.0e-9, ORDRE_GRANDEUR=200.0),
    _F(CHAM_GD=SE, MAILLE='M83', NOEUD='N5', NOM_CMP='SIXX', VALE_CALC=200.0, REFERENCE='ANALYTIQUE',
       VALE_REFE=200.0, PRECISION=1.0e-9),
    _F(CHAM_GD=SE, GROUP_MA='ALL', NOM_CMP='SIXX', TYPE_TEST='MAX', VALE_CALC=200.0, REFERENCE='ANALYTIQUE',
       VALE_REFE=200.0, PRECISION=1.0e-9),
))
FIN()
)";
  auto run = runStudy("crea_champ", comm, kCubeMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_EQ(run->session->counts().testsOk, 20) << run->resu.str();
  EXPECT_EQ(run->session->counts().testsNook, 0) << run->resu.str();
  const auto& concepts = run->session->concepts();
  ASSERT_TRUE(concepts.find("U1") && concepts.find("SG"));
  EXPECT_EQ(concepts.find("U1")->type, "cham_no");
  EXPECT_EQ(concepts.find("SG")->type, "cham_elem");
  auto se = concepts.findData<FieldConcept>("SE");
  ASSERT_TRUE(se);
  EXPECT_EQ(se->fieldType, "ELNO_SIEF_R");
  // The layout of reference §4.3: the header names the field concept, the cell and the point.
  const std::string resu = run->resu.str();
  EXPECT_NE(resu.find("---- CHAM_NO          NOM_CMP          NOEUD"), std::string::npos) << resu;
  EXPECT_NE(resu.find("---- CHAM_ELEM        NOM_CMP          MAILLE           POINT\n     SG"),
            std::string::npos)
      << resu;
  EXPECT_NE(resu.find(" OK  ANALYTIQUE       DEPL             0.001"), std::string::npos) << resu;
}

std::string errorOf(const std::string& name, const std::string& call) {
  auto run = runStudy(name, kPreamble + call + "\nFIN()\n", kCubeMesh);
  EXPECT_NE(run->failure(), FailureKind::None);
  return run->mess();
}

TEST(CreaChamp, RefusesWhatItCannotDo) {
  std::string m =
      errorOf("crea_affe", "C = CREA_CHAMP(OPERATION='AFFE', TYPE_CHAM='NOEU_DEPL_R', MAILLAGE=M, "
                           "AFFE=_F(TOUT='OUI', NOM_CMP='DX', VALE=0.0))");
  EXPECT_NE(m.find("CATALOG_17"), std::string::npos) << m;
  EXPECT_NE(m.find("OPERATION='AFFE' in CREA_CHAMP is not implemented yet"), std::string::npos) << m;
  m = errorOf("crea_asse",
              "C = CREA_CHAMP(OPERATION='ASSE', TYPE_CHAM='NOEU_DEPL_R', MAILLAGE=M, "
              "ASSE=_F(TOUT='OUI', CHAM_GD=CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', "
              "RESULTAT=R, NOM_CHAM='DEPL')))");
  EXPECT_NE(m.find("OPERATION='ASSE' in CREA_CHAMP is not implemented yet"), std::string::npos) << m;
  m = errorOf("crea_type",
              "C = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_SIEF_R', RESULTAT=R, NOM_CHAM='SIEF_ELGA')");
  EXPECT_NE(m.find("CREA_2"), std::string::npos) << m;
  EXPECT_NE(m.find("ELGA_SIEF_R"), std::string::npos) << m;
  m = errorOf(
      "crea_inst",
      "C = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=R, NOM_CHAM='DEPL', INST=1.5)");
  EXPECT_NE(m.find("RESU_1"), std::string::npos) << m;
  m = errorOf("crea_maxi",
              "C = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=R, NOM_CHAM='DEPL', "
              "TYPE_MAXI='MAXI')");
  EXPECT_NE(m.find("keyword TYPE_MAXI of CREA_CHAMP is not implemented yet"), std::string::npos) << m;
  // A cham_elem under CHAM_NO is a catalogue type error.
  m = errorOf("crea_kind", "SG = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELGA_SIEF_R', RESULTAT=R, "
                           "NOM_CHAM='SIEF_ELGA')\nTEST_RESU(CHAM_NO=_F(CHAM_GD=SG, NOM_CMP='SIXX', "
                           "TYPE_TEST='MAX', VALE_CALC=200.0))");
  EXPECT_NE(m.find("CATALOG_7"), std::string::npos) << m;
}

} // namespace
} // namespace stella
