#pragma once
// CONT_ELEM, the cell field of LAC contact (code_aster's option CONT_ELEM, quantity CLAC_R) on
// the slave cells of the patches made by CREA_MAILLAGE/DECOUPE_LAC (Mesh::lacPatches()); every
// cell of a patch carries its patch's values, the other cells none (a partial field):
//   PRES      the patch's contact pressure (its LAGS_C: negative in compression)
//   JEU       the patch's integrated gap, -1 when the patch is not paired
//   CONT      1 in contact, 0 otherwise
//   COEFSURF  the intersection weight (1 when the whole patch is paired)
//   PRESCOOR  COEFSURF * PRES
// The LAC formulation (contact/lac/LacContactConstraint) gives the states; the field is written by
// IMPR_RESU like any cell field.

#include "solver/database/Field.hpp"
#include "solver/mesh/Mesh.hpp"

#include <limits>
#include <span>
#include <string>
#include <vector>

namespace stella::mortar {

const std::vector<std::string>& contElemComponents();

struct LacPatchState {
  double pressure = 0.0;
  double gap = std::numeric_limits<double>::quiet_NaN(); // NaN: not paired
  bool contact = false;
  double coefficient = 0.0;
};

// `states` parallel to mesh.lacPatches().
Field buildContElem(const Mesh& mesh, std::span<const LacPatchState> states);

} // namespace stella::mortar
