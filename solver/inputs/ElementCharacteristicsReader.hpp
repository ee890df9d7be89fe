#pragma once
// The inputs half of AFFE_CARA_ELEM and of the CARA_ELEM= keyword of the commands: the keyword
// tree -> ElementCharacteristics (solver/model/), which the numerics receive.

#include "solver/model/ElementCharacteristics.hpp"

#include <memory>

namespace stella {

class KeywordTree;

// Reads AFFE_CARA_ELEM's keyword tree into `cara` (whose model is set). Throws UserError:
// CARA_1 (a keyword or CARA value not implemented yet, named), CARA_2 (wrong number of VALE
// values), CARA_3 (the selection holds no discrete element of the right dimension), CARA_4
// (negative stiffness).
void readElementCharacteristics(const KeywordTree& keywords, ElementCharacteristics& cara);

// The CARA_ELEM= of a command (MECA_STATIQUE, STAT_NON_LINE), null when absent.
std::shared_ptr<const ElementCharacteristics> readCaraElem(const KeywordTree& keywords);

} // namespace stella
