#pragma once
// The keywords TEST_RESU and TEST_TABLE share (VALE_CALC, TOLE_MACHINE, REFERENCE, VALE_REFE,
// PRECISION, CRITERE, ORDRE_GRANDEUR, LEGENDE) turned into a ValueTest (reported by
// TestReport.hpp's reportTest).

#include "catalog/KeywordTree.hpp"
#include "solver/post/TestReport.hpp"

#include <string>
#include <utility>
#include <vector>

namespace stella {

// `legend` is used when LEGENDE is absent. Throws UserError (TEST_1) for the forms not
// implemented yet (several values in VALE_CALC, complex values).
ValueTest valueTestFromKeywords(const KeywordTree& keywords, double computed, const std::string& legend);

} // namespace stella
