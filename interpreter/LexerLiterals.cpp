// The lexer's literals: names and keywords, numbers (decimal, hexadecimal, octal, binary, reals,
// imaginary), and strings (prefixes, triple quotes, f-strings).
#include "Lexer.hpp"
#include "LexerTables.hpp"

#include <charconv>
#include <limits>

namespace stella {

using namespace lexing;

Token Lexer::lexName() {
  std::size_t begin = at_;
  while (at_ < src_.size() && isNameChar(src_[at_])) {
    ++at_;
  }
  Token t = makeToken(TokenKind::Name, begin, at_);
  auto it = keywords().find(t.text);
  if (it != keywords().end()) {
    t.kind = it->second;
  }
  return t;
}

Token Lexer::lexNumber() {
  std::size_t begin = at_;
  std::string digits;
  bool real = false;
  bool bad = false;
  int base = 10;
  if (src_[at_] == '0' && at_ + 1 < src_.size() &&
      std::string_view("xXoObB").find(src_[at_ + 1]) != std::string_view::npos) {
    char p = static_cast<char>(src_[at_ + 1] | 0x20);
    base = p == 'x' ? 16 : (p == 'o' ? 8 : 2);
    at_ += 2;
    while (at_ < src_.size() && (isNameChar(src_[at_]))) {
      if (src_[at_] != '_') {
        int d = hexDigit(src_[at_]);
        if (d < 0 || d >= base) {
          bad = true;
        }
        digits += src_[at_];
      }
      ++at_;
    }
    bad = bad || digits.empty();
  } else {
    auto takeDigits = [&] {
      while (at_ < src_.size() && (isDigit(src_[at_]) || src_[at_] == '_')) {
        if (src_[at_] != '_') {
          digits += src_[at_];
        }
        ++at_;
      }
    };
    takeDigits();
    if (at_ < src_.size() && src_[at_] == '.') {
      real = true;
      digits += '.';
      ++at_;
      takeDigits();
    }
    if (at_ < src_.size() && (src_[at_] == 'e' || src_[at_] == 'E')) {
      std::size_t k = at_ + 1;
      if (k < src_.size() && (src_[k] == '+' || src_[k] == '-')) {
        ++k;
      }
      if (k < src_.size() && isDigit(src_[k])) {
        real = true;
        digits += 'e';
        digits.append(src_.substr(at_ + 1, k - at_ - 1));
        at_ = k;
        takeDigits();
      } else {
        bad = true;
        at_ = k;
      }
    }
  }
  bool imaginary = false;
  if (base == 10 && at_ < src_.size() && (src_[at_] == 'j' || src_[at_] == 'J')) {
    imaginary = true;
    ++at_;
  }
  while (at_ < src_.size() && isNameChar(src_[at_])) {
    bad = true;
    ++at_;
  }
  Token t = makeToken(TokenKind::Int, begin, at_);
  if (bad) {
    error("SYNTAX_9", {{"text", std::string(t.text)}}, t.pos);
    t.kind = TokenKind::Int;
    return t;
  }
  if (real || imaginary) {
    t.kind = imaginary ? TokenKind::Imaginary : TokenKind::Real;
    auto [end, status] = std::from_chars(digits.data(), digits.data() + digits.size(), t.realValue);
    (void)end;
    if (status == std::errc::result_out_of_range) {
      // Python's rule: a literal beyond the largest float is inf (1e400), below the smallest 0.0
      const std::size_t e = digits.find_first_of("eE");
      const bool tiny = e != std::string::npos && e + 1 < digits.size() && digits[e + 1] == '-';
      t.realValue = tiny ? 0.0 : std::numeric_limits<double>::infinity();
    }
    if (digits == ".") {
      t.realValue = 0.0;
    }
    return t;
  }
  auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), t.intValue, base);
  if (ec != std::errc() || ptr != digits.data() + digits.size()) {
    error("SYNTAX_9.2", {{"text", std::string(t.text)}}, t.pos);
  }
  return t;
}

Token Lexer::lexString(std::size_t prefixLength, bool raw, bool fString) {
  std::size_t begin = at_;
  int startLine = line_;
  Pos startPos = posOf(begin, begin + 1);
  bool startOfLine = physicalLineStart_;
  std::size_t q = at_ + prefixLength;
  char quoteChar = src_[q];
  bool triple = q + 2 < src_.size() && src_[q + 1] == quoteChar && src_[q + 2] == quoteChar;
  std::size_t quoteLength = triple ? 3 : 1;
  std::size_t contentBegin = q + quoteLength;
  int contentColumn = column(contentBegin);
  std::size_t i = contentBegin;
  std::size_t contentEnd = std::string_view::npos;
  while (i < src_.size()) {
    char c = src_[i];
    if (c == '\\' && i + 1 < src_.size()) {
      if (src_[i + 1] == '\n') {
        newline(i + 2);
      }
      i += 2;
      continue;
    }
    if (c == quoteChar) {
      if (!triple) {
        contentEnd = i;
        break;
      }
      if (i + 2 < src_.size() && src_[i + 1] == quoteChar && src_[i + 2] == quoteChar) {
        contentEnd = i;
        break;
      }
    }
    if (c == '\n') {
      if (!triple) {
        break;
      }
      newline(i + 1);
    }
    ++i;
  }
  Token t;
  t.kind = TokenKind::String;
  t.fString = fString;
  t.lineStart = startOfLine;
  physicalLineStart_ = false;
  t.contentColumn = contentColumn;
  t.pos = startPos;
  if (contentEnd == std::string_view::npos) {
    unterminatedStringLine_ = line_;
    error(triple ? "SYNTAX_2.triple" : "SYNTAX_2", {}, startPos);
    at_ = i;
    t.text = src_.substr(begin, at_ - begin);
    t.pos.length = 1;
    return t;
  }
  at_ = contentEnd + quoteLength;
  t.text = src_.substr(begin, at_ - begin);
  std::string_view body = src_.substr(contentBegin, contentEnd - contentBegin);
  if (line_ == startLine) {
    t.pos.length = static_cast<int>(at_ - begin);
  } else {
    t.pos.length = static_cast<int>(t.text.find('\n'));
  }
  if (!fString) {
    t.value = raw ? std::string(body) : decodeEscapes(body);
  } else {
    t.value = raw ? std::string("r") : std::string(); // (GCC 12 -Wrestrict false positive on a const char*)
  }
  return t;
}

} // namespace stella
