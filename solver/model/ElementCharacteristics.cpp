// ElementCharacteristics: the check that every discrete element has a stiffness. The keywords are
// read in solver/inputs/ElementCharacteristicsReader.

#include "solver/model/ElementCharacteristics.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/model/Model.hpp"

#include <fmt/format.h>

namespace stella {

void checkDiscreteElementsCovered(const Model& model, const ElementCharacteristics* cara,
                                  const SourceLocation& at) {
  std::vector<bool> covered(model.cells.size(), false);
  if (cara != nullptr) {
    for (const auto& s : cara->springs) {
      covered[static_cast<std::size_t>(s.cell)] = true;
    }
  }
  for (CellId c : model.cellsOfKind(ElementKind::Discrete)) {
    if (!covered[static_cast<std::size_t>(c)]) {
      throw UserError(Diagnostic::fatal("CARA_5",
                                        fmt::format("discrete element {} (node {}) has no stiffness{}",
                                                    model.mesh->cellName(c),
                                                    model.mesh->nodeName(model.mesh->cellNodes(c)[0]),
                                                    cara == nullptr ? ": the command has no CARA_ELEM" : ""),
                                        at)
                          .withNote(fmt::format(
                              "give its stiffness with AFFE_CARA_ELEM {}=_F(GROUP_MA=..., CARA='K_T_D_N', "
                              "VALE=...) and pass CARA_ELEM= to the command",
                              model.components == 3 ? "DISCRET" : "DISCRET_2D")));
    }
  }
}

} // namespace stella
