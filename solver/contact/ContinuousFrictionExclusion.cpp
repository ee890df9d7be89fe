// SANS_GROUP_NO_FR and DIRE_EXCL_FROT (see the header).

#include "solver/contact/ContinuousFrictionExclusion.hpp"

#include "messages/Messages.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <cmath>

namespace stella::contact {

std::vector<std::vector<char>> excludedFrictionNodes(const ContactDefinition& def) {
  std::vector<std::vector<char>> excluded(def.zones.size());
  for (std::size_t z = 0; z < def.zones.size(); ++z) {
    const ContinuousZone& c = def.zones[z].continuous;
    if (c.frictionExcludedGroups.empty()) {
      continue;
    }
    excluded[z].assign(static_cast<std::size_t>(def.mesh->nodeCount()), 0);
    for (const std::string& group : c.frictionExcludedGroups) {
      const auto* nodes = def.mesh->nodeGroup(group);
      if (nodes == nullptr) {
        throw UserError(msg::make("CONTACT_1.3", {{"group", group}}, c.frictionExcludedAt));
      }
      for (NodeId n : *nodes) {
        excluded[z][static_cast<std::size_t>(n)] = 1;
      }
    }
  }
  return excluded;
}

FrictionBasis excludedFrictionBasis(const ContinuousZone& z, const Point3& t1, const Point3& t2, bool threeD,
                                    const std::string& place) {
  FrictionBasis out;
  out.directions = 0;
  if (!z.excludedDirection) {
    return out;
  }
  const Point3 e{(*z.excludedDirection)[0], (*z.excludedDirection)[1], (*z.excludedDirection)[2]};
  const double a1 = dot(e, t1);
  const double a2 = threeD ? dot(e, t2) : 0.0;
  const double size = std::hypot(a1, a2);
  if (!(size > 1e-8 * norm(e))) {
    throw UserError(msg::make("CONTACT_30", {{"e", e[0]}, {"e_2", e[1]}, {"e_3", e[2]}, {"place", place}},
                              z.excludedDirectionAt));
  }
  if (threeD) {
    out.basis.row(0) = Eigen::Vector2d(-a2, a1).transpose() / size; // the tangent orthogonal to it
    out.basis.row(1).setZero();
    out.directions = 1;
  }
  return out;
}

} // namespace stella::contact
