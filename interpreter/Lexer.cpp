// The command-language lexer: Python's tokenizer rules for the subset command files use.
#include "Lexer.hpp"

#include <array>
#include <charconv>
#include <unordered_map>

namespace stella {

namespace {

bool isNameStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}
bool isNameChar(char c) {
  return isNameStart(c) || (c >= '0' && c <= '9');
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

const std::unordered_map<std::string_view, TokenKind>& keywords() {
  static const std::unordered_map<std::string_view, TokenKind> table = {
      {"and", TokenKind::KwAnd},
      {"as", TokenKind::KwAs},
      {"assert", TokenKind::KwAssert},
      {"break", TokenKind::KwBreak},
      {"class", TokenKind::KwClass},
      {"continue", TokenKind::KwContinue},
      {"def", TokenKind::KwDef},
      {"del", TokenKind::KwDel},
      {"elif", TokenKind::KwElif},
      {"else", TokenKind::KwElse},
      {"except", TokenKind::KwExcept},
      {"False", TokenKind::KwFalse},
      {"finally", TokenKind::KwFinally},
      {"for", TokenKind::KwFor},
      {"from", TokenKind::KwFrom},
      {"global", TokenKind::KwGlobal},
      {"if", TokenKind::KwIf},
      {"import", TokenKind::KwImport},
      {"in", TokenKind::KwIn},
      {"is", TokenKind::KwIs},
      {"lambda", TokenKind::KwLambda},
      {"None", TokenKind::KwNone},
      {"nonlocal", TokenKind::KwNonlocal},
      {"not", TokenKind::KwNot},
      {"or", TokenKind::KwOr},
      {"pass", TokenKind::KwPass},
      {"raise", TokenKind::KwRaise},
      {"return", TokenKind::KwReturn},
      {"True", TokenKind::KwTrue},
      {"try", TokenKind::KwTry},
      {"while", TokenKind::KwWhile},
      {"with", TokenKind::KwWith},
      {"yield", TokenKind::KwYield},
  };
  return table;
}

struct OperatorSpelling {
  std::string_view text;
  TokenKind kind;
};

// Longest first, so that the first match is the longest.
constexpr std::array<OperatorSpelling, 47> operatorTable = {{
    {"**=", TokenKind::DoubleStarAssign},
    {"//=", TokenKind::DoubleSlashAssign},
    {"...", TokenKind::Ellipsis},
    {"<<=", TokenKind::Error},
    {">>=", TokenKind::Error},
    {"**", TokenKind::DoubleStar},
    {"//", TokenKind::DoubleSlash},
    {"==", TokenKind::EqualEqual},
    {"!=", TokenKind::NotEqual},
    {"<>", TokenKind::Error},
    {"<=", TokenKind::LessEqual},
    {">=", TokenKind::GreaterEqual},
    {"+=", TokenKind::PlusAssign},
    {"-=", TokenKind::MinusAssign},
    {"*=", TokenKind::StarAssign},
    {"/=", TokenKind::SlashAssign},
    {"%=", TokenKind::PercentAssign},
    {"&=", TokenKind::Error},
    {"|=", TokenKind::Error},
    {"^=", TokenKind::Error},
    {"->", TokenKind::Arrow},
    {"<<", TokenKind::LeftShift},
    {">>", TokenKind::RightShift},
    {":=", TokenKind::Walrus},
    {"(", TokenKind::LParen},
    {")", TokenKind::RParen},
    {"[", TokenKind::LBracket},
    {"]", TokenKind::RBracket},
    {"{", TokenKind::LBrace},
    {"}", TokenKind::RBrace},
    {",", TokenKind::Comma},
    {":", TokenKind::Colon},
    {";", TokenKind::Semicolon},
    {".", TokenKind::Dot},
    {"+", TokenKind::Plus},
    {"-", TokenKind::Minus},
    {"*", TokenKind::Star},
    {"/", TokenKind::Slash},
    {"%", TokenKind::Percent},
    {"@", TokenKind::At},
    {"&", TokenKind::Ampersand},
    {"|", TokenKind::Pipe},
    {"^", TokenKind::Caret},
    {"~", TokenKind::Tilde},
    {"<", TokenKind::Less},
    {">", TokenKind::Greater},
    {"=", TokenKind::Assign},
}};

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | ((code >> 18) & 0x07));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') {
    return c - '0';
  }
  if (c >= 'a' && c <= 'f') {
    return c - 'a' + 10;
  }
  if (c >= 'A' && c <= 'F') {
    return c - 'A' + 10;
  }
  return -1;
}

} // namespace

