// Alarms of contact count in the job diagnostic: a zone with RESOLUTION='NON' whose blocks
// interpenetrate raises CONTACT_8 through the session's diagnostic sink (framed in the message
// file, <A>_ALARM), while the same study that stays open ends OK. Without a sink (the constraint
// alone) the alarm stays a line of the step report.

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

// Plane-strain blocks 0.002 apart, block B pushed down by `push` x t rigidly (contact only
// measured): JEU = 0.002 - push t exactly, negative (interpenetration) when push > 0.002.
std::string measuredComm(double push) {
  return fmt::format(
      "DEBUT()\n"
      "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
      "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
      "MAT = DEFI_MATERIAU(ELAS=_F(E=1000.0, NU=0.3))\n"
      "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
      "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA=('A_XMIN', 'B_XMIN'), DX=0.0), "
      "_F(GROUP_MA='A_YMIN', DY=0.0)))\n"
      "PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='B_YMAX', DY=-{push}))\n"
      "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
      "L = DEFI_LIST_REEL(VALE=(0.0, 0.2, 1.0))\n"
      "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE',\n"
      "                    ZONE=_F(GROUP_MA_MAIT='A_YMAX', GROUP_MA_ESCL='B_YMIN', RESOLUTION='NON'))\n"
      "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PUSH, "
      "FONC_MULT=F)), INCREMENT=_F(LIST_INST=L), CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-9))\n"
      "TEST_RESU(RESU=_F(RESULTAT=RESU, INST=1.0, NOM_CHAM='CONT_NOEU', NOM_CMP='JEU', GROUP_NO='B_YMIN', "
      "TYPE_TEST='MIN', VALE_CALC={jeu:.17g}, TOLE_MACHINE=1.0e-6, CRITERE='ABSOLU', "
      "REFERENCE='ANALYTIQUE', VALE_REFE={jeu:.17g}, PRECISION=1.0e-10))\n"
      "FIN()\n",
      fmt::arg("push", push), fmt::arg("jeu", 0.002 - push));
}

struct StudyResult {
  JobDiagnostic diagnostic = JobDiagnostic::AbnormalAbort;
  std::string message;
};

StudyResult runMeasured(const std::string& name, double push) {
  const fs::path dir = fs::path(::testing::TempDir()) / "stella_contact_alarm" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeAsterMesh(dir / "mesh.mail", testing::twoBlocks(CellType::QUAD4, 3, 3, 0.002));
  const fs::path file = dir / (name + ".comm");
  std::ofstream(file) << measuredComm(push);
  RunOptions options;
  options.echo = false;
  options.workDirectory = dir / "work";
  const JobResult r = runCommandFile(file, {{20, dir / "mesh.mail"}}, options);
  std::ifstream in(dir / (name + ".mess"));
  std::stringstream s;
  s << in.rdbuf();
  return {r.diagnostic, s.str()};
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(ContactAlarm, InterpenetrationWithResolutionNonCountsInTheJobDiagnostic) {
  // push 0.008: JEU = 0.0004 at t = 0.2 (open, no alarm), -0.006 at t = 1 (one CONTACT_8).
  const StudyResult r = runMeasured("penetrating", 0.008);
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Alarm) << r.message;
  EXPECT_EQ(count(r.message, "<A> <CONTACT_8>"), 1) << r.message;
  EXPECT_NE(r.message.find("RESOLUTION='NON'"), std::string::npos);
}

TEST(ContactAlarm, OpenGapRaisesNoAlarm) {
  // push 0.001: the gap stays open (JEU = 0.001 at t = 1): the job is OK, no CONTACT_8.
  const StudyResult r = runMeasured("open", 0.001);
  EXPECT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_EQ(r.message.find("CONTACT_8"), std::string::npos);
}

} // namespace
} // namespace stella::contact
