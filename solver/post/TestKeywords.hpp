#pragma once
// The keywords TEST_RESU and TEST_TABLE share (VALE_CALC, TOLE_MACHINE, REFERENCE, VALE_REFE,
// PRECISION, CRITERE, ORDRE_GRANDEUR, LEGENDE) turned into a ValueTest, and the printing of a
// test into the result and message files.

#include "TestReport.hpp"
#include "catalog/KeywordTree.hpp"

#include <string>
#include <utility>
#include <vector>

namespace stella {

class Session;

// `legend` is used when LEGENDE is absent. Throws UserError (TEST_1) for the forms not
// implemented yet (several values in VALE_CALC, complex values).
ValueTest valueTestFromKeywords(const KeywordTree& keywords, double computed, const std::string& legend);

// Writes the header and the lines to the result file and the message file, and counts OK/NOOK.
void reportTest(Session& session, const std::vector<std::pair<std::string, std::string>>& header,
                const ValueTest& test);

} // namespace stella