// Decodes the escapes of a (non-raw) string body, Python's rules; unknown escapes are kept.
std::string decodeEscapes(std::string_view body) {
  std::string out;
  out.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    char c = body[i];
    if (c != '\\' || i + 1 >= body.size()) {
      out += c;
      continue;
    }
    char e = body[++i];
    switch (e) {
    case '\n':
      break;
    case '\r':
      if (i + 1 < body.size() && body[i + 1] == '\n') {
        ++i;
      }
      break;
    case '\\':
    case '\'':
    case '"':
      out += e;
      break;
    case 'n':
      out += '\n';
      break;
    case 't':
      out += '\t';
      break;
    case 'r':
      out += '\r';
      break;
    case 'a':
      out += '\a';
      break;
    case 'b':
      out += '\b';
      break;
    case 'f':
      out += '\f';
      break;
    case 'v':
      out += '\v';
      break;
    case 'x':
    case 'u':
    case 'U': {
      std::size_t digits = e == 'x' ? 2 : (e == 'u' ? 4 : 8);
      std::uint32_t code = 0;
      std::size_t k = 0;
      for (; k < digits && i + 1 + k < body.size() && hexDigit(body[i + 1 + k]) >= 0; ++k) {
        code = code * 16 + static_cast<std::uint32_t>(hexDigit(body[i + 1 + k]));
      }
      if (k == digits && code <= 0x10FFFF) {
        appendUtf8(out, code);
        i += digits;
      } else {
        out += '\\';
        out += e;
      }
      break;
    }
    default:
      if (e >= '0' && e <= '7') {
        std::uint32_t code = 0;
        std::size_t k = 0;
        for (; k < 3 && i + k < body.size() && body[i + k] >= '0' && body[i + k] <= '7'; ++k) {
          code = code * 8 + static_cast<std::uint32_t>(body[i + k] - '0');
        }
        appendUtf8(out, code);
        i += k - 1;
      } else {
        out += '\\';
        out += e;
      }
    }
  }
  return out;
}

Lexer::Lexer(std::shared_ptr<const SourceFile> file, bool expressionMode)
    : file_(std::move(file)), src_(file_->text()), expressionMode_(expressionMode) {
  if (src_.size() >= 3 && src_.substr(0, 3) == "\xEF\xBB\xBF") {
    at_ = 3; // UTF-8 byte order mark
    lineStart_ = 3;
  }
}

Lexer::Lexer(std::shared_ptr<const SourceFile> file, std::string_view text, int firstLine, int firstColumn)
    : file_(std::move(file)), src_(text), line_(firstLine), firstColumn_(firstColumn), expressionMode_(true) {
}

SourceLocation Lexer::location(const Pos& pos) const {
  return SourceLocation{file_, pos.line, pos.column, pos.length};
}

