// CONT_NOEU from contact links and their states.

#include "solver/contact/ContactResultField.hpp"

#include "solver/database/Result.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <cmath>

namespace stella::contact {

const std::vector<std::string>& contNoeuComponents() {
  static const std::vector<std::string> names{
      "CONT", "JEU",  "RN",   "RNX",  "RNY",  "RNZ",  "GLIX", "GLIY",   "GLI",    "RTAX",
      "RTAY", "RTAZ", "RTGX", "RTGY", "RTGZ", "RX",   "RY",   "RZ",     "R",      "HN",
      "I",    "IX",   "IY",   "IZ",   "PT_X", "PT_Y", "PT_Z", "PROJ_X", "PROJ_Y", "PROJ_Z"};
  return names;
}

std::vector<LinkState> measuredGaps(const std::vector<ContactLink>& links) {
  std::vector<LinkState> states(links.size());
  for (std::size_t i = 0; i < links.size(); ++i) {
    states[i].gap = links[i].gap;
  }
  return states;
}

Field buildContNoeu(std::size_t nodeCount, const std::vector<ContactLink>& links,
                    const std::vector<LinkState>& states, bool withFriction) {
  Field field = Field::nodal("INFC_R", contNoeuComponents(), nodeCount);
  field.markPartial();
  enum C : std::size_t {
    CONT,
    JEU,
    RN,
    RNX,
    GLIX = 6,
    GLIY,
    GLI,
    RTAX,
    RTGX = 12,
    RX = 15,
    R = 18,
    PROJ_X = 27
  };
  for (std::size_t k = 0; k < links.size(); ++k) {
    const ContactLink& l = links[k];
    const LinkState& s = states[k];
    const auto node = static_cast<std::size_t>(l.slave);
    for (std::size_t c = 0; c < field.componentCount(); ++c) {
      field.setDefined(node, c);
      field.value(node, c) = 0.0;
    }
    if (!l.paired) {
      field.value(node, CONT) = -1.0;
      continue;
    }
    const bool active = s.status != LinkStatus::Open;
    field.value(node, CONT) = !active ? 0.0 : (withFriction && s.status == LinkStatus::Sticking ? 1.0 : 2.0);
    field.value(node, JEU) = s.gap;
    const Point3 rn = s.normalForce * l.normal;
    const Point3 rt = s.friction[0] * l.tangent1 + s.friction[1] * l.tangent2;
    const bool sticking = withFriction && s.status == LinkStatus::Sticking;
    const bool sliding = withFriction && s.status == LinkStatus::Sliding;
    for (std::size_t a = 0; a < 3; ++a) {
      field.value(node, RNX + a) = rn[a];
      field.value(node, RTAX + a) = sticking ? rt[a] : 0.0;
      field.value(node, RTGX + a) = sliding ? rt[a] : 0.0;
      field.value(node, RX + a) = rn[a] + (sticking || sliding ? rt[a] : 0.0);
      field.value(node, PROJ_X + a) = l.projection[a];
    }
    field.value(node, RN) = norm(rn);
    field.value(node, GLIX) = s.slip[0];
    field.value(node, GLIY) = s.slip[1];
    field.value(node, GLI) = std::hypot(s.slip[0], s.slip[1]);
    field.value(node, R) = std::sqrt(field.value(node, RX) * field.value(node, RX) +
                                     field.value(node, RX + 1) * field.value(node, RX + 1) +
                                     field.value(node, RX + 2) * field.value(node, RX + 2));
  }
  return field;
}

std::shared_ptr<Field> withMultiplierComponents(const Field& depl, const std::vector<std::string>& extra) {
  std::vector<std::string> components = depl.components();
  components.insert(components.end(), extra.begin(), extra.end());
  const std::size_t nodes = depl.entityCount();
  const std::size_t c0 = depl.componentCount();
  auto out = std::make_shared<Field>(Field::nodal(depl.quantity(), components, nodes));
  out->markPartial();
  for (std::size_t n = 0; n < nodes; ++n) {
    for (std::size_t c = 0; c < c0; ++c) {
      out->value(n, c) = depl.value(n, c);
      if (depl.defined(n, c)) {
        out->setDefined(n, c);
      }
    }
  }
  return out;
}

MultiplierDepl multiplierDepl(const ResultStep& step, std::size_t frictionDirections) {
  const auto found = step.fields.find("DEPL");
  if (found == step.fields.end() || found->second == nullptr) {
    return {};
  }
  const Field& depl = *found->second;
  if (depl.componentIndex("LAGS_C")) {
    return {};
  }
  std::vector<std::string> extra;
  extra.push_back("LAGS_C");
  if (frictionDirections >= 1) {
    extra.push_back("LAGS_F1");
  }
  if (frictionDirections >= 2) {
    extra.push_back("LAGS_F2");
  }
  return {withMultiplierComponents(depl, extra), depl.componentCount()};
}

} // namespace stella::contact
