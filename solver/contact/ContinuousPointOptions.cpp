// Continuous contact at integration points (ContinuousPointContact.hpp): the friction frame of a
// point at its pairing (its tangents, what SANS_GROUP_NO_FR / DIRE_EXCL_FROT leave of them), and
// the zone options SEUIL_INIT and GLISSIERE.

#include "solver/contact/ContinuousPointContact.hpp"

#include "solver/contact/ContinuousFrictionExclusion.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

void pointTangents(const Point3& n, bool threeD, Point3& t1, Point3& t2) {
  if (!threeD) {
    t1 = Point3{-n[1], n[0], 0.0};
    t2 = Point3{0.0, 0.0, 0.0};
    return;
  }
  const Point3 e = std::fabs(n[0]) <= 0.9 ? Point3{1.0, 0.0, 0.0} : Point3{0.0, 1.0, 0.0};
  const Point3 t = e - dot(e, n) * n;
  t1 = (1.0 / norm(t)) * t;
  t2 = cross(n, t1);
}

// SANS_GROUP_NO_FR at points: the points of a slave cell with an excluded node (the cell's contact
// element, as code_aster excludes per contact element) lose the excluded direction.
void ContinuousPointContactConstraint::markExcludedPoints() {
  if (!friction()) {
    return;
  }
  const auto excluded = excludedFrictionNodes(*definition_);
  for (ContactPoint& p : points_) {
    const auto& flags = excluded[static_cast<std::size_t>(p.zone)];
    p.excluded = false;
    for (NodeId n : p.nodes) {
      p.excluded = p.excluded || (!flags.empty() && flags[static_cast<std::size_t>(n)] != 0);
    }
  }
}

void ContinuousPointContactConstraint::pairFriction(ContactPoint& p, const Point3& n,
                                                    const std::vector<std::pair<NodeId, double>>& terms) {
  const bool threeD = tangentComponents() == 2;
  Point3 t1;
  Point3 t2;
  pointTangents(n, threeD, t1, t2);
  FrictionBasis b;
  b.directions = tangentComponents();
  if (p.excluded) {
    const ContinuousZone& z = definition_->zones[static_cast<std::size_t>(p.zone)].continuous;
    b = excludedFrictionBasis(
        z, t1, t2, threeD,
        fmt::format("a contact point of slave cell {}", definition_->mesh->cellName(p.cell)));
    if (b.directions == 1) { // the excluded direction second: its multiplier's equation is lambda_t = 0
      b.basis.row(1) = Eigen::Vector2d(b.basis(0, 1), -b.basis(0, 0)).transpose();
    }
  }
  p.basis = b.basis;
  p.directions = b.directions;
  for (std::size_t j = 0; j < 2; ++j) {
    const Point3 d =
        p.basis(static_cast<Eigen::Index>(j), 0) * t1 + p.basis(static_cast<Eigen::Index>(j), 1) * t2;
    p.direction[j] = {d[0], d[1], d[2]};
    if (static_cast<int>(j) < p.directions) {
      p.frictionRow[j] = rowAlong(dofs_, terms, d);
    }
  }
}

// SEUIL_INIT: LAGS_C = -SEUIL_INIT on the nodes of the points in contact at the first step's start
// (the friction threshold holding them sticking from the first iteration, notice §4.4.1); GLISSIERE:
// those points are held in contact from the start.
void ContinuousPointContactConstraint::applyInitialOptions() {
  if (!firstStep_) {
    return;
  }
  bool any = false;
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    const ContactZone& zone = definition_->zones[static_cast<std::size_t>(p.zone)];
    if (status_[q] == 0) {
      continue;
    }
    if (zone.slide) {
      closed_[q] = 1;
    }
    if (!friction() || !zone.continuous.initialThreshold || p.penalised) {
      continue;
    }
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      if (p.multiplier[k] >= 0 && p.shape[k] != 0.0) {
        lambda_[static_cast<std::size_t>(p.multiplier[k])] = -std::fabs(*zone.continuous.initialThreshold);
        any = true;
      }
    }
  }
  if (any) {
    resetFrictionStep(); // POINT_FIXE: the first loop's threshold
  }
}

// GLISSIERE: the points in contact at the end of an accepted step stay in contact.
void ContinuousPointContactConstraint::holdClosed() {
  for (std::size_t q = 0; q < points_.size() && q < contactStart_.size(); ++q) {
    if (contactStart_[q] != 0 && definition_->zones[static_cast<std::size_t>(points_[q].zone)].slide) {
      closed_[q] = 1;
    }
  }
}

} // namespace stella::contact
