#pragma once
// The contact links of a pairing written on the equations of a mechanical system (DofMap
// physical numbering): one row per paired link of a resolved zone (RESOLUTION='OUI'),
//   A   gradient of the gap:  +n on the slave node's DOFs, -w_j n on master node j's DOFs, so
//       that gap(u) = g + A (u - u_pairing) and A^T lambda is the contact force on the
//       structure (lambda >= 0 pushes the slave node along the master's outward normal);
//   T1, T2  the same with the tangents (relative slip of the slave node on the master).

#include "solver/assembly/DofMap.hpp"
#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/PenaltyContact.hpp"

#include <vector>

namespace stella::contact {

struct LinkRows {
  ContactProblem problem; // A, gaps at the pairing, bilateral flags
  FrictionRows friction;  // T1, T2 (empty unless requested)
  std::vector<int> link;  // row -> index of its link in the pairing
};

// `resolved[z]`: whether zone z is resolved; `bilateral[k]`: whether link k is bilateral
// (GLISSIERE, may be empty). Components of the links' vectors beyond the model's DOFs per node
// are ignored (2D models).
LinkRows buildLinkRows(const std::vector<ContactLink>& links, const DofMap& dofs,
                       const std::vector<bool>& resolved, const std::vector<char>& bilateral,
                       bool withFriction);

// The displacement of every node in the 3-per-node layout pairing positions use (zero for
// nodes without DOFs and for the missing components of 2D models).
std::vector<double> nodalDisplacement(const DofMap& dofs, NodeId nodeCount, const Eigen::VectorXd& u);

// Physical equations of the nodes of the contact surfaces (slave and master) of every zone,
// sorted: the geometric loop measures displacements on them.
std::vector<int> contactEquations(const ContactDefinition& definition, const DofMap& dofs);

} // namespace stella::contact
