// Tests of the built-in catalogue's DEFI_CONTACT: defaults of the discrete formulation, keywords
// with different defaults in exclusive blocks, zone variants, invalid calls named by id, and the
// settings the contact notice recommends.
#include "catalog/tests/CatalogRun.hpp"

namespace stella {
namespace {

using catalog_test::run;
using catalog_test::valid;
using catalog_test::zone;

TEST(DefiContact, DefaultsOfTheDiscreteFormulation) {
  auto r = run("CONT = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_MAIT='Top_B', GROUP_MA_ESCL='Bottom_C'))\n");
  ASSERT_TRUE(valid(*r));
  const ValidatedCall& v = r->last();
  EXPECT_EQ(v.resultType, "char_contact");
  EXPECT_EQ(v.keywords.text("FORMULATION"), "DISCRETE");
  EXPECT_EQ(v.keywords.text("REAC_GEOM"), "AUTOMATIQUE");
  EXPECT_DOUBLE_EQ(v.keywords.real("RESI_GEOM"), 0.01);
  EXPECT_EQ(v.keywords.integer("ITER_GEOM_MAXI"), 10);
  EXPECT_EQ(v.keywords.text("PRE_COND"), "SANS");
  EXPECT_FALSE(v.keywords.has("ALGO_RESO_CONT"));
  EXPECT_EQ(zone(v).text("ALGO_CONT"), "CONTRAINTE");
  EXPECT_EQ(zone(v).text("APPARIEMENT"), "MAIT_ESCL");
  EXPECT_DOUBLE_EQ(zone(v).real("TOLE_PROJ_EXT"), 0.5);
  EXPECT_FALSE(zone(v).has("COEF_CONT"));
  EXPECT_FALSE(zone(v).has("COULOMB"));
}

TEST(DefiContact, SameKeywordDifferentDefaultsInExclusiveBlocks) {
  auto newton = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_GEOM='NEWTON', "
                    "ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B'))\n");
  ASSERT_TRUE(valid(*newton));
  EXPECT_DOUBLE_EQ(newton->last().keywords.real("RESI_GEOM"), 1e-6);
  EXPECT_FALSE(newton->last().keywords.has("REAC_GEOM"));
  auto fixed = run(
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B'))\n");
  ASSERT_TRUE(valid(*fixed));
  EXPECT_DOUBLE_EQ(fixed->last().keywords.real("RESI_GEOM"), 0.01);
  EXPECT_EQ(fixed->last().keywords.text("ALGO_RESO_CONT"), "NEWTON");
  EXPECT_DOUBLE_EQ(fixed->last().keywords.real("RESI_CONT"), -1.0);
  auto controle = run("C = DEFI_CONTACT(MODELE=MO, REAC_GEOM='CONTROLE', NB_ITER_GEOM=3, "
                      "ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B'))\n");
  ASSERT_TRUE(valid(*controle));
  EXPECT_FALSE(controle->last().keywords.has("RESI_GEOM"));
  EXPECT_EQ(controle->last().keywords.integer("NB_ITER_GEOM"), 3);
}

TEST(DefiContact, FiveZoneVariants) {
  // (e) CONTINUE without friction, STANDARD.
  auto e = run(
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B'))\n");
  ASSERT_TRUE(valid(*e));
  EXPECT_EQ(zone(e->last()).text("ALGO_CONT"), "STANDARD");
  EXPECT_DOUBLE_EQ(zone(e->last()).real("COEF_CONT"), 100.0);
  EXPECT_EQ(zone(e->last()).text("ADAPTATION"), "CYCLAGE");
  EXPECT_EQ(zone(e->last()).text("INTEGRATION"), "AUTO");
  EXPECT_EQ(zone(e->last()).text("CONTACT_INIT"), "INTERPENETRE");
  EXPECT_FALSE(zone(e->last()).has("COULOMB"));
  // (e) LAC: mortar pairing, both groups mandatory.
  auto lac = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', "
                 "GROUP_MA_ESCL='B', ALGO_CONT='LAC'))\n");
  ASSERT_TRUE(valid(*lac));
  EXPECT_EQ(zone(lac->last()).text("APPARIEMENT"), "MORTAR");
  EXPECT_EQ(zone(lac->last()).text("TYPE_JACOBIEN"), "INITIAL");
  EXPECT_DOUBLE_EQ(zone(lac->last()).real("RESI_APPA"), 1e-8);
  EXPECT_FALSE(zone(lac->last()).has("COEF_CONT"));
  // (d) CONTINUE + COULOMB: COULOMB mandatory, friction defaults.
  auto d = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', "
               "ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', COULOMB=0.3))\n");
  ASSERT_TRUE(valid(*d));
  EXPECT_EQ(d->last().keywords.text("ALGO_RESO_FROT"), "NEWTON");
  EXPECT_DOUBLE_EQ(d->last().keywords.real("RESI_FROT"), 1e-4);
  EXPECT_EQ(zone(d->last()).text("ALGO_FROT"), "STANDARD");
  EXPECT_DOUBLE_EQ(zone(d->last()).real("COEF_FROT"), 100.0);
  EXPECT_EQ(zone(d->last()).text("GRAND_GLIS"), "NON");
  // (c) DISCRETE + COULOMB: E_T mandatory (penalised friction).
  auto c = run("C = DEFI_CONTACT(MODELE=MO, FROTTEMENT='COULOMB', ZONE=_F(GROUP_MA_MAIT='A', "
               "GROUP_MA_ESCL='B', COULOMB=0.2, E_T=1.e5))\n");
  ASSERT_TRUE(valid(*c));
  EXPECT_EQ(zone(c->last()).text("ALGO_FROT"), "PENALISATION");
  EXPECT_DOUBLE_EQ(zone(c->last()).real("COEF_MATR_FROT"), 0.0);
  // (a) LIAISON_UNIL.
  auto a = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='LIAISON_UNIL', ZONE=_F(GROUP_NO='N', NOM_CMP='DX', "
               "COEF_IMPO=RAMPE, COEF_MULT=RAMPE))\n");
  ASSERT_TRUE(valid(*a));
  EXPECT_EQ(zone(a->last()).text("ALGO_CONT"), "CONTRAINTE");
  EXPECT_FALSE(a->last().keywords.has("LISSAGE"));
}

TEST(DefiContact, InvalidCallsNameTheProblem) {
  // COEF_CONT does not exist in discrete contact (its penalty is E_N).
  auto r =
      run("C = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', COEF_CONT=100.))\n");
  EXPECT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_1"}) << r->sink.text();
  EXPECT_NE(r->sink.text().find("COEF_CONT belongs to the variant of this factor keyword used when "
                                "equal_to('FORMULATION', 'CONTINUE') and equal_to('FROTTEMENT', 'COULOMB')"),
            std::string::npos)
      << r->sink.text();
  // E_N exists in the discrete ZONE, but only with ALGO_CONT='PENALISATION'.
  r = run("C = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', E_N=100.))\n");
  EXPECT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_14"}) << r->sink.text();
  // Misspelt keyword: suggestion and allowed keywords.
  r = run("C = DEFI_CONTACT(MODELE=MO, ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESC='B'))\n");
  ASSERT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_1"}) << r->sink.text();
  EXPECT_NE(r->sink.text().find("did you mean 'GROUP_MA_ESCL'?"), std::string::npos) << r->sink.text();
  // Penalisation needs E_N; LAC needs both groups; friction needs COULOMB: all at once.
  r = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', "
          "ZONE=(_F(GROUP_MA_ESCL='B', ALGO_CONT='LAC'),))\n");
  EXPECT_EQ(r->sink.ids(), (std::vector<std::string>{"CATALOG_5", "CATALOG_5"})) << r->sink.text();
  // Value not allowed, and XFEM refused as outside the scope.
  r = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINU', ZONE=_F(GROUP_MA_MAIT='A'))\n");
  EXPECT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_3"}) << r->sink.text();
  r = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='XFEM', ZONE=_F(GROUP_MA_MAIT='A'))\n");
  EXPECT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_SCOPE"}) << r->sink.text();
  // Wrong concept type.
  r = run("C = DEFI_CONTACT(MODELE=MAIL, ZONE=_F(GROUP_MA_MAIT='A'))\n");
  ASSERT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_7"}) << r->sink.text();
  EXPECT_NE(r->sink.text().find("MODELE expects modele; MAIL is a maillage"), std::string::npos)
      << r->sink.text();
  // Real expected.
  r = run("C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
          "COEF_CONT='OUI'))\n");
  ASSERT_EQ(r->sink.ids(), std::vector<std::string>{"CATALOG_2"}) << r->sink.text();
  EXPECT_NE(r->sink.text().find("COEF_CONT expects a real, got 'OUI'"), std::string::npos);
}

