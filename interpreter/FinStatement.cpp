// The statement FIN() ends a command file: the text after it is ignored, even when it does
// not parse. Shared by the interpreter and the language test runner.
#include "Parser.hpp"

#include <algorithm>

namespace stella {

bool isFinStatement(const Stmt& s) {
  if (s.kind != StmtKind::Expr || s.exprs.empty()) {
    return false;
  }
  const Expr& e = *s.exprs[0];
  return e.kind == ExprKind::Call && e.items[0]->kind == ExprKind::Name && e.items[0]->text == "FIN";
}

// True when every syntax error lies after a top-level `FIN()`: the text after FIN is ignored.
bool errorsOnlyAfterFin(const ParseResult& r) {
  int finLine = 0;
  for (const auto& s : r.module->body) {
    if (isFinStatement(*s)) {
      finLine = std::max(s->endLine, s->pos.line);
      break;
    }
  }
  if (finLine == 0) {
    return false;
  }
  for (const auto& d : r.errors) {
    if (d.location.line <= finLine) {
      return false;
    }
  }
  return true;
}

} // namespace stella
