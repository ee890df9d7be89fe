#pragma once
// Internal to the lexer's source files (Lexer*.cpp, TokenNames.cpp): character classes, the
// keyword table and the operator spellings.

#include "Token.hpp"

#include <array>
#include <string_view>
#include <unordered_map>

namespace stella::lexing {

inline bool isNameStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}
inline bool isNameChar(char c) {
  return isNameStart(c) || (c >= '0' && c <= '9');
}
inline bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

inline int hexDigit(char c) {
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

// Reserved words, by spelling.
const std::unordered_map<std::string_view, TokenKind>& keywords();

struct OperatorSpelling {
  std::string_view text;
  TokenKind kind;
};

// Longest first, so that the first match is the longest.
inline constexpr std::array<OperatorSpelling, 47> operatorTable = {{
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

} // namespace stella::lexing
