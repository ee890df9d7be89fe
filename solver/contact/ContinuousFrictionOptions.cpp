// The zone options of the continuous formulation around friction (ContinuousContactConstraint):
//   SANS_GROUP_NO_FR (+ DIRE_EXCL_FROT): the friction directions of the listed slave nodes. Without
//     DIRE_EXCL_FROT no friction at all there; with it (global frame), the direction's projection on
//     the tangent plane carries no friction, the tangent orthogonal to it keeps Coulomb's law (in 2D
//     and AXIS the only tangent is the excluded one). A direction normal to the surface excludes
//     nothing: refused (CONTACT_30) naming the node.
//   SEUIL_INIT: the contact pressure |LAGS_C| of the nodes in contact at the first step's start, so
//     their friction threshold mu SEUIL_INIT holds them sticking from the first iteration (notice
//     §4.4.1: blocking the tangential rigid-body motion); default none (a zero threshold).
//   GLISSIERE='OUI': a slave node in contact at the start of the calculation (CONTACT_INIT) or at
//     the end of an accepted step stays in contact afterwards (bilateral: LAGS_C may turn positive,
//     a tension).
//   The DEPL components LAGS_F1 (and LAGS_F2 in 3D): the tangential pressure over the threshold
//     mu |LAGS_C| on the pairing's tangents (norm <= 1, 1 sliding), 0 out of contact.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousFrictionExclusion.hpp"

#include "messages/Messages.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

void addCombination(Triplets& out, int row, const SparseRows& t1, const SparseRows& t2, double a, double b) {
  for (SparseRows::InnerIterator it(t1, row); it; ++it) {
    out.emplace_back(row, static_cast<int>(it.col()), a * it.value());
  }
  if (t2.rows() > row) {
    for (SparseRows::InnerIterator it(t2, row); it; ++it) {
      out.emplace_back(row, static_cast<int>(it.col()), b * it.value());
    }
  }
}

} // namespace

void ContinuousContactConstraint::frictionPaired() {
  closed_.resize(links_.size(), 0);
  if (!friction()) {
    return;
  }
  lagsF_.resize(links_.size(), Eigen::Vector2d::Zero());
  lagsFStart_.resize(links_.size(), Eigen::Vector2d::Zero());
  const auto m = static_cast<int>(rows_.link.size());
  const SparseRows& t1 = rows_.friction.T1;
  const SparseRows& t2 = rows_.friction.T2;
  const bool threeD = t2.rows() > 0;
  const auto excluded = excludedFrictionNodes(*definition_);
  std::array<Triplets, 2> f;
  basis_.assign(static_cast<std::size_t>(m), Eigen::Matrix2d::Identity());
  directions_.assign(static_cast<std::size_t>(m), threeD ? 2 : 1);
  for (int i = 0; i < m; ++i) {
    const ContactLink& l = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)])];
    const auto& flags = excluded[static_cast<std::size_t>(l.zone)];
    auto& basis = basis_[static_cast<std::size_t>(i)];
    int& d = directions_[static_cast<std::size_t>(i)];
    if (!flags.empty() && flags[static_cast<std::size_t>(l.slave)] != 0) {
      const ContinuousZone& z = definition_->zones[static_cast<std::size_t>(l.zone)].continuous;
      const FrictionBasis b =
          excludedFrictionBasis(z, l.tangent1, l.tangent2, threeD,
                                fmt::format("slave node {}", definition_->mesh->nodeName(l.slave)));
      d = b.directions;
      if (d > 0) {
        basis = b.basis;
      }
    }
    for (int j = 0; j < d; ++j) {
      addCombination(f[static_cast<std::size_t>(j)], i, t1, t2, basis(j, 0), basis(j, 1));
    }
  }
  const auto n = static_cast<Eigen::Index>(t1.cols());
  for (std::size_t j = 0; j < 2; ++j) {
    frictionRows_[j].resize(m, n);
    frictionRows_[j].setFromTriplets(f[j].begin(), f[j].end());
  }
}

void ContinuousContactConstraint::applyInitialThreshold() {
  if (!firstStep_) {
    return;
  }
  bool any = false;
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    const ContactZone& zone = definition_->zones[static_cast<std::size_t>(links_[k].zone)];
    if (status_[k] == 0) {
      continue;
    }
    if (zone.slide) {
      closed_[k] = 1; // GLISSIERE: in contact from the start
    }
    if (friction() && zone.continuous.initialThreshold) {
      lagsC_[k] = -std::fabs(*zone.continuous.initialThreshold);
      any = true;
    }
  }
  if (any) {
    resetFrictionStep(); // POINT_FIXE: the first loop's threshold
  }
}

bool ContinuousContactConstraint::heldClosed(std::size_t k) const {
  return k < closed_.size() && closed_[k] != 0;
}

void ContinuousContactConstraint::storeFriction(Field& out, std::size_t c0) const {
  const bool threeD = rows_.friction.T2.rows() > 0;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (!resolvedZone_[static_cast<std::size_t>(links_[k].zone)]) {
      continue;
    }
    const auto n = static_cast<std::size_t>(links_[k].slave);
    for (std::size_t c = 0; c < (threeD ? 2U : 1U); ++c) {
      out.value(n, c0 + c) = 0.0;
      out.setDefined(n, c0 + c);
    }
  }
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    // the tangential pressure over the Coulomb threshold mu |LAGS_C| (norm <= 1, 1 sliding), on the
    // pairing's tangents; 0 out of contact
    const double limit = k < lagsC_.size() ? coulombOfRow(row) * std::max(0.0, -lagsC_[k]) : 0.0;
    if (!(limit > 0.0) || k >= lagsF_.size()) {
      continue;
    }
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    for (int j = 0; j < frictionDirections(row); ++j) {
      v += lagsF_[k](j) * basis_[i].row(j).transpose();
    }
    const auto n = static_cast<std::size_t>(links_[k].slave);
    out.value(n, c0) = v(0) / limit;
    if (threeD) {
      out.value(n, c0 + 1) = v(1) / limit;
    }
  }
}

} // namespace stella::contact
