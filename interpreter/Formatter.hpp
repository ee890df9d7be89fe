#pragma once
// The pretty-printer behind formatSource (`stella fmt`).

#include "Ast.hpp"
#include "Lexer.hpp"

#include <string>
#include <vector>

namespace stella {

// Source text of a parsed module; `comments` (from parseFile(..., true)) are put back in place.
std::string formatModule(const Module& module, const std::vector<Comment>& comments);
// One expression on one line (used in messages, e.g. a while loop's condition).
std::string formatExpression(const Expr& expr);

} // namespace stella
