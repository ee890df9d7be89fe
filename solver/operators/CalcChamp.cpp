// CALC_CHAMP: fields derived from the stored fields of a result, on the steps chosen by
// TOUT_ORDRE (the default), NUME_ORDRE, INST or LIST_INST (CRITERE, PRECISION) and the cells of
// GROUP_MA (default: every volume cell). Implemented options:
//   CONTRAINTE   SIEF_ELNO, SIGM_ELNO (SIEF_ELGA extrapolated to the cell nodes), SIEF_NOEU,
//                SIGM_NOEU (ELNO averaged at the nodes), SIGM_ELGA (= SIEF_ELGA for solids)
//   DEFORMATION  EPSI_ELGA (from DEPL), EPSI_ELNO, EPSI_NOEU
//   CRITERES     SIEQ_ELGA (from SIEF_ELGA), SIEQ_ELNO (from SIGM_ELNO), SIEQ_NOEU (SIEQ_ELNO averaged)
//   VARI_INTERNE VARI_ELNO, VARI_NOEU (from VARI_ELGA)
//   FORCE        FORC_NODA (B^T sigma of SIEF_ELGA, plus k u of the DIS_T / 2D_DIS_T springs of
//                the CARA_ELEM the result was computed with, or of CALC_CHAMP's CARA_ELEM),
//                REAC_NODA (FORC_NODA minus the external forces of the loads the result was
//                computed with)
// Only the asked fields are stored; intermediate ones (SIGM_ELNO for SIEQ_NOEU...) are computed
// in memory when needed and said so in the message file. Other options are refused by name as
// not implemented yet. The methods are described in solver/post/DerivedFields.hpp.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/assembly/ExternalForces.hpp"
#include "solver/assembly/NodalForces.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/ElementCharacteristics.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/Model.hpp"
#include "solver/nonlinear/ResultFields.hpp"
#include "solver/nonlinear/ResultLoads.hpp"
#include "solver/post/DerivedFields.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

