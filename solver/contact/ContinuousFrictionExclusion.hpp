#pragma once
// SANS_GROUP_NO_FR and DIRE_EXCL_FROT of the continuous formulation, shared by the friction at the
// slave nodes (ContinuousFrictionOptions.cpp) and at integration points (ContinuousPointPairing.cpp):
// the excluded slave nodes per zone, and the friction directions left at an excluded place.

#include "solver/contact/ContactDefinition.hpp"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace stella::contact {

// Per zone: flags over the mesh nodes of SANS_GROUP_NO_FR (empty without it). Throws CONTACT_1 for
// a group the mesh does not have.
std::vector<std::vector<char>> excludedFrictionNodes(const ContactDefinition& definition);

// The friction directions left at an excluded place of tangents t1 (and t2 in 3D): rows of `basis`
// (coefficients on t1, t2), `directions` of them. Without DIRE_EXCL_FROT none; with it, in 3D the
// tangent orthogonal to the direction's projection on the tangent plane, in 2D and AXIS none (the
// only tangent is the excluded one). A direction normal to the surface excludes nothing: CONTACT_30
// naming `place`.
struct FrictionBasis {
  Eigen::Matrix2d basis = Eigen::Matrix2d::Identity();
  int directions = 0;
};
FrictionBasis excludedFrictionBasis(const ContinuousZone& zone, const Point3& t1, const Point3& t2,
                                    bool threeD, const std::string& place);

} // namespace stella::contact
