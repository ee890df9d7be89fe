// Support is declared once, in the catalogue (issue 15): a keyword marked non_implemente= and a
// value outside implemente= are refused by validation with CATALOG_17 "not implemented yet" at
// their own line and column, and every such mark of STAT_NON_LINE is reached by a user value.
#include "catalog/tests/CatalogRun.hpp"

namespace stella {
namespace {

using catalog_test::run;
using catalog_test::valid;

const char* kSnl = "R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MAT, EXCIT=_F(CHARGE=LOAD), "
                   "INCREMENT=_F(LIST_INST=TIMES),\n";

// The diagnostics of one STAT_NON_LINE whose second line is `line`.
std::vector<Diagnostic> refusals(const std::string& line) {
  auto r = run(std::string(kSnl) + "    " + line + "\n");
  std::vector<Diagnostic> out;
  for (const auto& d : r->sink.all) {
    if (d.severity == Severity::Fatal) {
      out.push_back(d);
    }
  }
  return out;
}

// The prelude has 8 lines and a leading newline: the snippet's second line is line 11.
constexpr int kSecondLine = 11;

TEST(CatalogSupport, RefusedKeywordAtItsOwnLocation) {
  auto ds = refusals("CONVERGENCE=_F(RESI_REFE_RELA=1e-3, SIGM_REFE=1.0))");
  ASSERT_FALSE(ds.empty());
  EXPECT_EQ(ds.front().id, "CATALOG_17");
  EXPECT_NE(ds.front().message.find("RESI_REFE_RELA"), std::string::npos) << ds.front().message;
  EXPECT_NE(ds.front().message.find("not implemented yet"), std::string::npos);
  EXPECT_EQ(ds.front().location.line, kSecondLine);
  EXPECT_EQ(ds.front().location.column, 20); // RESI_REFE_RELA, after 4 spaces and CONVERGENCE=_F(
  EXPECT_EQ(ds.front().kind, FailureKind::Error);
}

TEST(CatalogSupport, RefusedValueAtItsOwnLocation) {
  auto ds = refusals("COMPORTEMENT=_F(RELATION='VMIS_CINE_LINE', TOUT='OUI'))");
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds.front().id, "CATALOG_17");
  EXPECT_NE(ds.front().message.find("RELATION='VMIS_CINE_LINE'"), std::string::npos) << ds.front().message;
  EXPECT_EQ(ds.front().location.line, kSecondLine);
  EXPECT_EQ(ds.front().location.column, 30); // the value 'VMIS_CINE_LINE'
  bool listsImplemented = false;
  for (const auto& n : ds.front().notes) {
    listsImplemented = listsImplemented || n.find("'VMIS_ISOT_LINE'") != std::string::npos;
  }
  EXPECT_TRUE(listsImplemented);
}

TEST(CatalogSupport, AcceptedValueOfARefusedKeywordPasses) {
  EXPECT_TRUE(refusals("CONVERGENCE=_F(ARRET='OUI'))").empty());
  EXPECT_TRUE(refusals("COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI', ITER_INTE_PAS=0))").empty());
  auto ds = refusals("CONVERGENCE=_F(ARRET='NON'))");
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds.front().id, "CATALOG_17");
}

TEST(CatalogSupport, EveryRefusalOfTheIssueIsFound) {
  for (const char* line :
       {"METHODE='IMPLEX')", "PILOTAGE=_F(TYPE='DDL_IMPO', NOEUD='N1', NOM_CMP='DX'))", "ENERGIE=_F())",
        "SUIVI_DDL=_F(NOM_CHAM='DEPL', NOM_CMP='DX', TOUT='OUI', EVAL_CMP='FORMULE', FORMULE=RAMPE))",
        "SUIVI_DDL=_F(NOM_CHAM='FORC_NODA', NOM_CMP='DX', TOUT='OUI'))",
        "OBSERVATION=_F(NOM_CHAM='VITE', NOM_CMP='DX', TOUT='OUI'))",
        "COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', DEFORMATION='GROT_GDEP', TOUT='OUI'))",
        "COMPORTEMENT=_F(RELATION='ELAS', DEFORMATION='SIMO_MIEHE', TOUT='OUI'))",
        "RECH_LINEAIRE=_F(METHODE='MIXTE'))", "ETAT_INIT=_F(DEPL=MO))", "CRIT_STAB=_F())"}) {
    auto ds = refusals(line);
    bool found = std::any_of(ds.begin(), ds.end(), [](const Diagnostic& d) { return d.id == "CATALOG_17"; });
    EXPECT_TRUE(found) << line;
  }
}

