#pragma once
// Turns a command file into tokens on demand: Python's rules for indentation (INDENT/DEDENT),
// implicit line joining inside brackets, backslash continuation, string and number forms.
// Lexical errors are collected (the lexer goes on after each) so that all are reported at once.

#include "Diagnostics.hpp"
#include "Token.hpp"
#include "messages/Messages.hpp"

#include <memory>
#include <string>
#include <vector>

namespace stella {

// Decodes the escapes of a non-raw string body with Python's rules (unknown escapes are kept).
std::string decodeEscapes(std::string_view body);

// A comment seen by the lexer (kept for the pretty-printer).
struct Comment {
  int line;
  bool ownLine; // alone on its line (not after code)
  std::string_view text;
};

class Lexer {
public:
  // `firstLine`/`firstColumn` place text that is part of a larger file (an f-string's
  // expression); `expressionMode` lexes a bare expression (no INDENT, newlines are blanks).
  explicit Lexer(std::shared_ptr<const SourceFile> file, bool expressionMode = false);
  Lexer(std::shared_ptr<const SourceFile> file, std::string_view text, int firstLine, int firstColumn);

  Token next();

  std::vector<Diagnostic>& errors() { return errors_; }
  const std::shared_ptr<const SourceFile>& file() const { return file_; }
  SourceLocation location(const Pos& pos) const;
  // Records the comments read (off by default).
  void keepComments(std::vector<Comment>* into) { comments_ = into; }

private:
  Token nextToken();
  void startLine();
  bool skipBlankAndComments();
  Token makeToken(TokenKind kind, std::size_t begin, std::size_t end);
  Token lexName();
  Token lexNumber();
  Token lexString(std::size_t prefixLength, bool raw, bool fString);
  Token lexOperator();
  // Records catalogue entry `key` (messages/language.msg) with `args`, at `at`.
  void error(std::string_view key, msg::Args args, Pos at);
  void checkEncoding();
  int column(std::size_t offset) const { return static_cast<int>(offset - lineStart_) + firstColumn_; }
  Pos posOf(std::size_t begin, std::size_t end) const;
  void newline(std::size_t offsetAfter);
  bool bracketNeverCloses(std::size_t from);
  bool looksLikeNewStatement() const;

  std::shared_ptr<const SourceFile> file_;
  std::string_view src_;
  std::size_t at_ = 0;
  std::size_t lineStart_ = 0;
  int line_ = 1;
  int firstColumn_ = 1;
  bool expressionMode_ = false;
  bool atLogicalLineStart_ = true;
  bool lineHasTokens_ = false;
  bool physicalLineStart_ = true;
  int pendingDedents_ = 0;
  bool pendingIndent_ = false;
  bool finished_ = false;
  std::vector<std::string> indents_{""};
  struct Bracket {
    char open;
    Pos pos;
  };
  std::vector<Bracket> brackets_;
  std::vector<Diagnostic> errors_;
  Pos indentPos_;
  std::vector<Comment>* comments_ = nullptr;
  TokenKind lastKind_ = TokenKind::Newline; // last significant token returned
  std::size_t knownCloseAt_ = 0;
  int unterminatedStringLine_ = 0; // the open brackets are known to close at this offset
};

} // namespace stella
