// CellBehaviours: behaviour objects from materials and relations, with the user checks.

#include "solver/nonlinear/CellBehaviours.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/behaviour/LinearElastic.hpp"
#include "solver/behaviour/VonMisesIsotropicLinear.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella {

namespace {

std::unique_ptr<behaviour::Behaviour> makeBehaviour(const Material& m, const std::string& relation, CellId c,
                                                    const Mesh& mesh, const SourceLocation& at) {
  if (!m.elastic) {
    throw UserError(msg::make("MATER_7", {{"name", m.name}, {"cell_name", mesh.cellName(c)}}, at));
  }
  behaviour::ElasticParameters e{m.elastic->youngModulus, m.elastic->poissonRatio};
  if (relation == "ELAS") {
    return std::make_unique<behaviour::LinearElastic>(e);
  }
  if (relation == "VMIS_ISOT_LINE") {
    if (!m.hardening) {
      throw UserError(msg::make("MATER_8", {{"cell_name", mesh.cellName(c)}, {"name", m.name}}, at));
    }
    return std::make_unique<behaviour::VonMisesIsotropicLinear>(
        e, behaviour::LinearHardening{m.hardening->tangentModulus, m.hardening->yieldStress});
  }
  // The catalogue refuses the other relations (COMPORTEMENT RELATION implemente=).
  STELLA_ASSERT(false, fmt::format("RELATION='{}' passed the catalogue but has no behaviour", relation));
  return nullptr;
}

} // namespace

CellBehaviours::CellBehaviours(const Model& model, const MaterialField& materials,
                               const std::vector<std::string>& relations, const SourceLocation& at,
                               std::vector<fem::StrainMeasure> strains)
    : strains_(std::move(strains)) {
  const Mesh& mesh = *model.mesh;
  largeDisplacements_ =
      std::find(strains_.begin(), strains_.end(), fem::StrainMeasure::GreenLagrange) != strains_.end();
  cells_.assign(static_cast<std::size_t>(mesh.cellCount()), nullptr);
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    if (model.cell(c).kind != ElementKind::Volume) {
      continue;
    }
    const Material* m = materials.material(c);
    if (m == nullptr) {
      throw UserError(msg::make("MATER_6", {{"cell_name", mesh.cellName(c)}}, at));
    }
    const std::string& relation = relations[static_cast<std::size_t>(c)];
    auto key = std::make_pair(m, relation);
    auto found = std::find_if(made_.begin(), made_.end(), [&](const auto& p) { return p.first == key; });
    const behaviour::Behaviour* b = nullptr;
    if (found == made_.end()) {
      owned_.push_back(makeBehaviour(*m, relation, c, mesh, at));
      b = owned_.back().get();
      made_.emplace_back(key, b);
      maxVariables_ = std::max(maxVariables_, b->internalVariableCount());
      allLinear_ = allLinear_ && b->isLinear();
      allSymmetric_ = allSymmetric_ && b->symmetricTangent();
    } else {
      b = found->second;
    }
    cells_[static_cast<std::size_t>(c)] = b;
  }
}

std::vector<std::string> CellBehaviours::relationNames() const {
  std::vector<std::string> out;
  for (const auto& b : owned_) {
    std::string n(b->name());
    if (std::find(out.begin(), out.end(), n) == out.end()) {
      out.push_back(n);
    }
  }
  return out;
}

} // namespace stella
