// The units commands write (IMPR_RESU, IMPR_TABLE): declared ones only, one format per unit per
// run. Unit 6 is the message file and unit 8 the text result file: both take text only.
#include "Session.hpp"

#include "catalog/KeywordTree.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella {

namespace {

// What a command writes to its unit: the text formats share a file (they append), the others
// each need a file of their own.
std::string writtenFormat(const std::string& command, const KeywordTree& kw) {
  if (command == "IMPR_TABLE") {
    return "text";
  }
  const std::string format = kw.text("FORMAT");
  return format == "RESULTAT" ? "text" : format;
}

std::string describe(const std::string& format) {
  return format == "text" ? "text (FORMAT='RESULTAT', IMPR_TABLE)" : "FORMAT='" + format + "'";
}

} // namespace

void Session::declareResultUnit(int unit) {
  resultUnits_.push_back(unit);
}

void Session::checkOutputUnit(const std::string& command, const KeywordTree& kw, const SourceLocation& call) {
  if ((command != "IMPR_RESU" && command != "IMPR_TABLE") || !kw.has("UNITE")) {
    return;
  }
  const int unit = static_cast<int>(kw.integer("UNITE"));
  SourceLocation at = kw.locationOf("UNITE");
  if (!at.known()) {
    at = call;
  }
  if (unit < 1 || unit > 99) {
    throw UserError(msg::make("UNIT_2", {{"unit", unit}}, at));
  }
  const std::string format = writtenFormat(command, kw);
  if ((unit == 6 || unit == 8) && format != "text") {
    throw UserError(msg::make("UNIT_3",
                              {{"command", command},
                               {"describe", describe(format)},
                               {"unit", unit},
                               {"unit_2", unit == 6 ? "message file" : "text result file"}},
                              at));
  }
  const bool declared = unit == 6 || unit == 8 || units_.count(unit) > 0 ||
                        std::find(resultUnits_.begin(), resultUnits_.end(), unit) != resultUnits_.end();
  if (!resultUnits_.empty() && !declared) {
    std::string known;
    for (int u : resultUnits_) {
      known += (known.empty() ? "" : ", ") + std::to_string(u);
    }
    throw UserError(msg::make("UNIT_2.2", {{"command", command}, {"unit", unit}, {"known", known}}, at));
  }
  auto [it, first] = unitFormats_.emplace(unit, std::make_pair(format, at));
  if (!first && it->second.first != format) {
    throw UserError(msg::make("UNIT_3.2",
                              {{"command", command},
                               {"describe", describe(format)},
                               {"unit", unit},
                               {"describe_2", describe(it->second.first)},
                               {"second", it->second.second.str()}},
                              at));
  }
}

} // namespace stella