// Settings the contact notice recommends, each written as a user would.
TEST(DefiContact, NoticeRecommendationsValidate) {
  const char* calls[] = {
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='Top_B', "
      "GROUP_MA_ESCL='Bottom_C', ALGO_CONT='LAC'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='LAC', TYPE_JACOBIEN='ACTUALISE'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='PENALISATION', ADAPTATION='ADAPT_COEF', PENE_MAXI=1.e-3))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='PENALISATION', ADAPTATION='TOUT'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='PENALISATION', COEF_PENA_CONT=1.e6))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', REAC_GEOM='CONTROLE', "
      "NB_ITER_GEOM=2, ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', ALGO_CONT='STANDARD', "
      "ALGO_FROT='PENALISATION', COEF_PENA_FROT=1.e4, COULOMB=0.1))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', "
      "ALGO_RESO_FROT='POINT_FIXE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', COULOMB=0.3, "
      "ADAPTATION='TOUT'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', FROTTEMENT='COULOMB', ZONE=_F(GROUP_MA_MAIT='A', "
      "GROUP_MA_ESCL='B', COULOMB=0.3, SANS_GROUP_NO_FR='ARETE', DIRE_EXCL_FROT=(1, 0, 0)))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_CONT='POINT_FIXE', "
      "ALGO_RESO_GEOM='NEWTON', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', CONTACT_INIT='NON'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "CONTACT_INIT='OUI', INTEGRATION='NCOTES', ORDRE_INT=6))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ADAPTATION='NON'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', RECH_LINEAIRE='NON_ADMISSIBLE', "
      "PRE_COND='DIRICHLET', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', ALGO_CONT='GCP'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='PENALISATION', E_N=1.e10))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=(_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "RESOLUTION='NON'), _F(GROUP_MA_MAIT='C', GROUP_MA_ESCL='D', APPARIEMENT='NODAL')))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ALGO_CONT='LAC', APPARIEMENT='MORTAR'))",
      "C = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B', "
      "ADAPTATION='TOUT'))",
  };
  for (const char* call : calls) {
    auto r = run(std::string(call) + "\n");
    EXPECT_TRUE(valid(*r)) << call;
  }
}

} // namespace
} // namespace stella
