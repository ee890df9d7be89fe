#pragma once
// Change of frame of field components (MODI_REPERE), as code_aster's chrpno/chrpel:
//   - a frame is the rotation R whose rows are the local axes in global coordinates: local
//     components v' = R v of a vector, S' = R S R^T of a symmetric tensor;
//   - UTILISATEUR: R from the nautical angles (alpha about Z, then beta about the new Y, then
//     gamma about the new X, degrees: first row (cos b cos a, cos b sin a, -sin b)), or from
//     VECT_X and VECT_Y (Y made orthogonal to X, Z = X x Y);
//   - CYLINDRIQUE: at each point P, the rows (e_r, e_z, e_theta): e_z the unit axis, e_r the unit
//     part of P - ORIGINE orthogonal to the axis, e_theta = e_z x e_r (2D: axis Z).
// Component layouts (the NOM_CMP of MODI_CHAM, in this order):
//   VECT_2D (vx, vy)                  UTILISATEUR: the in-plane rotation; CYLINDRIQUE: (v_r, v_theta)
//   VECT_3D (vx, vy, vz)              R v (CYLINDRIQUE: (v_r, v_z, v_theta), code_aster's order)
//   TENS_2D (xx, yy, zz, xy)          UTILISATEUR: (xx', yy', zz', xy'); CYLINDRIQUE, as code_aster:
//                                     (rr, zz, theta theta, r theta)
//   TENS_3D (xx, yy, zz, xy, xz, yz)  the six components of R S R^T in the same order.

#include "solver/mesh/Mesh.hpp"

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace stella {

enum class FrameQuantity { Vector2D, Vector3D, Tensor2D, Tensor3D };

// The quantity of a MODI_CHAM TYPE_CHAM (VECT_2D ... TENS_3D), nullopt for the others.
std::optional<FrameQuantity> frameQuantity(std::string_view typeCham);
// Number of components NOM_CMP must give.
int frameComponentCount(FrameQuantity q);

using Rotation = std::array<std::array<double, 3>, 3>;

Rotation nauticalRotation(double alphaDegrees, double betaDegrees, double gammaDegrees);
// nullopt when X is zero or Y is parallel to X.
std::optional<Rotation> rotationFromVectors(const Point3& x, const Point3& y);
// The cylindrical frame at `p`; nullopt when `p` lies on the axis (`axis` of unit length).
std::optional<Rotation> cylindricalRotation(const Point3& origin, const Point3& axis, const Point3& p);

// The components `v` (frameComponentCount(q) values) expressed in the frame `r`.
void rotateComponents(FrameQuantity q, const Rotation& r, bool cylindrical, std::span<double> v);

} // namespace stella
