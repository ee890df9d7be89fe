#pragma once
// The loads (EXCIT) each result was computed with, remembered by MECA_STATIQUE and STAT_NON_LINE
// so that CALC_CHAMP can form REAC_NODA = FORC_NODA - external forces without EXCIT, as
// code_aster does. Kept beside the shared Result contract (which has no place for them).

#include "solver/database/Result.hpp"
#include "solver/nonlinear/Excitation.hpp"

#include <memory>
#include <vector>

namespace stella {

void rememberLoads(const std::shared_ptr<Result>& result, std::vector<Excitation> excitations);
// Null when the result was not made by a static driver of this run.
const std::vector<Excitation>* rememberedLoads(const Result& result);

} // namespace stella
