#pragma once
// The inputs half of ARCHIVAGE (STAT_NON_LINE): the keyword tree -> ArchiveSelection
// (solver/nonlinear/Archiving), which the numerics receive.

#include "solver/nonlinear/Archiving.hpp"

namespace stella {

class KeywordTree;

// From the ARCHIVAGE factor keyword of STAT_NON_LINE (absent or defaulted: every step). Throws
// UserError SNL_6 at PAS_ARCH when it is below 1.
ArchiveSelection readArchiveSelection(const KeywordTree& statNonLine);

} // namespace stella
