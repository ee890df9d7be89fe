#pragma once
// The tokens of the command language, with their place in the file.

#include <cstdint>
#include <string>
#include <string_view>

namespace stella {

// A compact place in the file being read (the SourceFile is known from context): 1-based line
// and byte column, and how many bytes to underline.
struct Pos {
  int line = 0;
  int column = 0;
  int length = 1;
};

enum class TokenKind : std::uint8_t {
  EndOfFile,
  Newline,
  Indent,
  Dedent,
  Name,
  Int,
  Real,
  Imaginary,
  String,
  // keywords
  KwAnd,
  KwAs,
  KwAssert,
  KwBreak,
  KwClass,
  KwContinue,
  KwDef,
  KwDel,
  KwElif,
  KwElse,
  KwExcept,
  KwFalse,
  KwFinally,
  KwFor,
  KwFrom,
  KwGlobal,
  KwIf,
  KwImport,
  KwIn,
  KwIs,
  KwLambda,
  KwNone,
  KwNonlocal,
  KwNot,
  KwOr,
  KwPass,
  KwRaise,
  KwReturn,
  KwTrue,
  KwTry,
  KwWhile,
  KwWith,
  KwYield,
  // operators and delimiters
  LParen,
  RParen,
  LBracket,
  RBracket,
  LBrace,
  RBrace,
  Comma,
  Colon,
  Semicolon,
  Dot,
  Plus,
  Minus,
  Star,
  DoubleStar,
  Slash,
  DoubleSlash,
  Percent,
  At,
  Ampersand,
  Pipe,
  Caret,
  Tilde,
  LeftShift,
  RightShift,
  Less,
  Greater,
  LessEqual,
  GreaterEqual,
  EqualEqual,
  NotEqual,
  Assign,
  PlusAssign,
  MinusAssign,
  StarAssign,
  SlashAssign,
  DoubleSlashAssign,
  PercentAssign,
  DoubleStarAssign,
  Arrow,
  Walrus,
  Ellipsis,
  Error // a character that starts no token (already reported)
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  Pos pos;
  std::string_view text; // the source text of the token (for strings: including the quotes)
  std::string value;     // a string token's decoded content (an f-string's raw content)
  std::int64_t intValue = 0;
  double realValue = 0.0;
  bool fString = false;
  bool lineStart = false; // first token of a physical line
  bool recovered = false; // a NEWLINE made by the lexer after an unclosed bracket (already reported)
  int contentColumn = 0;  // string tokens: column of the first content character
};

// "NAME", "'('", "end of file"... for messages and token dumps.
std::string tokenKindName(TokenKind kind);
// How a token is shown in "expected X, found Y" messages.
std::string describeToken(const Token& token);

} // namespace stella
