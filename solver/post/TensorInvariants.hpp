#pragma once
// Invariants and equivalent values of a symmetric second-order tensor given by its components in
// code_aster's order (XX, YY, ZZ, XY[, XZ, YZ]; 2D fields have 4 components, XZ = YZ = 0):
// used by CALC_CHAMP CRITERES (SIEQ_*) and POST_RELEVE_T INVARIANT.
//
// SIEQ components, as code_aster defines them (17 values):
//   VMIS      von Mises stress sqrt(3/2 s:s), s the deviator;
//   TRESCA    the largest difference of two principal stresses;
//   PRIN_1..3 principal stresses in ascending order;
//   VMIS_SG   VMIS with the sign of the trace (+ when the trace is >= 0);
//   VECT_i_X, VECT_i_Y, VECT_i_Z  the unit principal direction of PRIN_i (sign chosen so that its
//             largest-magnitude component is positive);
//   TRSIG     the trace;
//   TRIAX     the triaxiality TRSIG / 3 / VMIS (0 when VMIS <= 1e-10 |TRSIG|).

#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

namespace stella {

// The full 3 x 3 tensor from 4 or 6 components.
Eigen::Matrix3d tensorFromComponents(std::span<const double> components);

double vonMises(const Eigen::Matrix3d& t);
double tresca(const Eigen::Matrix3d& t);

struct PrincipalValues {
  Eigen::Vector3d values;  // ascending
  Eigen::Matrix3d vectors; // column i: direction of values(i)
};
PrincipalValues principalValues(const Eigen::Matrix3d& t);

// SIEQ component names and values (17 each).
const std::vector<std::string>& equivalentStressComponents();
void equivalentStress(const Eigen::Matrix3d& t, std::span<double> out);

} // namespace stella
