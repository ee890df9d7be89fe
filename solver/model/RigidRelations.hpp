#pragma once
// AFFE_CHAR_MECA LIAISON_SOLIDE: the linear relations that make a set of nodes move as a rigid
// body under small rotations, u(M) = u(A) + theta x AM, with the translation and rotation
// eliminated so that only displacement DOFs appear (dualised like LIAISON_DDL).
// With a reference node A, the node B farthest from A and (3D) the node C farthest from the
// line AB: the distances AB (2D), AB, AC, BC (3D) are kept to first order, theta is the linear
// function of u(A), u(B), u(C) that these relative displacements give, and every other node M
// follows u(A) + theta x AM. Degenerate sets are handled: coincident nodes (all follow A:
// dim (n - 1) relations), collinear nodes in 3D (the rotation about the line is free:
// 3n - 5 relations). Otherwise 2n - 3 (2D) or 3n - 6 (3D) independent relations.

#include "solver/mesh/Mesh.hpp"
#include "solver/model/MechanicalLoad.hpp"

#include <span>
#include <vector>

namespace stella {

// `dim`: 2 (DX, DY; rotation about z) or 3. `distMin`: nodes closer than this count as
// coincident, and C closer than this to the line AB makes the set collinear (<= 0: 1e-8 times
// the size of the set).
std::vector<LinearRelation> rigidBodyRelations(const Mesh& mesh, std::span<const NodeId> nodes, int dim,
                                               double distMin);

} // namespace stella
