#pragma once
// An expression written inside a string literal of a command file (FORMULE's VALE, a block
// condition): parsed as its own little file, its diagnostics mapped back onto the string's
// place in the command file when the text appears there verbatim.

#include "Diagnostics.hpp"

#include <memory>
#include <string>
#include <vector>

namespace stella {

class EmbeddedText {
public:
  EmbeddedText(const std::string& text, const SourceLocation& origin);
  const std::shared_ptr<const SourceFile>& file() const { return file_; }
  SourceLocation map(const SourceLocation& at) const;
  bool mapped() const { return mapped_; }
  const SourceLocation& origin() const { return origin_; }
  std::vector<Diagnostic> map(std::vector<Diagnostic> ds) const;

private:
  std::shared_ptr<const SourceFile> file_;
  SourceLocation origin_;
  bool mapped_ = false;
  int firstColumn_ = 1;
};

} // namespace stella
