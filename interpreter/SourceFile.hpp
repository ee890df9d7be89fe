#pragma once
// A command file held in memory, with the positions that every token, node, keyword and
// diagnostic refers to.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace stella {

class SourceFile {
public:
  // Reads `path`; throws UserError (FILE_1) naming the path when it cannot be read.
  static std::shared_ptr<const SourceFile> load(const std::string& path);
  static std::shared_ptr<const SourceFile> fromText(std::string name, std::string text);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }
  // Line `line` (1-based) without its end-of-line characters; empty when out of range.
  std::string_view line(int line) const;
  int lineCount() const { return static_cast<int>(lineStarts_.size()); }

private:
  SourceFile(std::string name, std::string text);
  std::string name_;
  std::string text_;
  std::vector<std::size_t> lineStarts_;
};

// A place in a source file: 1-based line and column (in bytes), and the length to underline.
// `file` may be null for locations that do not come from a file (defaults, the catalogue).
struct SourceLocation {
  std::shared_ptr<const SourceFile> file;
  int line = 0;
  int column = 0;
  int length = 1;

  bool known() const { return file != nullptr && line > 0; }
  // "path:line:col" or "<unknown>".
  std::string str() const;
};

} // namespace stella
