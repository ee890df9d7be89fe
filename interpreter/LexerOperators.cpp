// The lexer's operators and brackets: the longest operator spelling, bracket matching, and the
// detection of a bracket left open before a new statement.
#include "Lexer.hpp"
#include "LexerTables.hpp"

namespace stella {

using namespace lexing;

Token Lexer::lexOperator() {
  std::string_view rest = src_.substr(at_, 3);
  char first = rest[0];
  for (const auto& op : operatorTable) {
    if (op.text[0] == first && rest.substr(0, op.text.size()) == op.text) {
      std::size_t begin = at_;
      at_ += op.text.size();
      Token t = makeToken(op.kind, begin, at_);
      if (op.kind == TokenKind::Error) {
        error("SYNTAX_3", {{"text", std::string(op.text)}}, t.pos);
        return t;
      }
      char c = op.text[0];
      if (c == '(' || c == '[' || c == '{') {
        brackets_.push_back({c, t.pos});
      } else if (c == ')' || c == ']' || c == '}') {
        char open = c == ')' ? '(' : (c == ']' ? '[' : '{');
        if (!brackets_.empty()) {
          if (brackets_.back().open != open) {
            error("SYNTAX_8.3",
                  {{"c", c},
                   {"open", brackets_.back().open},
                   {"line", std::to_string(brackets_.back().pos.line)}},
                  t.pos);
          }
          brackets_.pop_back();
        }
      }
      return t;
    }
  }
  std::size_t begin = at_;
  ++at_;
  Token t = makeToken(TokenKind::Error, begin, at_);
  std::string shown = (static_cast<unsigned char>(t.text[0]) < 0x20)
                          ? "\\x" + std::to_string(static_cast<int>(t.text[0]))
                          : std::string(t.text);
  error("SYNTAX_3.2", {{"shown", shown}}, t.pos);
  return t;
}

// At the start of a physical line inside brackets: does the line look like a new statement
// (`NAME =` or `NAME(` at column 1, after a token that cannot continue an expression)?
bool Lexer::looksLikeNewStatement() const {
  if (at_ >= src_.size() || !isNameStart(src_[at_]) || at_ < knownCloseAt_) {
    return false;
  }
  switch (lastKind_) {
  case TokenKind::Name:
  case TokenKind::Int:
  case TokenKind::Real:
  case TokenKind::Imaginary:
  case TokenKind::String:
  case TokenKind::RParen:
  case TokenKind::RBracket:
  case TokenKind::RBrace:
  case TokenKind::KwNone:
  case TokenKind::KwTrue:
  case TokenKind::KwFalse:
    break;
  default:
    return false;
  }
  std::size_t i = at_;
  while (i < src_.size() && isNameChar(src_[i])) {
    ++i;
  }
  if (keywords().contains(src_.substr(at_, i - at_))) {
    return false;
  }
  while (i < src_.size() && (src_[i] == ' ' || src_[i] == '\t')) {
    ++i;
  }
  if (i >= src_.size()) {
    return false;
  }
  return src_[i] == '(' || (src_[i] == '=' && (i + 1 >= src_.size() || src_[i + 1] != '='));
}

// Scans ahead (skipping strings and comments) to see whether the open brackets ever close.
bool Lexer::bracketNeverCloses(std::size_t from) {
  auto depth = static_cast<long>(brackets_.size());
  std::size_t i = from;
  while (i < src_.size()) {
    char c = src_[i];
    if (c == '#') {
      while (i < src_.size() && src_[i] != '\n') {
        ++i;
      }
      continue;
    }
    if (c == '\'' || c == '"') {
      bool triple = i + 2 < src_.size() && src_[i + 1] == c && src_[i + 2] == c;
      std::size_t k = i + (triple ? 3 : 1);
      while (k < src_.size()) {
        if (src_[k] == '\\') {
          k += 2;
          continue;
        }
        if (!triple && src_[k] == '\n') {
          break;
        }
        if (src_[k] == c && (!triple || (k + 2 < src_.size() && src_[k + 1] == c && src_[k + 2] == c))) {
          k += triple ? 3 : 1;
          break;
        }
        ++k;
      }
      i = k;
      continue;
    }
    if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if (c == ')' || c == ']' || c == '}') {
      if (--depth == 0) {
        knownCloseAt_ = i;
        return false;
      }
    }
    ++i;
  }
  return true;
}

} // namespace stella
