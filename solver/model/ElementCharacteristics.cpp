// ElementCharacteristics: the check that every discrete element has a stiffness. The keywords are
// read in solver/inputs/ElementCharacteristicsReader.

#include "solver/model/ElementCharacteristics.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
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
      throw UserError(msg::make("CARA_5",
                                {{"cell_name", model.mesh->cellName(c)},
                                 {"node_name", model.mesh->nodeName(model.mesh->cellNodes(c)[0])},
                                 {"cara", cara == nullptr ? ": the command has no CARA_ELEM" : ""},
                                 {"components", model.components == 3 ? "DISCRET" : "DISCRET_2D"}},
                                at));
    }
  }
}

} // namespace stella
