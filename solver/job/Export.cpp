#include "Export.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

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
    throw UserError(msg::make("EXPORT_2", {{"w", w[0]}, {"w_count", std::to_string(w.size() - 1)}}, at));
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
      throw UserError(msg::make("EXPORT_3", {{"v1c", std::string(1, c)}, {"w", w[3]}}, at));
    }
  }
  if (!e.data && !e.result) {
    throw UserError(msg::make("EXPORT_3.2", {}, at));
  }
  int unit = -1;
  auto [ptr, ec] = std::from_chars(w[4].data(), w[4].data() + w[4].size(), unit);
  if (ec != std::errc() || ptr != w[4].data() + w[4].size() || unit < 0 || unit > 99) {
    throw UserError(msg::make("EXPORT_4", {{"w", w[4]}}, at));
  }
  e.unit = unit;
  if (e.data && e.type != "comm" && (unit == 6 || unit == 15)) {
    throw UserError(msg::make("EXPORT_5", {}, at));
  }
  if (e.compressed && e.data) {
    throw UserError(msg::make("EXPORT_6", {}, at));
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
        throw UserError(msg::make("EXPORT_2.2", {}, at));
      }
      ex.parameters[w[1]] = std::vector<std::string>(w.begin() + 2, w.end());
    } else if (w[0] == "A") {
      ex.arguments.insert(ex.arguments.end(), w.begin() + 1, w.end());
    } else if (w[0] == "F" || w[0] == "R") {
      ExportEntry e = parseFileLine(w, at, base);
      e.line = n;
      if (e.type == "comm" && e.data && !std::filesystem::exists(e.path)) {
        throw UserError(
            msg::make("EXPORT_7", {{"path_as_written", e.pathAsWritten}, {"base", base.string()}}, at));
      }
      ex.entries.push_back(std::move(e));
    } else {
      throw UserError(msg::make("EXPORT_1", {{"w", w[0]}}, at));
    }
  }
  if (ex.commandFiles().empty()) {
    SourceLocation at;
    at.file = src;
    at.line = std::max(1, src->lineCount());
    at.column = 1;
    throw UserError(msg::make("EXPORT_8", {}, at));
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
