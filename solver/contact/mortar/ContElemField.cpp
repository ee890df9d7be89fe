// CONT_ELEM of LAC contact (see ContElemField.hpp).

#include "solver/contact/mortar/ContElemField.hpp"

#include "interpreter/Diagnostics.hpp"

#include <cmath>

namespace stella::mortar {

const std::vector<std::string>& contElemComponents() {
  static const std::vector<std::string> names{"PRES", "JEU", "CONT", "COEFSURF", "PRESCOOR"};
  return names;
}

Field buildContElem(const Mesh& mesh, std::span<const LacPatchState> states) {
  const auto& patches = mesh.lacPatches();
  STELLA_ASSERT(states.size() == patches.size(), "CONT_ELEM: one state per LAC patch");
  Field f = Field::perCell("CLAC_R", contElemComponents(), static_cast<std::size_t>(mesh.cellCount()));
  f.markPartial();
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const LacPatchState& s = states[p];
    const double values[5] = {s.pressure, std::isnan(s.gap) ? -1.0 : s.gap, s.contact ? 1.0 : 0.0,
                              s.coefficient, s.coefficient * s.pressure};
    for (const CellId c : patches[p].cells) {
      for (std::size_t k = 0; k < 5; ++k) {
        f.value(static_cast<std::size_t>(c), k) = values[k];
        f.setDefined(static_cast<std::size_t>(c), k);
      }
    }
  }
  return f;
}

} // namespace stella::mortar
