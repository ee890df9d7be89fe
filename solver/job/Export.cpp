#include "Export.hpp"

#include "interpreter/Diagnostics.hpp"

#include <charconv>
#include <sstream>

namespace stella {

namespace {

std::vector<std::string> splitWords(std::string_view line) {
  std::vector<std::string> words;
  std::istringstream in{std::string(line)};
  std::string w;
  while (in >> w) {
    words.push_back(w);
  }
  return words;
}

SourceLocation lineLocation(const std::shared_ptr<const SourceFile>& src, int line, std::string_view text) {
  SourceLocation at;
  at.file = src;
  at.line = line;
  std::size_t first = text.find_first_not_of(" \t");
  at.column = first == std::string_view::npos ? 1 : static_cast<int>(first) + 1;
  at.length = static_cast<int>(text.size()) - at.column + 1;
  return at;
}

ExportEntry parseFileLine(const std::vector<std::string>& w, const SourceLocation& at,
                          const std::filesystem::path& base) {
  if (w.size() != 5) {
    throw UserError(Diagnostic::fatal("EXPORT_2",
                                      "an " + w[0] +
                                          " line needs 4 fields: type, path, D/R/C flags and unit; found " +
                                          std::to_string(w.size() - 1),
                                      at)
                        .withNote("example: F mmed mesh.med D 20"));
  }
  ExportEntry e;
  e.directory = w[0] == "R";
  e.type = w[1];
  e.pathAsWritten = w[2];
  std::filesystem::path p(w[2]);
  e.path = p.is_absolute() ? p : (base / p).lexically_normal();
  for (char c : w[3]) {
    if (c == 'D') {
      e.data = true;
    } else if (c == 'R') {
      e.result = true;
    } else if (c == 'C') {
      e.compressed = true;
    } else {
      throw UserError(
          Diagnostic::fatal("EXPORT_3", "unknown flag '" + std::string(1, c) + "' in '" + w[3] + "'", at)
              .withNote("the flags are D (data), R (result) and C (compressed), e.g. D, R, DR, RC"));
    }
  }
  if (!e.data && !e.result) {
    throw UserError(Diagnostic::fatal("EXPORT_3", "the entry is neither data (D) nor result (R)", at));
  }
  int unit = -1;
  auto [ptr, ec] = std::from_chars(w[4].data(), w[4].data() + w[4].size(), unit);
  if (ec != std::errc() || ptr != w[4].data() + w[4].size() || unit < 0 || unit > 99) {
    throw UserError(
        Diagnostic::fatal("EXPORT_4", "the unit '" + w[4] + "' is not an integer between 0 and 99", at));
  }
  e.unit = unit;
  if (e.data && e.type != "comm" && (unit == 6 || unit == 15)) {
    throw UserError(
        Diagnostic::fatal("EXPORT_5", "units 6 and 15 are reserved and cannot hold a data file", at)
            .withNote("unit 6 is the message file; give the data file another unit, e.g. 20"));
  }
  if (e.compressed && e.data) {
    throw UserError(
        Diagnostic::fatal("EXPORT_6", "compressed data files (flag C) are not implemented yet", at)
            .withNote("uncompress the file and drop the C flag"));
  }
  return e;
}

} // namespace

Export Export::read(const std::filesystem::path& file) {
  auto src = SourceFile::load(file.string());
  Export ex;
  ex.file = std::filesystem::absolute(file);
  std::filesystem::path base = ex.file.parent_path();
  for (int n = 1; n <= src->lineCount(); ++n) {
    std::string_view text = src->line(n);
    std::vector<std::string> w = splitWords(text);
    if (w.empty() || w[0][0] == '#') {
      continue;
    }
    SourceLocation at = lineLocation(src, n, text);
    if (w[0] == "P") {
      if (w.size() < 2) {
        throw UserError(Diagnostic::fatal("EXPORT_2", "a P line needs a parameter name", at));
      }
      ex.parameters[w[1]] = std::vector<std::string>(w.begin() + 2, w.end());
    } else if (w[0] == "A") {
      ex.arguments.insert(ex.arguments.end(), w.begin() + 1, w.end());
    } else if (w[0] == "F" || w[0] == "R") {
      ExportEntry e = parseFileLine(w, at, base);
      e.line = n;
      if (e.type == "comm" && e.data && !std::filesystem::exists(e.path)) {
        throw UserError(
            Diagnostic::fatal("EXPORT_7", "the command file '" + e.pathAsWritten + "' does not exist", at)
                .withNote("paths are relative to the export's folder " + base.string()));
      }
      ex.entries.push_back(std::move(e));
    } else {
      throw UserError(Diagnostic::fatal("EXPORT_1", "unknown line type '" + w[0] + "'", at)
                          .withNote("an export line starts with P (parameter), A (arguments), F (file) or R "
                                    "(directory)"));
    }
  }
  if (ex.commandFiles().empty()) {
    SourceLocation at;
    at.file = src;
    at.line = std::max(1, src->lineCount());
    at.column = 1;
    throw UserError(Diagnostic::fatal("EXPORT_8", "the export declares no command file", at)
                        .withNote("add a line such as: F comm study.comm D 1"));
  }
  return ex;
}

std::vector<const ExportEntry*> Export::commandFiles() const {
  std::vector<const ExportEntry*> out;
  for (const auto& e : entries) {
    if (e.type == "comm" && e.data) {
      out.push_back(&e);
    }
  }
  return out;
}

std::vector<std::string> Export::parameter(const std::string& name) const {
  auto it = parameters.find(name);
  return it == parameters.end() ? std::vector<std::string>{} : it->second;
}

} // namespace stella
