#pragma once
// What stella does with each keyword of STAT_NON_LINE's catalogue: implemented, accepted
// without effect (with the reason: e.g. the radial return of VMIS_ISOT_LINE is exact, so
// RESI_INTE changes nothing), or refused by name as not implemented yet. A factor keyword listed
// as refused covers its whole content. The operator refuses, before computing anything, every
// keyword the user gave (not a default) that is refused here; a test walks the catalogue so that
// no keyword is left unclassified.

#include "catalog/KeywordTree.hpp"

#include <map>
#include <string>

namespace stella {

enum class KeywordSupport { Implemented, NoEffect, Refused };

struct KeywordStatus {
  KeywordSupport support = KeywordSupport::Implemented;
  std::string note; // why it has no effect / what it would be
};

// Keyed by path: "NEWTON/REAC_INCR", "PILOTAGE", "INFO".
const std::map<std::string, KeywordStatus>& statNonLineKeywords();

// The status of a path: its own entry, else the nearest listed factor above it; null when the
// path is unclassified.
const KeywordStatus* statNonLineKeywordStatus(const std::string& path);

// Throws UserError SNL_1 naming the first keyword given by the user that is refused.
void refuseUnsupportedKeywords(const KeywordTree& statNonLine);

} // namespace stella
