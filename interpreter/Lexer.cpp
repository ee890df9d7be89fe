// The command-language lexer: Python's tokenizer rules for the subset command files use.
// This file: positions, errors, indentation (INDENT/DEDENT) and the dispatch of each token; the
// literals are in LexerLiterals.cpp, operators and brackets in LexerOperators.cpp.
#include "Lexer.hpp"
#include "LexerTables.hpp"
#include "SourceEncoding.hpp"

#include <algorithm>
#include <cstdio>

namespace stella {

using namespace lexing;

Lexer::Lexer(std::shared_ptr<const SourceFile> file, bool expressionMode)
    : file_(std::move(file)), src_(file_->text()), expressionMode_(expressionMode) {
  if (src_.size() >= 3 && src_.substr(0, 3) == "\xEF\xBB\xBF") {
    at_ = 3; // UTF-8 byte order mark
    lineStart_ = 3;
  }
  checkEncoding();
}

// Python's rules (PEP 263): an unknown declared encoding is an error at its name; without a
// declaration (or with utf-8) the first byte that is not UTF-8 is an error at its place. A file
// declared in an 8-bit encoding was decoded when it was read (SourceFile::fromText).
void Lexer::checkEncoding() {
  auto declaration = declaredEncoding(src_);
  if (declaration) {
    if (encodingNamed(declaration->name) == SourceEncoding::Unknown) {
      Pos at{declaration->line, static_cast<int>(declaration->column),
             static_cast<int>(declaration->name.size())};
      error("SYNTAX_ENCODING", {{"name", declaration->name}}, at);
      return;
    }
  }
  auto bad = invalidUtf8(src_);
  if (!bad) {
    return;
  }
  const std::size_t lineBegin = src_.rfind('\n', *bad == 0 ? 0 : *bad - 1);
  const std::size_t first = lineBegin == std::string_view::npos || (*bad == 0) ? 0 : lineBegin + 1;
  Pos at{
      1 + static_cast<int>(std::count(src_.begin(), src_.begin() + static_cast<std::ptrdiff_t>(*bad), '\n')),
      1 + static_cast<int>(*bad - first), 1};
  char byte[8];
  std::snprintf(byte, sizeof(byte), "0x%02X", static_cast<unsigned char>(src_[*bad]));
  error("SYNTAX_ENCODING.2",
        {{"byte", byte},
         {"value", (declaration ? " is not UTF-8, the encoding its coding line declares"
                                : " is not UTF-8 and no coding line declares the file's encoding")}},
        at);
}

Lexer::Lexer(std::shared_ptr<const SourceFile> file, std::string_view text, int firstLine, int firstColumn)
    : file_(std::move(file)), src_(text), line_(firstLine), firstColumn_(firstColumn), expressionMode_(true) {
}

SourceLocation Lexer::location(const Pos& pos) const {
  return SourceLocation{file_, pos.line, pos.column, pos.length};
}

void Lexer::error(std::string_view key, msg::Args args, Pos at) {
  errors_.push_back(msg::make(key, args, location(at)));
}

Pos Lexer::posOf(std::size_t begin, std::size_t end) const {
  Pos p;
  p.line = line_;
  p.column = column(begin);
  p.length = static_cast<int>(end > begin ? end - begin : 1);
  return p;
}

void Lexer::newline(std::size_t offsetAfter) {
  ++line_;
  lineStart_ = offsetAfter;
  firstColumn_ = 1;
  physicalLineStart_ = true;
}

Token Lexer::makeToken(TokenKind kind, std::size_t begin, std::size_t end) {
  Token t;
  t.kind = kind;
  t.pos = posOf(begin, end);
  t.text = src_.substr(begin, end - begin);
  t.lineStart = physicalLineStart_;
  physicalLineStart_ = false;
  return t;
}

// Measures the indentation of the next non-blank line and queues INDENT/DEDENT tokens.
void Lexer::startLine() {
  while (at_ < src_.size()) {
    std::size_t begin = at_;
    std::size_t i = at_;
    while (i < src_.size() && (src_[i] == ' ' || src_[i] == '\t' || src_[i] == '\f' || src_[i] == '\r')) {
      ++i;
    }
    if (i >= src_.size()) {
      at_ = i;
      return;
    }
    if (src_[i] == '#' || src_[i] == '\n') {
      std::size_t commentBegin = i;
      while (i < src_.size() && src_[i] != '\n') {
        ++i;
      }
      if (comments_ != nullptr && src_[commentBegin] == '#') {
        std::size_t end = i;
        while (end > commentBegin && (src_[end - 1] == '\r' || src_[end - 1] == ' ')) {
          --end;
        }
        comments_->push_back({line_, true, src_.substr(commentBegin, end - commentBegin)});
      }
      if (i < src_.size()) {
        ++i;
        newline(i);
      }
      at_ = i;
      continue;
    }
    std::string ws;
    for (std::size_t k = begin; k < i; ++k) {
      if (src_[k] == ' ' || src_[k] == '\t') {
        ws += src_[k];
      }
    }
    at_ = i;
    indentPos_ = posOf(i, i + 1);
    const std::string& top = indents_.back();
    if (ws == top) {
      return;
    }
    if (ws.size() > top.size() && ws.compare(0, top.size(), top) == 0) {
      indents_.push_back(ws);
      pendingIndent_ = true;
      return;
    }
    int dedents = 0;
    std::size_t level = indents_.size();
    while (level > 1 && indents_[level - 1].size() > ws.size()) {
      --level;
      ++dedents;
    }
    bool consistent = indents_[level - 1] == ws;
    bool prefixOfTop = top.compare(0, ws.size(), ws) == 0;
    if (!consistent) {
      if (prefixOfTop) {
        error("SYNTAX_4", {}, indentPos_);
      } else {
        error("SYNTAX_5", {}, indentPos_);
        return; // read the line as if it were at the current level
      }
    }
    indents_.resize(level);
    pendingDedents_ = dedents;
    return;
  }
}

Token Lexer::next() {
  Token t = nextToken();
  if (t.kind != TokenKind::Indent && t.kind != TokenKind::Dedent) {
    lastKind_ = t.kind;
  }
  return t;
}

Token Lexer::nextToken() {
  for (;;) {
    if (pendingIndent_) {
      pendingIndent_ = false;
      Token t;
      t.kind = TokenKind::Indent;
      t.pos = indentPos_;
      return t;
    }
    if (pendingDedents_ > 0) {
      --pendingDedents_;
      Token t;
      t.kind = TokenKind::Dedent;
      t.pos = indentPos_;
      return t;
    }
    if (atLogicalLineStart_ && brackets_.empty() && !expressionMode_) {
      atLogicalLineStart_ = false;
      startLine();
      continue;
    }
    while (at_ < src_.size() &&
           (src_[at_] == ' ' || src_[at_] == '\t' || src_[at_] == '\f' || src_[at_] == '\r')) {
      ++at_;
    }
    if (at_ >= src_.size()) {
      Pos end = posOf(at_, at_ + 1);
      if (lineHasTokens_ && !expressionMode_) {
        lineHasTokens_ = false;
        Token t;
        t.kind = TokenKind::Newline;
        t.pos = end;
        return t;
      }
      if (indents_.size() > 1 && !expressionMode_) {
        indents_.pop_back();
        Token t;
        t.kind = TokenKind::Dedent;
        t.pos = end;
        return t;
      }
      if (!brackets_.empty() && !finished_) {
        const Bracket& b = brackets_.back();
        error("SYNTAX_8", {{"open", b.open}}, b.pos);
      }
      finished_ = true;
      Token t;
      t.kind = TokenKind::EndOfFile;
      t.pos = end;
      return t;
    }
    char c = src_[at_];
    if (c == '#') {
      std::size_t begin = at_;
      while (at_ < src_.size() && src_[at_] != '\n') {
        ++at_;
      }
      if (comments_ != nullptr) {
        std::size_t end = at_;
        while (end > begin && (src_[end - 1] == '\r' || src_[end - 1] == ' ')) {
          --end;
        }
        comments_->push_back({line_, !lineHasTokens_, src_.substr(begin, end - begin)});
      }
      continue;
    }
    if (c == '\\') {
      std::size_t k = at_ + 1;
      while (k < src_.size() && src_[k] == '\r') {
        ++k;
      }
      if (k < src_.size() && src_[k] == '\n') {
        at_ = k + 1;
        newline(at_);
        physicalLineStart_ = false;
        continue;
      }
      if (k >= src_.size()) {
        at_ = k;
        continue;
      }
      error("SYNTAX_17", {}, posOf(at_, at_ + 1));
      ++at_;
      continue;
    }
    if (c == '\n') {
      Pos p = posOf(at_, at_ + 1);
      ++at_;
      newline(at_);
      if (!expressionMode_ && !brackets_.empty() && looksLikeNewStatement() && bracketNeverCloses(at_)) {
        // `C = [1, 2` then `D = 4` at column 1: the bracket was never closed; report it and read on
        const Bracket& b = brackets_.front();
        if (unterminatedStringLine_ != line_ - 1) { // else the unterminated string explains it
          error("SYNTAX_8.2", {{"open", b.open}, {"line", std::to_string(line_)}}, b.pos);
        }
        brackets_.clear();
        atLogicalLineStart_ = true;
        lineHasTokens_ = false;
        Token t;
        t.kind = TokenKind::Newline;
        t.pos = p;
        t.recovered = true;
        lastKind_ = TokenKind::Newline;
        return t;
      }
      if (expressionMode_ || !brackets_.empty()) {
        continue;
      }
      atLogicalLineStart_ = true;
      if (lineHasTokens_) {
        lineHasTokens_ = false;
        Token t;
        t.kind = TokenKind::Newline;
        t.pos = p;
        return t;
      }
      continue;
    }
    lineHasTokens_ = true;
    if (isDigit(c) || (c == '.' && at_ + 1 < src_.size() && isDigit(src_[at_ + 1]))) {
      return lexNumber();
    }
    if (isNameStart(c)) {
      // string prefixes: r, u, f, b and their two-letter combinations
      std::size_t k = at_;
      bool raw = false;
      bool fstr = false;
      bool bytes = false;
      while (k < src_.size() && k - at_ < 2) {
        char p = static_cast<char>(src_[k] | 0x20);
        if (p == 'r' && !raw) {
          raw = true;
        } else if (p == 'f' && !fstr && !bytes) {
          fstr = true;
        } else if (p == 'b' && !bytes && !fstr) {
          bytes = true;
        } else if (p == 'u' && k == at_) {
          // u'' is a plain string
        } else {
          break;
        }
        ++k;
      }
      if (k > at_ && k < src_.size() && (src_[k] == '\'' || src_[k] == '"')) {
        return lexString(k - at_, raw, fstr);
      }
      return lexName();
    }
    if (c == '\'' || c == '"') {
      return lexString(0, false, false);
    }
    return lexOperator();
  }
}

} // namespace stella
