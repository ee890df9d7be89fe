// The units commands write (IMPR_RESU, IMPR_TABLE): declared ones only, one format per unit per
// run. Unit 6 is the message file and unit 8 the text result file: both take text only.
#include "Session.hpp"

#include "catalog/KeywordTree.hpp"

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
    throw UserError(Diagnostic::fatal("UNIT_2", fmt::format("UNITE={} is not a unit number", unit), at)
                        .withNote("units go from 1 to 99; 8 is the result file, 80 the MED result"));
  }
  const std::string format = writtenFormat(command, kw);
  if ((unit == 6 || unit == 8) && format != "text") {
    throw UserError(
        Diagnostic::fatal("UNIT_3",
                          fmt::format("{} {} to unit {}: unit {} is the {}, which holds text only", command,
                                      describe(format), unit, unit,
                                      unit == 6 ? "message file" : "text result file"),
                          at)
            .withNote(fmt::format("write {} to a unit of its own (UNITE=80 for MED), declared in the export",
                                  describe(format))));
  }
  const bool declared = unit == 6 || unit == 8 || units_.count(unit) > 0 ||
                        std::find(resultUnits_.begin(), resultUnits_.end(), unit) != resultUnits_.end();
  if (!resultUnits_.empty() && !declared) {
    std::string known;
    for (int u : resultUnits_) {
      known += (known.empty() ? "" : ", ") + std::to_string(u);
    }
    throw UserError(
        Diagnostic::fatal(
            "UNIT_2",
            fmt::format("{} writes to unit {}, which the run does not declare: its file would be lost",
                        command, unit),
            at)
            .withNote("result units of this run: " + known)
            .withNote(fmt::format(
                "declare it in the export (F rmed result.rmed R {}) or write to a declared unit", unit)));
  }
  auto [it, first] = unitFormats_.emplace(unit, std::make_pair(format, at));
  if (!first && it->second.first != format) {
    throw UserError(
        Diagnostic::fatal(
            "UNIT_3",
            fmt::format("{} {} to unit {}, which already receives {} (at {}): one format per unit "
                        "per run",
                        command, describe(format), unit, describe(it->second.first), it->second.second.str()),
            at)
            .withNote("two writers in one file leave it corrupt; give each format its own unit"));
  }
}

} // namespace stella
