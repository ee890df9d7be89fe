// Developer views of a command file: syntax check, token dump, tree dump, pretty-printing.
#include "Formatter.hpp"
#include "Interpreter.hpp"
#include "Lexer.hpp"
#include "Parser.hpp"

#include <fmt/format.h>

namespace stella {

bool checkSyntax(const std::shared_ptr<const SourceFile>& file, DiagnosticSink& sink) {
  ParseResult result = parseFile(file);
  for (const auto& d : result.errors) {
    sink.report(d);
  }
  return result.errors.empty();
}

std::string dumpTokens(const std::shared_ptr<const SourceFile>& file) {
  Lexer lexer(file);
  std::string out;
  for (;;) {
    Token t = lexer.next();
    out += fmt::format("{}:{} {}", t.pos.line, t.pos.column, tokenKindName(t.kind));
    if (t.kind == TokenKind::Name || t.kind == TokenKind::Int || t.kind == TokenKind::Real ||
        t.kind == TokenKind::Imaginary || t.kind == TokenKind::String) {
      out += " " + std::string(t.text);
    }
    out += '\n';
    if (t.kind == TokenKind::EndOfFile) {
      break;
    }
  }
  for (const auto& d : lexer.errors()) {
    out += formatDiagnostic(d);
  }
  return out;
}

std::string dumpAst(const std::shared_ptr<const SourceFile>& file) {
  ParseResult result = parseFile(file);
  std::string out = dumpModule(*result.module, true);
  for (const auto& d : result.errors) {
    out += formatDiagnostic(d);
  }
  return out;
}

std::string formatSource(const std::shared_ptr<const SourceFile>& file) {
  ParseResult result = parseFile(file, true);
  if (!result.errors.empty()) {
    throw UserError(std::move(result.errors));
  }
  return formatModule(*result.module, result.comments);
}

} // namespace stella
