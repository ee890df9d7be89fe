// Unit tests of the validation engine on specs built directly in C++ (no catalogue files):
// types, counts, into-lists, bounds, defaults in active blocks only, exclusive blocks with
// different defaults, rule defaults, 'd' factor keywords, reuse, concept types, messages.
#include "catalog/Validator.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

std::shared_ptr<SimpleSpec> simp(std::vector<std::string> types, Presence p = Presence::Optional) {
  auto s = std::make_shared<SimpleSpec>();
  s->types = std::move(types);
  s->presence = p;
  s->description = "test keyword";
  return s;
}

Entry entry(const std::string& name, std::shared_ptr<SimpleSpec> s) {
  return Entry{name, std::move(s), nullptr, nullptr};
}
Entry entry(const std::string& name, std::shared_ptr<FactorSpec> f) {
  return Entry{name, nullptr, std::move(f), nullptr};
}
Entry block(const std::string& name, const std::string& condition, Level body) {
  auto b = std::make_shared<BlockSpec>();
  b->conditionText = condition;
  b->condition = std::make_shared<const CompiledExpression>(CompiledExpression::compile(condition));
  b->body = std::move(body);
  return Entry{name, nullptr, nullptr, std::move(b)};
}

KeywordArgument kw(const std::string& name, Value v) {
  return KeywordArgument{name, std::make_shared<const Value>(std::move(v)), {}, {}};
}

Value factor(std::vector<KeywordArgument> keywords) {
  auto f = std::make_shared<FactorObject>();
  f->keywords = std::move(keywords);
  return Value(f);
}

CallArguments call(std::vector<KeywordArgument> keywords) {
  CallArguments a;
  a.keywords = std::move(keywords);
  return a;
}

std::shared_ptr<Concept> concept_(const std::string& name, const std::string& type) {
  auto c = std::make_shared<Concept>();
  c->name = name;
  c->type = type;
  return c;
}

std::vector<std::string> errorIds(const CommandSpec& spec, const ConceptTypes& types,
                                  const CallArguments& args, std::vector<std::string>* messages = nullptr) {
  try {
    validateCall(spec, types, args);
  } catch (const UserError& e) {
    std::vector<std::string> ids;
    for (const auto& d : e.diagnostics()) {
      ids.push_back(d.id);
      if (messages) {
        messages->push_back(d.message);
      }
    }
    return ids;
  }
  return {};
}

// A small DEFI_CONTACT-like command: FORMULATION drives exclusive blocks that define RESI_GEOM
// with different defaults, and a ZONE factor keyword.
struct Fixture : ::testing::Test {
  CommandSpec spec;
  ConceptTypes types;
  void SetUp() override {
    types.addParent("char_meca", "charge");
    types.addParent("evol_noli", "resultat");
    types.addKnown("maillage");
    spec.name = "CMD";
    spec.resultType = "char_contact";
    auto formulation = simp({"TXM"});
    formulation->defaultValue = ValueList{Value("DISCRETE")};
    formulation->into = {Value("DISCRETE"), Value("CONTINUE")};
    spec.body.entries.push_back(entry("FORMULATION", formulation));
    auto resiD = simp({"R"});
    resiD->defaultValue = ValueList{Value(0.01)};
    auto resiC = simp({"R"});
    resiC->defaultValue = ValueList{Value(1e-6)};
    Level discrete;
    discrete.entries.push_back(entry("RESI_GEOM", resiD));
    Level continuous;
    continuous.entries.push_back(entry("RESI_GEOM", resiC));
    auto en = simp({"R"}, Presence::Mandatory);
    continuous.entries.push_back(entry("COEF_CONT", en));
    spec.body.entries.push_back(block("b_disc", "FORMULATION == 'DISCRETE'", discrete));
    spec.body.entries.push_back(block("b_cont", "equal_to('FORMULATION', 'CONTINUE')", continuous));

    auto zone = std::make_shared<FactorSpec>();
    zone->presence = Presence::Mandatory;
    zone->max = kUnbounded;
    zone->description = "zones";
    auto tout = simp({"TXM"});
    tout->into = {Value("OUI")};
    auto gma = simp({"grma"});
    gma->max = kUnbounded;
    gma->noRepeat = true;
    zone->body.entries.push_back(entry("TOUT", tout));
    zone->body.entries.push_back(entry("GROUP_MA", gma));
    Rule r;
    r.kind = Rule::Kind::UnParmi;
    r.names = {"TOUT", "GROUP_MA"};
    r.defaults = {{"TOUT", Value("OUI")}};
    zone->body.rules.push_back(r);
    auto coef = simp({"R"});
    coef->valMin = 0.0;
    zone->body.entries.push_back(entry("COEF", coef));
    spec.body.entries.push_back(entry("ZONE", zone));

    auto conv = std::make_shared<FactorSpec>();
    conv->presence = Presence::Defaulted;
    conv->description = "convergence";
    conv->body.entries.push_back(entry("RESI_GLOB_RELA", simp({"R"})));
    conv->body.entries.push_back(entry("RESI_GLOB_MAXI", simp({"R"})));
    Rule au;
    au.kind = Rule::Kind::AuMoinsUn;
    au.names = {"RESI_GLOB_RELA", "RESI_GLOB_MAXI"};
    au.defaults = {{"RESI_GLOB_RELA", Value(1e-6)}};
    conv->body.rules.push_back(au);
    spec.body.entries.push_back(entry("CONVERGENCE", conv));

    auto charge = simp({"char_meca", "char_cine_meca"});
    spec.body.entries.push_back(entry("CHARGE", charge));
    auto n = simp({"I"});
    n->into = {Value(1), Value(2)};
    spec.body.entries.push_back(entry("INFO", n));
  }
};

