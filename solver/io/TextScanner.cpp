// Token reader for text mesh formats (see TextScanner.hpp).

#include "solver/io/TextScanner.hpp"

#include "solver/io/MeshFileError.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace stella {

TextScanner::TextScanner(std::filesystem::path file, std::string text, char comment)
    : file_(std::move(file)), text_(std::move(text)), comment_(comment) {}

void TextScanner::skipSpace() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') {
        ++pos_;
      }
    } else {
      break;
    }
  }
}

std::string_view TextScanner::next() {
  skipSpace();
  tokenLine_ = line_;
  if (pos_ >= text_.size()) {
    return {};
  }
  const std::string_view all(text_);
  if (text_[pos_] == '"') {
    const std::size_t start = pos_ + 1;
    const std::size_t end = text_.find_first_of("\"\n", start);
    if (end == std::string::npos || text_[end] != '"') {
      fail("MESHFILE_2.3", {});
    }
    pos_ = end + 1;
    return all.substr(start, end - start);
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' ||
        (comment_ != '\0' && c == comment_)) {
      break;
    }
    ++pos_;
  }
  return all.substr(start, pos_ - start);
}

std::string_view TextScanner::expect(const char* what) {
  const auto t = next();
  if (t.empty()) {
    fail("MESHFILE_2.4", {{"what", what}});
  }
  return t;
}

std::string_view TextScanner::peek() {
  const std::size_t pos = pos_;
  const int line = line_;
  const int tokenLine = tokenLine_;
  const auto t = next();
  pos_ = pos;
  line_ = line;
  tokenLine_ = tokenLine;
  return t;
}

bool TextScanner::atEnd() {
  skipSpace();
  return pos_ >= text_.size();
}

bool TextScanner::moreOnLine() {
  skipSpace();
  return pos_ < text_.size() && line_ == tokenLine_;
}

void TextScanner::skipLine() {
  while (pos_ < text_.size() && text_[pos_] != '\n') {
    ++pos_;
  }
}

std::int64_t TextScanner::integer(const char* what) {
  const auto t = expect(what);
  std::int64_t v = 0;
  const char* begin = t.data();
  if (!t.empty() && t[0] == '+') {
    ++begin;
  }
  const auto [ptr, ec] = std::from_chars(begin, t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size()) {
    fail("MESHFILE_2.5", {{"what", what}, {"substr", std::string(t.substr(0, 40))}});
  }
  return v;
}

double TextScanner::real(const char* what) {
  const auto t = expect(what);
  std::string s(t);
  // Fortran-style exponents (1.0D+00) appear in .mail files.
  for (char& c : s) {
    if (c == 'D' || c == 'd') {
      c = 'E';
    }
  }
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) {
    fail("MESHFILE_2.6", {{"what", what}, {"substr", std::string(t.substr(0, 40))}});
  }
  if (!std::isfinite(v)) {
    failContent("MESHFILE_3.27", {{"what", std::string(what)}, {"substr", std::string(t.substr(0, 40))}});
  }
  return v;
}

std::int64_t TextScanner::count(const char* what, std::int64_t bytesPerItem) {
  const std::int64_t n = integer(what);
  if (n < 0) {
    failContent("MESHFILE_3.28", {{"what", std::string(what)}, {"n", std::to_string(n)}});
  }
  if (n > static_cast<std::int64_t>(text_.size()) / std::max<std::int64_t>(1, bytesPerItem) + 1) {
    failContent("MESHFILE_3.29", {{"what", std::string(what)}, {"n", std::to_string(n)}});
  }
  return n;
}

void TextScanner::startBinary() {
  if (pos_ < text_.size() && text_[pos_] == '\r') {
    ++pos_;
  }
  if (pos_ < text_.size() && text_[pos_] == '\n') {
    ++pos_;
    ++line_;
  }
}

bool TextScanner::skipPastLine(std::string_view marker) {
  const std::string needle = "\n" + std::string(marker);
  const std::size_t at = text_.find(needle, pos_);
  if (at == std::string::npos) {
    return false;
  }
  pos_ = at + needle.size();
  return true;
}

std::int64_t TextScanner::binaryInteger(int bytes, const char* what) {
  if (pos_ + static_cast<std::size_t>(bytes) > text_.size()) {
    fail("MESHFILE_2.4", {{"what", what}});
  }
  std::int64_t v = 0;
  if (bytes == 4) {
    std::int32_t i = 0;
    std::memcpy(&i, text_.data() + pos_, 4);
    v = i;
  } else {
    std::memcpy(&v, text_.data() + pos_, 8);
  }
  pos_ += static_cast<std::size_t>(bytes);
  return v;
}

double TextScanner::binaryReal(const char* what) {
  if (pos_ + 8 > text_.size()) {
    fail("MESHFILE_2.4", {{"what", what}});
  }
  double v = 0.0;
  std::memcpy(&v, text_.data() + pos_, 8);
  pos_ += 8;
  if (!std::isfinite(v)) {
    failContent("MESHFILE_3.30", {{"what", std::string(what)}});
  }
  return v;
}

std::int64_t TextScanner::binaryCount(const char* what, std::int64_t bytesPerItem) {
  const std::int64_t n = binaryInteger(8, what);
  if (n < 0 || n > static_cast<std::int64_t>(text_.size()) / std::max<std::int64_t>(1, bytesPerItem) + 1) {
    failContent("MESHFILE_3.29", {{"what", std::string(what)}, {"n", std::to_string(n)}});
  }
  return n;
}

void TextScanner::fail(std::string_view key, msg::Args args) const {
  throwFileError(key, file_, args, tokenLine_);
}

void TextScanner::failContent(std::string_view key, msg::Args args) const {
  throwFileError(key, file_, args, tokenLine_);
}

} // namespace stella
