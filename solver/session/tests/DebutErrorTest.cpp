// DEBUT(ERREUR=_F(ERREUR_F='EXCEPTION')) asks code_aster to turn errors of commands into
// exceptions a try/except catches; stella stops the study on them (doc/language.md), so the
// setting gets an alarm naming it, and the default ABORT none.

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

TEST(DebutErrors, ExceptionModeIsAnnouncedAsNotImplemented) {
  auto exception = runStudy("debut_exception", "DEBUT(ERREUR=_F(ERREUR_F='EXCEPTION'))\nFIN()\n",
                            "solver/session/tests/data/two_quads.msh");
  EXPECT_EQ(exception->failure(), FailureKind::None) << exception->mess();
  EXPECT_EQ(exception->session->counts().alarms, 1) << exception->mess();
  EXPECT_NE(exception->mess().find("DEBUT_1"), std::string::npos) << exception->mess();
  EXPECT_NE(exception->mess().find("debut_exception.comm:1"), std::string::npos) << exception->mess();

  auto abort = runStudy("debut_abort", "DEBUT(ERREUR=_F(ERREUR_F='ABORT'))\nFIN()\n",
                        "solver/session/tests/data/two_quads.msh");
  EXPECT_EQ(abort->session->counts().alarms, 0) << abort->mess();
}

} // namespace
} // namespace stella
