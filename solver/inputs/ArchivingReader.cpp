// The ARCHIVAGE factor keyword of STAT_NON_LINE -> ArchiveSelection.

#include "solver/inputs/ArchivingReader.hpp"

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/functions/RealFunction.hpp"

namespace stella {

ArchiveSelection readArchiveSelection(const KeywordTree& statNonLine) {
  if (!statNonLine.has("ARCHIVAGE")) {
    return ArchiveSelection::every(1);
  }
  const KeywordTree& a = statNonLine.occurrences("ARCHIVAGE").front();
  // CRITERE and PRECISION: in the block of INST and LIST_INST
  const auto precision = [&a] { return a.real("PRECISION"); };
  const auto absolute = [&a] { return a.text("CRITERE") == "ABSOLU"; };
  if (a.has("INST")) {
    return ArchiveSelection::at(a.reals("INST"), precision(), absolute());
  }
  if (a.has("LIST_INST")) {
    auto list = conceptData<RealList>(a.conceptValue("LIST_INST"));
    STELLA_ASSERT(list != nullptr, "ARCHIVAGE/LIST_INST holds no list of reals");
    return ArchiveSelection::at(list->values, precision(), absolute());
  }
  const auto step = a.integerOr("PAS_ARCH", 1);
  if (step < 1) {
    throw UserError(msg::make("SNL_6", {}, a.locationOf("PAS_ARCH")));
  }
  return ArchiveSelection::every(static_cast<int>(step));
}

} // namespace stella
