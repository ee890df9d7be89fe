// Names of tokens in messages ("end of line", "name 'X'").
#include "Lexer.hpp"
#include "LexerTables.hpp"

namespace stella {

using namespace lexing;

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
