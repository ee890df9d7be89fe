// RepeatedConditions: one multiplier per imposed DOF (see the header).

#include "solver/model/RepeatedConditions.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/model/Model.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>

namespace stella {

namespace {

struct FirstCondition {
  std::size_t entry = 0; // index in the EXCIT list
  double value = 0.0;    // the imposed DOF value, v / c
  std::string origin;
};

bool sameValue(double a, double b) {
  return std::fabs(a - b) <= 1.0e-12 * std::max(std::fabs(a), std::fabs(b));
}

// The DOFs imposed so far (eliminated ones first) and the check of a repetition.
class ImposedDofs {
public:
  explicit ImposedDofs(const std::vector<ExcitedLoad>& loads) : loads_(loads) {}

  // Records the condition, or checks it against the first one on the same DOF; returns true
  // when it repeats that one (same value at every instant), throws LOAD_11 when it conflicts.
  bool repeats(std::size_t entry, NodeId node, int component, double value, const std::string& origin,
               const Mesh* mesh) {
    auto [it, inserted] = first_.try_emplace({node, component}, FirstCondition{entry, value, origin});
    if (inserted) {
      return false;
    }
    const FirstCondition& f = it->second;
    const ExcitedLoad& other = loads_[f.entry];
    const ExcitedLoad& self = loads_[entry];
    const bool bothZero = value == 0.0 && f.value == 0.0;
    const bool sameScaling = f.entry == entry || other.multiplier == self.multiplier;
    if (bothZero || (sameScaling && sameValue(value, f.value))) {
      return true;
    }
    const std::string name = mesh != nullptr ? mesh->nodeName(node) : fmt::format("#{}", node + 1);
    const std::string cmp = Model::componentName(component);
    throw UserError(msg::make("LOAD_11",
                              {{"name", name},
                               {"cmp", cmp},
                               {"f", f.value},
                               {"origin", f.origin},
                               {"name_2", other.name},
                               {"value", value},
                               {"origin_2", origin},
                               {"name_3", self.name}},
                              self.location)
                        .withNote(sameScaling ? msg::text("LOAD_11.n1") : msg::text("LOAD_11.n2")));
  }

private:
  const std::vector<ExcitedLoad>& loads_;
  std::map<std::pair<NodeId, int>, FirstCondition> first_;
};

} // namespace

std::vector<std::shared_ptr<const MechanicalLoad>>
mergeRepeatedConditions(const std::vector<ExcitedLoad>& loads, int* dropped) {
  ImposedDofs imposed(loads);
  for (std::size_t e = 0; e < loads.size(); ++e) {
    if (const auto& k = loads[e].kinematic) {
      const Mesh* mesh = k->model ? k->model->mesh.get() : nullptr;
      for (const ImposedDof& d : k->imposed) {
        imposed.repeats(e, d.node, d.component, d.value, "MECA_IMPO", mesh);
      }
    }
  }
  std::vector<std::shared_ptr<const MechanicalLoad>> out;
  int count = 0;
  for (std::size_t e = 0; e < loads.size(); ++e) {
    const ExcitedLoad& entry = loads[e];
    out.push_back(entry.load);
    if (!entry.load) {
      continue;
    }
    const Mesh* mesh = entry.load->model ? entry.load->model->mesh.get() : nullptr;
    std::vector<bool> keep(entry.load->relations.size(), true);
    bool anyDropped = false;
    for (std::size_t r = 0; r < entry.load->relations.size(); ++r) {
      const LinearRelation& rel = entry.load->relations[r];
      if (rel.terms.size() != 1 || rel.terms.front().coefficient == 0.0) {
        continue;
      }
      const RelationTerm& t = rel.terms.front();
      if (imposed.repeats(e, t.node, t.component, rel.value / t.coefficient, rel.origin, mesh)) {
        keep[r] = false;
        anyDropped = true;
        ++count;
      }
    }
    if (anyDropped) {
      auto copy = std::make_shared<MechanicalLoad>(*entry.load);
      copy->relations.clear();
      for (std::size_t r = 0; r < keep.size(); ++r) {
        if (keep[r]) {
          copy->relations.push_back(entry.load->relations[r]);
        }
      }
      out.back() = std::move(copy);
    }
  }
  if (dropped != nullptr) {
    *dropped = count;
  }
  return out;
}

} // namespace stella
