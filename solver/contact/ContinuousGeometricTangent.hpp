#pragma once
// The geometric part of the consistent tangent of node-to-surface contact (DEFI_CONTACT
// FORMULATION='CONTINUE', ALGO_RESO_GEOM='NEWTON', notice §3.3.3 and §4.12): the second derivative
// of the gap g of a slave point x_s orthogonally projected on a master cell,
//   g = (x_s - x_m(xi)) . n(xi),   (x_s - x_m(xi)) . tau_a = 0   (xi the projection),
// x_m = sum_j N_j x_j, tau_a = dx_m/dxi_a, n the unit normal, with respect to the positions of the
// slave node and of the master cell's nodes. Its first derivative is the row of the pairing (+n on
// the slave, -N_j n on master node j: the projection's own variation drops out, tau_a . n = 0).
// The second, written with dr = dx_s - sum_j N_j dx_j (at fixed xi), T_a = tau_a . dr,
// P_a = n . sum_j dN_j/dxi_a dx_j (the rotation of the cell), the metric a_ab = tau_a . tau_b,
// the curvature k_ab = n . d2x_m/dxi_a dxi_b and A = a - g k (the derivative of the projection
// equations: dxi = A^-1 (T + g P)):
//   d2g = -[ T^T a^-1 k A^-1 T + T^T A^-1 P + P^T A^-1 T + g P^T A^-1 P ]
// (symmetric: a^-1 k A^-1 = a^-1/2 M (I - g M)^-1 a^-1/2 with M = a^-1/2 k a^-1/2). The curvature
// term vanishes on straight (SEG2) and flat (TRIA3) masters and on a plane QUAD4 whose sides are
// parallel (a parallelogram); it is the term of SEG3, warped QUAD4 and the quadratic faces.
// With friction (FROTTEMENT='COULOMB'), the friction rows T_j (+t_j on the slave, -N_k(xi) t_j on
// master node k; t_1 = +-tau_1 / |tau_1|, t_2 = n x t_1) vary with the geometry too: through the
// tangents t_j (dtau_a = sum_k dN_k/dxi_a dx_k + d2x_m/dxi_a dxi_b dxi_b) and the projection
// (dN_k = dN_k/dxi_a dxi_a, dxi above). frictionRowJacobians gives dT_j / d(x_s, x_1 .. x_n); the
// slip s_j = T_j . (u - u_start) then varies by (T_j + M_j^T (u - u_start)) . du, and the force
// -w p_j T_j by -w (dp_j T_j + p_j M_j du) (ContinuousGeometricFriction.cpp).
// The projection is taken as it is: a slave point brought back onto its cell (projection outside
// by less than TOLE_PROJ_EXT) is linearised as if it were inside.

#include "solver/contact/CellProjection.hpp"
#include "solver/contact/ContactPairing.hpp"

#include <Eigen/Dense>

namespace stella::contact {

// d2g over (x_s, x_1 .. x_n), 3 components per node (x, y, z; the z ones zero in 2D): a square
// matrix of size 3 (1 + n). `dim` is the master cell's parametric dimension (1: SEG, 2: faces);
// `normal` orients n (the pairing's normal, towards the slave).
Eigen::MatrixXd gapHessian(const CellNodes& master, int dim, const std::array<double, 2>& xi,
                           const Point3& slave, const Point3& normal);

// dT_j / d(x_s, x_1 .. x_n) for j = 0 (t_1) and 1 (t_2, zero in 2D): square matrices of size
// 3 (1 + n), row (node, component) of T_j, column the position moved. `tangent1` orients t_1 (the
// pairing's).
std::array<Eigen::MatrixXd, 2> frictionRowJacobians(const CellNodes& master, int dim,
                                                    const std::array<double, 2>& xi, const Point3& slave,
                                                    const Point3& normal, const Point3& tangent1);

// The same for a paired link of the pairing at the positions `position` (its master cell's nodes
// and its projection xi).
Eigen::MatrixXd gapHessian(const Mesh& mesh, const NodePosition& position, const ContactLink& link);

} // namespace stella::contact
