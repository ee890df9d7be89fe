#pragma once
// Nodal forces of a stress field: FORC_NODA = sum over the volume cells of B^T sigma at the
// Gauss points (physical DOF vector), the internal forces in equilibrium with the loads and the
// reactions; REAC_NODA = FORC_NODA - external forces.

#include "solver/assembly/DofMap.hpp"
#include "solver/database/Field.hpp"
#include "solver/fem/GreenLagrange.hpp"

#include <Eigen/Dense>

namespace stella {

// B^T sigma summed over the volume cells. A cell whose `strains` entry (null: all PETIT) is
// GROT_GDEP gets B_F^T S, B_F at the displacement `depl` (a DEPL field, required then).
Eigen::VectorXd forcesFromStress(const Model& model, const DofMap& dofs, const Field& stress,
                                 const std::vector<fem::StrainMeasure>* strains = nullptr,
                                 const Field* depl = nullptr);

} // namespace stella
