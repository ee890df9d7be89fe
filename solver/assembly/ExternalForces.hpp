#pragma once
// The external force vector of the excitations at a time (physical DOFs): nodal forces,
// pressures and forces on skins, volume forces and gravity (rho g, RHO from the material),
// each load scaled by its FONC_MULT.

#include "solver/assembly/DofMap.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/nonlinear/Excitation.hpp"

#include <Eigen/Dense>
#include <vector>

namespace stella {

// Forces of one load at multiplier 1. Throws UserError LOAD_7 when gravity meets a material
// without RHO.
Eigen::VectorXd loadForces(const MechanicalLoad& load, const DofMap& dofs, const MaterialField* materials);

// Sum over the excitations of factor(time) * loadForces (the per-load vectors are cached by
// the caller through `cache`, one per excitation, computed on first use).
Eigen::VectorXd externalForces(const std::vector<Excitation>& excitations, double time, const DofMap& dofs,
                               const MaterialField* materials, std::vector<Eigen::VectorXd>& cache);

} // namespace stella
