#pragma once
// The loads (EXCIT) and element characteristics (CARA_ELEM) each result was computed with,
// remembered by MECA_STATIQUE and STAT_NON_LINE so that CALC_CHAMP can form FORC_NODA (with the
// forces of discrete springs, and in large displacements where COMPORTEMENT asked for them) and REAC_NODA =
// FORC_NODA - external forces without EXCIT or CARA_ELEM, as code_aster does. Kept beside the shared Result
// contract (which has no place for them).

#include "solver/database/Result.hpp"
#include "solver/fem/GreenLagrange.hpp"
#include "solver/model/ElementCharacteristics.hpp"
#include "solver/nonlinear/Excitation.hpp"

#include <memory>
#include <vector>

namespace stella {

void rememberLoads(const std::shared_ptr<Result>& result, std::vector<Excitation> excitations);
// Null when the result was not made by a static driver of this run.
const std::vector<Excitation>* rememberedLoads(const Result& result);

// The CARA_ELEM of a result (null: none given, or not made by a static driver of this run).
void rememberCharacteristics(const std::shared_ptr<Result>& result,
                             std::shared_ptr<const ElementCharacteristics> cara);
std::shared_ptr<const ElementCharacteristics> rememberedCharacteristics(const Result& result);

// The strain measure of each cell (COMPORTEMENT DEFORMATION) a STAT_NON_LINE result was computed
// with: FORC_NODA of a GROT_GDEP cell is B_F^T S, at the stored DEPL. Null: PETIT everywhere (or
// not made by STAT_NON_LINE in this run).
void rememberStrainMeasures(const std::shared_ptr<Result>& result, std::vector<fem::StrainMeasure> strains);
const std::vector<fem::StrainMeasure>* rememberedStrainMeasures(const Result& result);

} // namespace stella