TEST_F(Fixture, DefaultsComeFromTheActiveBlockOnly) {
  auto out = validateCall(spec, types, call({kw("ZONE", factor({}))}));
  EXPECT_EQ(out.keywords.text("FORMULATION"), "DISCRETE");
  EXPECT_DOUBLE_EQ(out.keywords.real("RESI_GEOM"), 0.01);
  EXPECT_FALSE(out.keywords.has("COEF_CONT"));
  EXPECT_EQ(out.resultType, "char_contact");

  auto cont = validateCall(
      spec, types, call({kw("FORMULATION", "CONTINUE"), kw("COEF_CONT", 100), kw("ZONE", factor({}))}));
  EXPECT_DOUBLE_EQ(cont.keywords.real("RESI_GEOM"), 1e-6);
  // An integer is accepted for a real and converted.
  EXPECT_TRUE(cont.keywords.value("COEF_CONT").isReal());
  EXPECT_DOUBLE_EQ(cont.keywords.real("COEF_CONT"), 100.0);
}

TEST_F(Fixture, RuleDefaultsAndDefaultedFactors) {
  auto out = validateCall(spec, types, call({kw("ZONE", factor({}))}));
  const auto& zone = out.keywords.occurrences("ZONE");
  ASSERT_EQ(zone.size(), 1u);
  EXPECT_EQ(zone[0].text("TOUT"), "OUI");
  ASSERT_TRUE(out.keywords.factor("CONVERGENCE"));
  EXPECT_TRUE(out.keywords.factor("CONVERGENCE")->defaulted);
  EXPECT_DOUBLE_EQ(out.keywords.occurrences("CONVERGENCE")[0].real("RESI_GLOB_RELA"), 1e-6);

  auto withMaxi = validateCall(
      spec, types, call({kw("ZONE", factor({})), kw("CONVERGENCE", factor({kw("RESI_GLOB_MAXI", 1e-3)}))}));
  EXPECT_FALSE(withMaxi.keywords.occurrences("CONVERGENCE")[0].has("RESI_GLOB_RELA"));
}

TEST_F(Fixture, ScalarsAndListsAreNormalised) {
  auto out = validateCall(
      spec, types,
      call({kw("ZONE", Value::tuple({factor({kw("GROUP_MA", "A")}),
                                     factor({kw("GROUP_MA", Value::tuple({Value("B"), Value("C")}))})}))}));
  const auto& zones = out.keywords.occurrences("ZONE");
  ASSERT_EQ(zones.size(), 2u);
  EXPECT_EQ(zones[0].texts("GROUP_MA"), std::vector<std::string>{"A"});
  EXPECT_EQ(zones[1].texts("GROUP_MA"), (std::vector<std::string>{"B", "C"}));
}

TEST_F(Fixture, DictAcceptedLikeF) {
  auto d = std::make_shared<DictObject>();
  d->items.emplace_back(Value("GROUP_MA"), Value("A"));
  auto out = validateCall(spec, types, call({kw("ZONE", Value(d))}));
  EXPECT_EQ(out.keywords.occurrences("ZONE")[0].text("GROUP_MA"), "A");
}

TEST_F(Fixture, AllErrorsReportedAtOnceWithIds) {
  std::vector<std::string> messages;
  auto ids = errorIds(spec, types,
                      call({kw("FORMULATION", "DISCRETTE"), kw("INFO", 3), kw("GROUP_MA_ESC", "x"),
                            kw("ZONE", factor({kw("TOUT", "OUI"), kw("GROUP_MA", "A"), kw("COEF", -1.0)})),
                            kw("CHARGE", Value(concept_("MAIL", "maillage")))}),
                      &messages);
  // FORMULATION not allowed; INFO not allowed; unknown keyword; rule broken; below minimum; wrong concept.
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "CATALOG_3"), 2);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "CATALOG_1"), 1);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "CATALOG_6"), 1);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "CATALOG_8"), 1);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), "CATALOG_7"), 1);
  bool conceptMessage = false;
  for (const auto& m : messages) {
    conceptMessage |= m == "CHARGE expects char_meca or char_cine_meca; MAIL is a maillage";
  }
  EXPECT_TRUE(conceptMessage);
}