namespace stella {

namespace {

// Option keyword -> the options of it that are implemented.
const std::map<std::string, std::vector<std::string>>& implementedOptions() {
  static const std::map<std::string, std::vector<std::string>> options{
      {"CONTRAINTE", {"SIEF_ELNO", "SIGM_ELNO", "SIEF_NOEU", "SIGM_NOEU", "SIGM_ELGA", "SIEF_ELGA"}},
      {"DEFORMATION", {"EPSI_ELGA", "EPSI_ELNO", "EPSI_NOEU"}},
      {"CRITERES", {"SIEQ_ELGA", "SIEQ_ELNO", "SIEQ_NOEU"}},
      {"VARI_INTERNE", {"VARI_ELNO", "VARI_NOEU"}},
      {"FORCE", {"FORC_NODA", "REAC_NODA"}}};
  return options;
}

std::string implementedList() {
  std::vector<std::string> parts;
  for (const auto& [keyword, names] : implementedOptions()) {
    parts.push_back(fmt::format("{}=({})", keyword, fmt::join(names, ", ")));
  }
  return fmt::format("implemented: {}", fmt::join(parts, "; "));
}

// The requested options in keyword order; refuses the keywords and options not implemented.
std::vector<std::string> requestedOptions(const KeywordTree& kw) {
  for (const char* k : {"ENERGIE", "PROPRIETES", "HYDRAULIQUE", "CHAM_UTIL", "SOUS_POINT", "EXCIT",
                        "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "FREQ", "LIST_FREQ", "LIST_ORDRE"}) {
    if (kw.has(k)) {
      throw UserError(msg::make("CALC_2", {{"k", k}}, kw.locationOf(k)).withNote(implementedList()));
    }
  }
  std::vector<std::string> out;
  for (const char* keyword : {"CONTRAINTE", "DEFORMATION", "CRITERES", "VARI_INTERNE", "FORCE"}) {
    if (!kw.has(keyword)) {
      continue;
    }
    const auto& known = implementedOptions().at(keyword);
    for (const auto& option : kw.texts(keyword)) {
      if (std::find(known.begin(), known.end(), option) == known.end()) {
        throw UserError(
            msg::make("CALC_2.2", {{"keyword", keyword}, {"option", option}}, kw.locationOf(keyword))
                .withNote(implementedList()));
      }
      if (std::find(out.begin(), out.end(), option) == out.end()) {
        out.push_back(option);
      }
    }
  }
  if (out.empty()) {
    throw UserError(msg::make("CALC_2.3", {}, kw.location()).withNote(implementedList()));
  }
  return out;
}

std::string stepList(const Result& r) {
  std::vector<std::string> items;
  for (const auto& s : r.steps) {
    items.push_back(fmt::format("{} (INST {})", s.number, s.time));
  }
  return listNames(items);
}

std::vector<ResultStep*> selectedSteps(Result& result, const std::string& name, const KeywordTree& kw) {
  std::vector<ResultStep*> out;
  if (kw.has("NUME_ORDRE")) {
    for (auto n : kw.integers("NUME_ORDRE")) {
      ResultStep* s = result.stepNumber(static_cast<int>(n));
      if (s == nullptr) {
        throw UserError(msg::make("CALC_1", {{"name", name}, {"n", n}, {"step_list", stepList(result)}},
                                  kw.locationOf("NUME_ORDRE")));
      }
      out.push_back(s);
    }
    return out;
  }
  if (kw.has("INST") || kw.has("LIST_INST")) {
    const bool absolute = kw.text("CRITERE") == "ABSOLU";
    const double precision = kw.real("PRECISION");
    std::vector<double> times;
    if (kw.has("INST")) {
      times = kw.reals("INST");
    } else {
      auto list = conceptData<RealList>(kw.conceptValue("LIST_INST"));
      STELLA_ASSERT(list != nullptr, "LIST_INST holds no list of reals");
      times = list->values;
    }
    const char* keyword = kw.has("INST") ? "INST" : "LIST_INST";
    for (double t : times) {
      const ResultStep* s = result.stepAtTime(t, precision, absolute);
      if (s == nullptr) {
        throw UserError(msg::make("CALC_1.2", {{"name", name}, {"t", t}, {"step_list", stepList(result)}},
                                  kw.locationOf(keyword)));
      }
      out.push_back(result.stepNumber(s->number));
    }
    return out;
  }
  for (ResultStep& s : result.steps) {
    out.push_back(&s);
  }
  return out;
}

// ELGA field restricted to the selected cells (the others get no point).
Field restrictToCells(const Field& elga, const std::vector<bool>& cells) {
  std::vector<int> perCell(elga.cellCount(), 0);
  for (std::size_t c = 0; c < perCell.size(); ++c) {
    perCell[c] = c < cells.size() && cells[c] ? elga.pointCount(c) : 0;
  }
  Field out = Field::perPoint(FieldSupport::GaussPoint, elga.quantity(), elga.components(), perCell);
  for (std::size_t c = 0; c < perCell.size(); ++c) {
    for (int q = 0; q < perCell[c]; ++q) {
      const auto from = elga.entity(elga.firstPoint(c) + static_cast<std::size_t>(q));
      auto to = out.entity(out.firstPoint(c) + static_cast<std::size_t>(q));
      std::copy(from.begin(), from.end(), to.begin());
    }
  }
  return out;
}

// The fields of one step: stored sources (DEPL, SIEF_ELGA, VARI_ELGA) and the derived ones,
// computed on demand once.
class StepFields {
public:
  StepFields(const Model& model, const MaterialField* materials, const std::vector<bool>& cells,
             const ResultStep& step, const std::string& resultName, const KeywordTree& kw)
      : model_(model), materials_(materials), cells_(cells), step_(step), resultName_(resultName), kw_(kw) {}

  // Every field computed so far (asked or intermediate).
  const std::map<std::string, std::shared_ptr<Field>>& computed() const { return cache_; }

  std::shared_ptr<Field> get(const std::string& name, const std::string& forOption) {
    if (auto it = cache_.find(name); it != cache_.end()) {
      return it->second;
    }
    auto f = std::make_shared<Field>(compute(name, forOption));
    cache_[name] = f;
    return f;
  }

private:
  const Field& source(const std::string& name, const std::string& forOption) {
    const Field* f = step_.field(name);
    if (f == nullptr) {
      throw UserError(msg::make("CALC_4",
                                {{"result_name", resultName_},
                                 {"name", name},
                                 {"number", step_.number},
                                 {"for_option", forOption}},
                                kw_.location())
                          .withNote(name == "VARI_ELGA" ? msg::text("CALC_4.n1") : msg::text("CALC_4.n2")));
    }
    return *f;
  }

  Field compute(const std::string& name, const std::string& forOption) {
    const Mesh& mesh = *model_.mesh;
    if (name == "SIEF_ELGA" || name == "SIGM_ELGA") {
      return restrictToCells(source("SIEF_ELGA", forOption), cells_);
    }
    if (name == "SIEF_ELNO" || name == "SIGM_ELNO") { // the same values for solids: extrapolate once
      const auto twin = cache_.find(name == "SIEF_ELNO" ? "SIGM_ELNO" : "SIEF_ELNO");
      return twin != cache_.end() ? *twin->second
                                  : extrapolateToCellNodes(model_, source("SIEF_ELGA", forOption), cells_);
    }
    if (name == "EPSI_ELGA") {
      return strainAtGaussPoints(model_, source("DEPL", forOption), materials_, cells_);
    }
    if (name == "EPSI_ELNO") {
      return extrapolateToCellNodes(model_, *get("EPSI_ELGA", forOption), cells_);
    }
    if (name == "VARI_ELNO") {
      return extrapolateToCellNodes(model_, source("VARI_ELGA", forOption), cells_);
    }
    if (name == "SIEQ_ELGA") {
      return equivalentStressField(*get("SIEF_ELGA", forOption));
    }
    if (name == "SIEQ_ELNO") {
      return equivalentStressField(*get("SIGM_ELNO", forOption));
    }
    if (name.ends_with("_NOEU")) {
      return averageAtNodes(mesh, *get(name.substr(0, name.size() - 5) + "_ELNO", forOption));
    }
    STELLA_ASSERT(false, "no derivation rule for a CALC_CHAMP option");
    return Field();
  }

  const Model& model_;
  const MaterialField* materials_;
  const std::vector<bool>& cells_;
  const ResultStep& step_;
  const std::string& resultName_;
  const KeywordTree& kw_;
  std::map<std::string, std::shared_ptr<Field>> cache_;
};

struct ForceContext {
  const Model& model;
  const DofMap dofs;
  const std::vector<Excitation>* loads;
  const MaterialField* materials;
  const ElementCharacteristics* cara;             // springs, or null
  const std::vector<fem::StrainMeasure>* strains; // GROT_GDEP cells (null: PETIT everywhere)
  std::vector<Eigen::VectorXd> cache;
};

// Adds the internal forces of the discrete springs, k_c u_c at the spring's node, to `forces`.
void addSpringForces(const ForceContext& ctx, const ResultStep& step, const std::string& name,
                     const KeywordTree& kw, Eigen::VectorXd& forces) {
  if (ctx.cara == nullptr || ctx.cara->springs.empty()) {
    return;
  }
  const Field* depl = step.field("DEPL");
  if (depl == nullptr || depl->support() != FieldSupport::Node) {
    throw UserError(msg::make("CALC_4.2", {{"name", name}, {"number", step.number}}, kw.locationOf("FORCE")));
  }
  for (const DiscreteSpring& spring : ctx.cara->springs) {
    for (int c = 0; c < ctx.dofs.components(); ++c) {
      const int eq = ctx.dofs.dof(spring.node, c);
      const auto cmp = depl->componentIndex(Model::componentName(c));
      if (eq >= 0 && cmp) {
        forces(eq) += spring.stiffness[static_cast<std::size_t>(c)] *
                      depl->value(static_cast<std::size_t>(spring.node), *cmp);
      }
    }
  }
}

void computeForces(ForceContext& ctx, ResultStep& step, const std::vector<std::string>& options,
                   const std::string& name, const KeywordTree& kw) {
  const Field* sief = step.field("SIEF_ELGA");
  if (sief == nullptr) {
    throw UserError(msg::make("CALC_4.3", {{"name", name}, {"number", step.number}}, kw.locationOf("FORCE")));
  }
  const Field* depl = step.field("DEPL");
  if (ctx.strains != nullptr && (depl == nullptr || depl->support() != FieldSupport::Node)) {
    throw UserError(msg::make("CALC_4.4", {{"name", name}, {"number", step.number}}, kw.locationOf("FORCE")));
  }
  Eigen::VectorXd forc = forcesFromStress(ctx.model, ctx.dofs, *sief, ctx.strains, depl);
  addSpringForces(ctx, step, name, kw, forc);
  for (const auto& option : options) {
    if (option == "FORC_NODA") {
      step.fields["FORC_NODA"] = nodalField(ctx.model, ctx.dofs, forc, "DEPL_R");
    } else if (option == "REAC_NODA") {
      if (ctx.loads == nullptr) {
        throw UserError(msg::make("CALC_5", {{"name", name}}, kw.locationOf("FORCE")));
      }
      const Eigen::VectorXd fext = externalForces(*ctx.loads, step.time, ctx.dofs, ctx.materials, ctx.cache);
      step.fields["REAC_NODA"] = nodalField(ctx.model, ctx.dofs, forc - fext, "DEPL_R");
    }
  }
}

// CALC_CHAMP's CARA_ELEM, else the one the result was computed with (null: none).
std::shared_ptr<const ElementCharacteristics> characteristics(const KeywordTree& kw, const Result& source,
                                                              const Model& model) {
  if (!kw.has("CARA_ELEM")) {
    return rememberedCharacteristics(source);
  }
  auto cara = conceptData<ElementCharacteristics>(kw.conceptValue("CARA_ELEM"));
  STELLA_ASSERT(cara != nullptr, "CARA_ELEM holds no element characteristics");
  if (cara->model.get() != &model) {
    throw UserError(msg::make("CARA_6.2", {}, kw.locationOf("CARA_ELEM")));
  }
  return cara;
}

Value runCalcChamp(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const std::vector<std::string> options = requestedOptions(kw);
  auto concept_ = kw.conceptValue("RESULTAT");
  auto source = conceptData<Result>(concept_);
  STELLA_ASSERT(source != nullptr, "RESULTAT holds no result");
  auto model = std::dynamic_pointer_cast<Model>(source->model);
  if (!model) {
    throw UserError(msg::make("CALC_3", {{"name", concept_->name}}, kw.locationOf("RESULTAT")));
  }
  auto materials = std::dynamic_pointer_cast<MaterialField>(source->material);
  std::vector<CellId> group;
  if (kw.has("GROUP_MA")) {
    group = selectCells(*model->mesh, kw);
    if (std::find(options.begin(), options.end(), "FORC_NODA") != options.end() ||
        std::find(options.begin(), options.end(), "REAC_NODA") != options.end()) {
      throw UserError(msg::make("CALC_2.4", {}, kw.locationOf("GROUP_MA")));
    }
  }
  const std::vector<bool> cells = selectedVolumeCells(*model, group);
  // Without reuse=, the new result shares the fields of the source and gets the new ones.
  std::shared_ptr<Result> result = call.reused ? source : std::make_shared<Result>(*source);
  const auto steps = selectedSteps(*result, concept_->name, kw);

  std::vector<std::string> fieldOptions;
  std::vector<std::string> forceOptions;
  for (const auto& o : options) {
    (o == "FORC_NODA" || o == "REAC_NODA" ? forceOptions : fieldOptions).push_back(o);
  }
  std::unique_ptr<ForceContext> forces;
  const auto* loads = rememberedLoads(*source);
  auto cara = characteristics(kw, *source, *model);
  const std::vector<fem::StrainMeasure>* strains = rememberedStrainMeasures(*source);
  if (!forceOptions.empty()) {
    forces = std::make_unique<ForceContext>(
        ForceContext{*model, DofMap(*model), loads, materials.get(), cara.get(), strains, {}});
  }
  std::set<std::string> intermediates;
  for (ResultStep* step : steps) {
    StepFields fields(*model, materials.get(), cells, *step, concept_->name, kw);
    for (const auto& option : fieldOptions) {
      step->fields[option] = fields.get(option, option);
    }
    for (const auto& [name, field] : fields.computed()) {
      if (std::find(fieldOptions.begin(), fieldOptions.end(), name) == fieldOptions.end()) {
        intermediates.insert(name);
      }
    }
    if (forces) {
      computeForces(*forces, *step, forceOptions, concept_->name, kw);
    }
  }
  if (loads != nullptr && !call.reused) {
    rememberLoads(result, *loads);
  }
  if (!call.reused) {
    rememberCharacteristics(result, rememberedCharacteristics(*source));
    if (strains != nullptr) {
      rememberStrainMeasures(result, *strains);
    }
  }
  call.session.message() << fmt::format("  CALC_CHAMP: {} stored on {} step(s) of {}",
                                        fmt::join(options, ", "), steps.size(), concept_->name);
  if (!intermediates.empty()) {
    call.session.message() << fmt::format(" (computed on the way, not stored: {})",
                                          fmt::join(intermediates, ", "));
  }
  call.session.message() << "\n";
  return call.makeConcept(result);
}

} // namespace

STELLA_OPERATOR("CALC_CHAMP", runCalcChamp);

} // namespace stella
