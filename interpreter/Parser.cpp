// Recursive-descent parser of the command language (the part of Python that command files use).
// Each function states the grammar rule it parses; the rules are in ParserStatements.cpp,
// ParserExpressions.cpp, ParserAtoms.cpp and ParserStrings.cpp. A syntax error throws
// ParseError, caught at the statement level, which records it and skips to the next statement.
// This file: tree-height checks, resynchronisation and the entry points.
#include "ParserClass.hpp"

#include <algorithm>

namespace stella::parsing {

ExprPtr Parser::finish(ExprPtr e) {
  int depth = 0;
  for (const auto& c : e->items) {
    if (c) {
      depth = std::max(depth, c->depth);
    }
  }
  e->depth = depth + 1;
  if (e->depth > maxTreeDepth) {
    failAt(e->pos, "SYNTAX_10", {{"max_tree_depth", std::to_string(maxTreeDepth)}});
  }
  return e;
}

// After an error: skip to the end of the current logical line.
void Parser::synchronize() {
  while (!at(TokenKind::EndOfFile)) {
    if (at(TokenKind::Newline)) {
      advance();
      return;
    }
    if (at(TokenKind::Indent) || at(TokenKind::Dedent)) {
      return;
    }
    advance();
  }
}

// A whole input holding one expression (f-string fields, FORMULE bodies).
ExprPtr Parser::parseStandaloneExpression() {
  ExprPtr e = parseTestList();
  if (!at(TokenKind::EndOfFile)) {
    fail("SYNTAX_1.3", {{"describe_token", describeToken(cur_)}});
  }
  return e;
}

} // namespace stella::parsing

namespace stella {

using parsing::ParseError;
using parsing::Parser;

namespace {

void sortErrors(std::vector<Diagnostic>& errors) {
  std::stable_sort(errors.begin(), errors.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.location.line != b.location.line) {
      return a.location.line < b.location.line;
    }
    return a.location.column < b.location.column;
  });
}

} // namespace

ParseResult parseFile(const std::shared_ptr<const SourceFile>& file, bool keepComments) {
  ParseResult result;
  Lexer lexer(file);
  if (keepComments) {
    lexer.keepComments(&result.comments);
  }
  result.module = std::make_shared<Module>();
  result.module->file = file;
  Parser parser(lexer, 0, result.module->arena.get());
  result.module->body = parser.parseFileInput();
  result.errors = std::move(lexer.errors());
  for (auto& d : parser.errors()) {
    result.errors.push_back(std::move(d));
  }
  sortErrors(result.errors);
  return result;
}

ParseResult parseExpressionFile(const std::shared_ptr<const SourceFile>& file) {
  ParseResult result;
  Lexer lexer(file, true);
  result.module = std::make_shared<Module>();
  result.module->file = file;
  try {
    Parser parser(lexer, 0, result.module->arena.get());
    try {
      ExprPtr e = parser.parseStandaloneExpression();
      auto s = std::make_unique<Stmt>(StmtKind::Expr, e->pos);
      s->exprs.push_back(std::move(e));
      result.module->body.push_back(std::move(s));
    } catch (const ParseError&) {
    }
    result.errors = std::move(lexer.errors());
    for (auto& d : parser.errors()) {
      result.errors.push_back(std::move(d));
    }
  } catch (const ParseError&) {
    result.errors = std::move(lexer.errors());
  }
  sortErrors(result.errors);
  return result;
}

} // namespace stella