void Lexer::error(const std::string& id, const std::string& message, Pos at, const std::string& note) {
  Diagnostic d = Diagnostic::syntax(id, message, location(at));
  if (!note.empty()) {
    d.withNote(note);
  }
  errors_.push_back(std::move(d));
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
        error("SYNTAX_4", "unindent does not match any outer indentation level", indentPos_,
              "indent this line like one of the blocks that contain it");
      } else {
        error("SYNTAX_5", "inconsistent use of tabs and spaces in indentation", indentPos_,
              "indent with spaces only: tabs mixed with spaces are refused because their width is ambiguous");
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
        error("SYNTAX_8", std::string("'") + b.open + "' was never closed", b.pos,
              "add the matching closing bracket");
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
      error("SYNTAX_17", "a backslash outside a string must end the line (line continuation)",
            posOf(at_, at_ + 1));
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
          error("SYNTAX_8", std::string("'") + b.open + "' was never closed", b.pos,
                "add the matching closing bracket before line " + std::to_string(line_));
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
    error("SYNTAX_9", "invalid number literal '" + std::string(t.text) + "'", t.pos,
          "numbers are written like 1, 1., .5, 2.1e5, 1.E-6");
    t.kind = TokenKind::Int;
    return t;
  }
  if (real || imaginary) {
    t.kind = imaginary ? TokenKind::Imaginary : TokenKind::Real;
    std::from_chars(digits.data(), digits.data() + digits.size(), t.realValue);
    if (digits == ".") {
      t.realValue = 0.0;
    }
    return t;
  }
  auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), t.intValue, base);
  if (ec != std::errc() || ptr != digits.data() + digits.size()) {
    error("SYNTAX_9", "integer literal '" + std::string(t.text) + "' is too large", t.pos,
          "integers are limited to 64 bits; write it as a real number (e.g. 1.e20)");
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
    error("SYNTAX_2", triple ? "unterminated triple-quoted string" : "unterminated string", startPos,
          triple ? "close it with three quotes of the same kind"
                 : "close the string with the same quote on the same line, or use triple quotes for several "
                   "lines");
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
    t.value = raw ? "r" : "";
  }
  return t;
}

Token Lexer::lexOperator() {
  std::string_view rest = src_.substr(at_, 3);
  char first = rest[0];
  for (const auto& op : operatorTable) {
    if (op.text[0] == first && rest.substr(0, op.text.size()) == op.text) {
      std::size_t begin = at_;
      at_ += op.text.size();
      Token t = makeToken(op.kind, begin, at_);
      if (op.kind == TokenKind::Error) {
        error("SYNTAX_3", "operator '" + std::string(op.text) + "' is not part of the command language",
              t.pos);
        return t;
      }
      char c = op.text[0];
      if (c == '(' || c == '[' || c == '{') {
        brackets_.push_back({c, t.pos});
      } else if (c == ')' || c == ']' || c == '}') {
        char open = c == ')' ? '(' : (c == ']' ? '[' : '{');
        if (!brackets_.empty()) {
          if (brackets_.back().open != open) {
            error("SYNTAX_8",
                  std::string("closing '") + c + "' does not match the '" + brackets_.back().open +
                      "' opened at line " + std::to_string(brackets_.back().pos.line),
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
  error("SYNTAX_3", "invalid character '" + shown + "'", t.pos);
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

std::string tokenKindName(TokenKind kind) {
  switch (kind) {
  case TokenKind::EndOfFile:
    return "end of file";
  case TokenKind::Newline:
    return "end of line";
  case TokenKind::Indent:
    return "indent";
  case TokenKind::Dedent:
    return "dedent";
  case TokenKind::Name:
    return "name";
  case TokenKind::Int:
    return "integer";
  case TokenKind::Real:
    return "real number";
  case TokenKind::Imaginary:
    return "imaginary number";
  case TokenKind::String:
    return "string";
  case TokenKind::Error:
    return "invalid character";
  default:
    break;
  }
  for (const auto& [text, k] : keywords()) {
    if (k == kind) {
      return "'" + std::string(text) + "'";
    }
  }
  for (const auto& op : operatorTable) {
    if (op.kind == kind) {
      return "'" + std::string(op.text) + "'";
    }
  }
  return "token";
}

std::string describeToken(const Token& token) {
  switch (token.kind) {
  case TokenKind::Name:
    return "name '" + std::string(token.text) + "'";
  case TokenKind::Int:
  case TokenKind::Real:
  case TokenKind::Imaginary:
    return "number '" + std::string(token.text) + "'";
  case TokenKind::String:
    return "a string";
  default:
    return tokenKindName(token.kind);
  }
}

} // namespace stella