TEST(CatalogSupport, ImplementedKeywordsPass) {
  EXPECT_TRUE(refusals("NEWTON=_F(REAC_INCR=1, MATRICE='ELASTIQUE'), ARCHIVAGE=_F(PAS_ARCH=2))").empty());
  EXPECT_TRUE(
      refusals("SUIVI_DDL=_F(NOM_CHAM='DEPL', NOM_CMP='DX', TOUT='OUI', EVAL_CHAM='MAX'), INFO=1)").empty());
  // GROT_GDEP is implemented with ELAS only (the relation's block of COMPORTEMENT)
  EXPECT_TRUE(refusals("COMPORTEMENT=_F(RELATION='ELAS', DEFORMATION='GROT_GDEP', TOUT='OUI'))").empty());
  EXPECT_TRUE(refusals("COMPORTEMENT=_F(DEFORMATION='GROT_GDEP', TOUT='OUI'))").empty());
}

TEST(CatalogSupport, GrotGdepWithAnotherRelationIsRefusedAtDeformation) {
  auto ds = refusals("COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', DEFORMATION='GROT_GDEP', TOUT='OUI'))");
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds.front().id, "CATALOG_17");
  EXPECT_NE(ds.front().message.find("DEFORMATION='GROT_GDEP'"), std::string::npos) << ds.front().message;
  EXPECT_EQ(ds.front().location.line, kSecondLine);
  EXPECT_EQ(ds.front().location.column, 60); // the value 'GROT_GDEP'
}

TEST(CatalogSupport, DefiListInstRefusalsAreCatalogueMarks) {
  for (const char* call :
       {"L = DEFI_LIST_INST(METHODE='AUTO', DEFI_LIST=_F(LIST_INST=L1))\n",
        "L = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L1), ECHEC=_F(ACTION='ITER_SUPPL'))\n",
        "L = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L1), ECHEC=_F(SUBD_METHODE='AUTO'))\n",
        "L = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L1), ECHEC=_F(EVENEMENT='DIVE_RESI'))\n"}) {
    auto r = run(call);
    EXPECT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_17"}) << call << r->sink.text();
  }
  EXPECT_TRUE(valid(*run("L = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L1), ECHEC=_F(ACTION='DECOUPE'))\n")));
}

// A command stella has no operator for is marked in its catalogue entry.
TEST(CatalogSupport, DynaNonLineIsMarkedNotImplemented) {
  const CommandSpec* spec = Catalog::builtin().find("DYNA_NON_LINE");
  ASSERT_NE(spec, nullptr);
  EXPECT_TRUE(spec->notImplemented.has_value());
  EXPECT_FALSE(Catalog::builtin().find("STAT_NON_LINE")->notImplemented.has_value());
}

// SOLVEUR METHODE='PETSC': what PETSc does not give stella yet is refused at the value (HPDDM,
// GMRES_LMP, a RENUM other than SANS for LDLT_SP), what it gives passes.
TEST(CatalogSupport, PetscPreconditionersNotImplementedAreRefused) {
  for (const char* refused : {"PRE_COND='HPDDM'", "PRE_COND='LDLT_DP'", "PRE_COND='FIELDSPLIT'",
                              "ALGORITHME='GMRES_LMP', PRE_COND='GAMG'", "ALGORITHME='CR', PRE_COND='JACOBI'",
                              "PRE_COND='LDLT_SP', RENUM='PARMETIS'", "PRE_COND='JACOBI', RENUM='RCMK'",
                              "PRE_COND='GAMG', MATR_DISTRIBUEE='OUI'"}) {
    auto ds = refusals(std::string("SOLVEUR=_F(METHODE='PETSC', ") + refused + "))");
    ASSERT_FALSE(ds.empty()) << refused;
    EXPECT_EQ(ds.front().id, "CATALOG_17") << refused;
    EXPECT_NE(ds.front().message.find("not implemented yet"), std::string::npos) << ds.front().message;
    EXPECT_EQ(ds.front().location.line, kSecondLine) << refused;
  }
  for (const char* accepted :
       {"PRE_COND='GAMG', ALGORITHME='CG'", "PRE_COND='BOOMER'", "PRE_COND='ML'",
        "PRE_COND='LDLT_SP', REAC_PRECOND=10", "PRE_COND='LDLT_INC', NIVE_REMPLISSAGE=1",
        "PRE_COND='SOR', ALGORITHME='GMRES'", "PRE_COND='JACOBI', NMAX_ITER=50"}) {
    EXPECT_TRUE(refusals(std::string("SOLVEUR=_F(METHODE='PETSC', ") + accepted + "))").empty()) << accepted;
  }
}

} // namespace
} // namespace stella