TEST_F(Fixture, WrongTypeAndMissingMandatory) {
  std::vector<std::string> messages;
  auto ids = errorIds(
      spec, types, call({kw("FORMULATION", "CONTINUE"), kw("ZONE", factor({kw("COEF", "OUI")}))}), &messages);
  std::sort(ids.begin(), ids.end());
  ASSERT_EQ(ids, (std::vector<std::string>{"CATALOG_2", "CATALOG_5"}));
  EXPECT_NE(std::find(messages.begin(), messages.end(), "COEF expects a real, got 'OUI'"), messages.end());
  EXPECT_NE(std::find(messages.begin(), messages.end(), "missing mandatory keyword COEF_CONT in CMD"),
            messages.end());
}

TEST_F(Fixture, KeywordOfAnInactiveBlockIsNamedWithItsCondition) {
  std::vector<std::string> messages;
  auto ids = errorIds(spec, types, call({kw("COEF_CONT", 1.0), kw("ZONE", factor({}))}), &messages);
  ASSERT_EQ(ids, std::vector<std::string>{"CATALOG_14"});
  EXPECT_NE(messages[0].find("equal_to('FORMULATION', 'CONTINUE')"), std::string::npos);
}

TEST_F(Fixture, CountsOccurrencesAndRepeats) {
  EXPECT_EQ(errorIds(spec, types, call({})), std::vector<std::string>{"CATALOG_5"});
  EXPECT_EQ(errorIds(spec, types,
                     call({kw("ZONE", factor({kw("GROUP_MA", Value::tuple({Value("A"), Value("A")}))}))})),
            std::vector<std::string>{"CATALOG_10"});
  EXPECT_EQ(
      errorIds(spec, types, call({kw("ZONE", factor({})), kw("INFO", Value::tuple({Value(1), Value(2)}))})),
      std::vector<std::string>{"CATALOG_4"});
  EXPECT_EQ(errorIds(spec, types, call({kw("ZONE", 3)})), std::vector<std::string>{"CATALOG_2"});
}

TEST_F(Fixture, Reuse) {
  spec.reentrant = 'n';
  EXPECT_EQ(errorIds(spec, types,
                     call({kw("ZONE", factor({})), kw("reuse", Value(concept_("X", "char_contact")))})),
            std::vector<std::string>{"CATALOG_11"});
  spec.reentrant = 'o';
  EXPECT_EQ(errorIds(spec, types, call({kw("ZONE", factor({}))})), std::vector<std::string>{"CATALOG_11"});
  auto c = concept_("X", "char_contact");
  auto out = validateCall(spec, types, call({kw("ZONE", factor({})), kw("reuse", Value(c))}));
  EXPECT_EQ(out.reused, c);
}

TEST_F(Fixture, ConceptHierarchy) {
  types.addParent("char_cine_meca", "charge");
  auto out = validateCall(
      spec, types, call({kw("ZONE", factor({})), kw("CHARGE", Value(concept_("C", "char_cine_meca")))}));
  EXPECT_EQ(out.keywords.conceptValue("CHARGE")->name, "C");
  EXPECT_TRUE(types.isA("evol_noli", "resultat"));
  EXPECT_FALSE(types.isA("resultat", "evol_noli"));
}

TEST(Rules, Semantics) {
  Rule r;
  r.names = {"A", "B", "C"};
  r.kind = Rule::Kind::PresentAbsent;
  EXPECT_TRUE(r.holds({"B", "C"}));
  EXPECT_FALSE(r.holds({"A", "C"}));
  r.kind = Rule::Kind::PresentPresent;
  EXPECT_FALSE(r.holds({"A", "B"}));
  EXPECT_TRUE(r.holds({"A", "B", "C"}));
  r.kind = Rule::Kind::Ensemble;
  EXPECT_FALSE(r.holds({"A"}));
  EXPECT_TRUE(r.holds({}));
  r.kind = Rule::Kind::Exclus;
  EXPECT_TRUE(r.holds({"C"}));
  EXPECT_FALSE(r.holds({"A", "B"}));
  EXPECT_EQ(editDistance("GROUP_MA_ESC", "GROUP_MA_ESCL"), 1u);
}

} // namespace
} // namespace stella
