// Text dumps of the syntax tree (`--dump-ast`, round-trip checks) and operator spellings.
#include "Ast.hpp"

#include <fmt/format.h>

namespace stella {

const char* binaryOpText(BinaryOp op) {
  static const char* const texts[] = {"+", "-", "*", "/", "//", "%", "**", "&", "|", "^", "<<", ">>"};
  return texts[static_cast<int>(op)];
}

const char* unaryOpText(UnaryOp op) {
  static const char* const texts[] = {"-", "+", "~"};
  return texts[static_cast<int>(op)];
}

const char* compareOpText(CompareOp op) {
  static const char* const texts[] = {"<", ">", "<=", ">=", "==", "!=", "in", "not in", "is", "is not"};
  return texts[static_cast<int>(op)];
}

int binaryPrecedence(BinaryOp op) {
  switch (op) {
  case BinaryOp::BitOr:
    return 1;
  case BinaryOp::BitXor:
    return 2;
  case BinaryOp::BitAnd:
    return 3;
  case BinaryOp::LShift:
  case BinaryOp::RShift:
    return 4;
  case BinaryOp::Add:
  case BinaryOp::Sub:
    return 5;
  case BinaryOp::Mul:
  case BinaryOp::Div:
  case BinaryOp::FloorDiv:
  case BinaryOp::Mod:
    return 6;
  case BinaryOp::Pow:
    return 8;
  }
  return 0;
}

namespace {

const char* exprKindName(ExprKind k) {
  static const char* const names[] = {
      "Name",   "Int",        "Real",      "Imaginary", "String", "FString",     "Formatted", "None",
      "True",   "False",      "Tuple",     "List",      "Dict",   "ListComp",    "CompFor",   "Unary",
      "Binary", "Compare",    "And",       "Or",        "Not",    "Conditional", "Call",      "Keyword",
      "Star",   "DoubleStar", "Attribute", "Subscript", "Slice",  "Lambda"};
  return names[static_cast<int>(k)];
}

const char* stmtKindName(StmtKind k) {
  static const char* const names[] = {"Expr",   "Assign", "AugAssign",     "For",        "While",
                                      "If",     "Pass",   "Break",         "Continue",   "Del",
                                      "Def",    "Return", "Import",        "FromImport", "Global",
                                      "Assert", "Try",    "ExceptHandler", "Raise"};
  return names[static_cast<int>(k)];
}

struct Dumper {
  bool withLocations;
  std::string out;

  void line(int indent, const std::string& text, const Pos& pos) {
    out.append(static_cast<std::size_t>(indent) * 2, ' ');
    out += text;
    if (withLocations) {
      out += fmt::format(" @{}:{}", pos.line, pos.column);
    }
    out += '\n';
  }

  void expr(const Expr* e, int indent) {
    if (e == nullptr) {
      out.append(static_cast<std::size_t>(indent) * 2, ' ');
      out += "<empty>\n";
      return;
    }
    std::string text = exprKindName(e->kind);
    switch (e->kind) {
    case ExprKind::Name:
    case ExprKind::Attribute:
    case ExprKind::Keyword:
      text += " " + e->text;
      break;
    case ExprKind::Int:
      text += " " + std::to_string(e->intValue);
      break;
    case ExprKind::Real:
    case ExprKind::Imaginary:
      text += fmt::format(" {}", e->realValue);
      break;
    case ExprKind::String:
      text += " " + Value(e->text).repr();
      break;
    case ExprKind::FormattedValue:
      if (e->op != 0) {
        text += std::string(" !") + static_cast<char>(e->op);
      }
      if (!e->text.empty()) {
        text += " :" + e->text;
      }
      break;
    case ExprKind::Unary:
      text += std::string(" ") + unaryOpText(static_cast<UnaryOp>(e->op));
      break;
    case ExprKind::Binary:
      text += std::string(" ") + binaryOpText(static_cast<BinaryOp>(e->op));
      break;
    case ExprKind::Compare:
      for (std::size_t i = 0; i < e->compareCount(); ++i) {
        text += std::string(" '") + compareOpText(e->compareOp(i)) + "'";
      }
      break;
    default:
      break;
    }
    line(indent, text, e->pos);
    for (const auto& c : e->items) {
      expr(c.get(), indent + 1);
    }
  }

  void block(const char* label, const std::vector<StmtPtr>& body, int indent) {
    out.append(static_cast<std::size_t>(indent) * 2, ' ');
    out += label;
    out += '\n';
    for (const auto& s : body) {
      stmt(*s, indent + 1);
    }
  }

  void stmt(const Stmt& s, int indent) {
    std::string text = stmtKindName(s.kind);
    if (s.kind == StmtKind::AugAssign) {
      text += std::string(" ") + binaryOpText(static_cast<BinaryOp>(s.op)) + "=";
    }
    if (!s.name.empty()) {
      text += " " + s.name;
    }
    for (const auto& p : s.params) {
      text += " " + std::string(p.star == 1 ? "*" : (p.star == 2 ? "**" : "")) + p.name +
              (p.defaultValue ? "=" : "");
    }
    for (const auto& in : s.imports) {
      if (!in.name.empty()) {
        text += " " + in.name + (in.alias.empty() ? "" : " as " + in.alias);
      }
    }
    line(indent, text, s.pos);
    for (const auto& p : s.params) {
      if (p.defaultValue) {
        expr(p.defaultValue.get(), indent + 1);
      }
    }
    for (const auto& e : s.exprs) {
      expr(e.get(), indent + 1);
    }
    if (!s.body.empty()) {
      block("body", s.body, indent + 1);
    }
    if (!s.handlers.empty()) {
      block("handlers", s.handlers, indent + 1);
    }
    if (!s.orelse.empty()) {
      block("else", s.orelse, indent + 1);
    }
    if (!s.finalbody.empty()) {
      block("finally", s.finalbody, indent + 1);
    }
  }
};

} // namespace

std::string dumpModule(const Module& module, bool withLocations) {
  Dumper d{withLocations, {}};
  d.out = "Module\n";
  for (const auto& s : module.body) {
    d.stmt(*s, 1);
  }
  return d.out;
}

std::string dumpExpr(const Expr& expr, bool withLocations) {
  Dumper d{withLocations, {}};
  d.expr(&expr, 0);
  return d.out;
}

} // namespace stella
