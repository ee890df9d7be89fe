#pragma once
// Hand-written recursive-descent parser for the command language. It keeps a location on every
// node, resynchronises at the next statement after a syntax error and reports every error of
// the file in one pass; nesting is capped so that no input can exhaust the stack.

#include "Ast.hpp"
#include "Diagnostics.hpp"
#include "Lexer.hpp"

#include <memory>
#include <vector>

namespace stella {

// Bracket/block/unary nesting allowed while parsing, and height allowed for any tree.
inline constexpr int maxParseNesting = 200;
inline constexpr int maxTreeDepth = 1000;

struct ParseResult {
  std::shared_ptr<Module> module;
  std::vector<Diagnostic> errors; // lexical and syntax errors, in file order
  std::vector<Comment> comments;  // when asked for
};

// Parses a whole file.
ParseResult parseFile(const std::shared_ptr<const SourceFile>& file, bool keepComments = false);

// Parses a file holding one expression (FORMULE bodies, block conditions); newlines inside are
// blanks. On success `module->body` holds one Expr statement.
ParseResult parseExpressionFile(const std::shared_ptr<const SourceFile>& file);

// `FIN()` as a statement.
bool isFinStatement(const Stmt& s);
// True when every syntax error lies after a top-level `FIN()` (the text after FIN is ignored).
bool errorsOnlyAfterFin(const ParseResult& r);

} // namespace stella
