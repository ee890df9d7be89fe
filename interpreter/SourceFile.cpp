#include "SourceFile.hpp"

#include "Diagnostics.hpp"
#include "SourceEncoding.hpp"

#include <fstream>
#include <sstream>

namespace stella {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  lineStarts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n' && i + 1 < text_.size()) {
      lineStarts_.push_back(i + 1);
    }
  }
}

std::shared_ptr<const SourceFile> SourceFile::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw UserError(Diagnostic::fatal("FILE_1", "cannot open file '" + path + "'")
                        .withNote("check that the file exists and is readable"));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return fromText(path, buffer.str());
}

std::shared_ptr<const SourceFile> SourceFile::fromText(std::string name, std::string text) {
  // a file declaring an 8-bit encoding (`# -*- coding: latin-1 -*-`) is held in UTF-8
  return std::shared_ptr<const SourceFile>(new SourceFile(std::move(name), decodeSource(std::move(text))));
}

std::string_view SourceFile::line(int line) const {
  if (line < 1 || line > lineCount()) {
    return {};
  }
  std::size_t begin = lineStarts_[static_cast<std::size_t>(line - 1)];
  std::size_t end = text_.find('\n', begin);
  if (end == std::string::npos) {
    end = text_.size();
  }
  if (end > begin && text_[end - 1] == '\r') {
    --end;
  }
  return std::string_view(text_).substr(begin, end - begin);
}

std::string SourceLocation::str() const {
  if (!file) {
    return "<unknown>";
  }
  std::ostringstream out;
  out << file->name() << ':' << line << ':' << column;
  return out.str();
}

} // namespace stella
