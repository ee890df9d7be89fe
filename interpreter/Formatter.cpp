// The pretty-printer (`stella fmt`): prints a parsed command file back as source, keeping its
// comments and blank-line groups, breaking long command calls one keyword per line aligned
// after the '(' as code_aster users write them. Its output re-parses to the same tree.
#include "Formatter.hpp"
#include "SourceEncoding.hpp"
#include "StringEscape.hpp"

#include "Parser.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

constexpr std::size_t lineWidth = 100;

// Precedence levels used to decide where parentheses are needed (higher binds tighter).
enum Level : int {
  LambdaLevel = 0,
  ConditionalLevel = 1,
  OrLevel = 2,
  AndLevel = 3,
  NotLevel = 4,
  CompareLevel = 5,
  UnaryLevel = 12,
  PowerLevel = 13,
  PrimaryLevel = 14,
  AtomLevel = 15
};

int levelOf(const Expr& e) {
  switch (e.kind) {
  case ExprKind::Lambda:
    return LambdaLevel;
  case ExprKind::Conditional:
    return ConditionalLevel;
  case ExprKind::Or:
    return OrLevel;
  case ExprKind::And:
    return AndLevel;
  case ExprKind::Not:
    return NotLevel;
  case ExprKind::Compare:
    return CompareLevel;
  case ExprKind::Binary: {
    auto op = static_cast<BinaryOp>(e.op);
    return op == BinaryOp::Pow ? PowerLevel : 5 + binaryPrecedence(op);
  }
  case ExprKind::Unary:
    return UnaryLevel;
  case ExprKind::Call:
  case ExprKind::Subscript:
  case ExprKind::Attribute:
    return PrimaryLevel;
  default:
    return AtomLevel;
  }
}

std::string realText(double d) {
  if (std::isinf(d)) {
    return "1e999";
  }
  return Value(d).repr();
}

std::string fstringText(const Expr& e);

std::string exprText(const Expr& e, int minLevel = 0, bool bareTuple = false);

std::string callText(const Expr& e) {
  std::string out = exprText(*e.items[0], PrimaryLevel) + "(";
  for (std::size_t i = 1; i < e.items.size(); ++i) {
    if (i > 1) {
      out += ", ";
    }
    out += exprText(*e.items[i]);
  }
  return out + ")";
}

std::string sliceText(const Expr& e) {
  if (e.kind != ExprKind::Slice) {
    return exprText(e);
  }
  std::string out;
  if (e.items[0]) {
    out += exprText(*e.items[0]);
  }
  out += ":";
  if (e.items[1]) {
    out += exprText(*e.items[1]);
  }
  if (e.items[2]) {
    out += ":" + exprText(*e.items[2]);
  }
  return out;
}

std::string sequenceText(const Expr& e, const char* open, const char* close, bool tuple) {
  std::string out = open;
  for (std::size_t i = 0; i < e.items.size(); ++i) {
    if (i > 0) {
      out += ", ";
    }
    out += exprText(*e.items[i]);
  }
  if (tuple && e.items.size() == 1) {
    out += ",";
  }
  return out + close;
}

std::string exprText(const Expr& e, int minLevel, bool bareTuple) {
  std::string out;
  switch (e.kind) {
  case ExprKind::Name:
    out = e.text;
    break;
  case ExprKind::Int:
    out = std::to_string(e.intValue);
    break;
  case ExprKind::Real:
    out = realText(e.realValue);
    break;
  case ExprKind::Imaginary:
    out = realText(e.realValue) + "j";
    break;
  case ExprKind::String:
    out = Value(e.text).repr();
    break;
  case ExprKind::FString:
    out = fstringText(e);
    break;
  case ExprKind::None:
    out = "None";
    break;
  case ExprKind::True:
    out = "True";
    break;
  case ExprKind::False:
    out = "False";
    break;
  case ExprKind::Tuple:
    if (bareTuple && !e.items.empty()) {
      out = sequenceText(e, "", "", true);
    } else {
      out = sequenceText(e, "(", ")", true);
    }
    break;
  case ExprKind::List:
    out = sequenceText(e, "[", "]", false);
    break;
  case ExprKind::Dict:
    out = "{";
    for (std::size_t i = 0; i + 1 < e.items.size(); i += 2) {
      if (i > 0) {
        out += ", ";
      }
      if (e.items[i]) {
        out += exprText(*e.items[i]) + ": " + exprText(*e.items[i + 1]);
      } else {
        out += "**" + exprText(*e.items[i + 1], 6);
      }
    }
    out += "}";
    break;
  case ExprKind::ListComp:
    out = "[" + exprText(*e.items[0]);
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      const Expr& c = *e.items[i];
      out += " for " + exprText(*c.items[0], 6, true) + " in " + exprText(*c.items[1], OrLevel);
      for (std::size_t k = 2; k < c.items.size(); ++k) {
        out += " if " + exprText(*c.items[k], OrLevel);
      }
    }
    out += "]";
    break;
  case ExprKind::Unary:
    out = std::string(unaryOpText(static_cast<UnaryOp>(e.op))) + exprText(*e.items[0], UnaryLevel);
    break;
  case ExprKind::Binary: {
    auto op = static_cast<BinaryOp>(e.op);
    int level = levelOf(e);
    if (op == BinaryOp::Pow) {
      out = exprText(*e.items[0], PrimaryLevel) + "**" + exprText(*e.items[1], UnaryLevel);
    } else {
      out = exprText(*e.items[0], level) + " " + binaryOpText(op) + " " + exprText(*e.items[1], level + 1);
    }
    break;
  }
  case ExprKind::Compare:
    out = exprText(*e.items[0], CompareLevel + 1);
    for (std::size_t i = 0; i < e.compareCount(); ++i) {
      out += std::string(" ") + compareOpText(e.compareOp(i)) + " " +
             exprText(*e.items[i + 1], CompareLevel + 1);
    }
    break;
  case ExprKind::And:
  case ExprKind::Or: {
    bool isAnd = e.kind == ExprKind::And;
    for (std::size_t i = 0; i < e.items.size(); ++i) {
      if (i > 0) {
        out += isAnd ? " and " : " or ";
      }
      out += exprText(*e.items[i], (isAnd ? AndLevel : OrLevel) + 1);
    }
    break;
  }
  case ExprKind::Not:
    out = "not " + exprText(*e.items[0], NotLevel);
    break;
  case ExprKind::Conditional:
    out = exprText(*e.items[0], OrLevel) + " if " + exprText(*e.items[1], OrLevel) + " else " +
          exprText(*e.items[2], ConditionalLevel);
    break;
  case ExprKind::Call:
    out = callText(e);
    break;
  case ExprKind::Keyword:
    out = e.text + "=" + exprText(*e.items[0]);
    break;
  case ExprKind::Star:
    out = "*" + exprText(*e.items[0]);
    break;
  case ExprKind::DoubleStar:
    out = "**" + exprText(*e.items[0]);
    break;
  case ExprKind::Attribute:
    out = exprText(*e.items[0], PrimaryLevel) + "." + e.text;
    // `1 .real`: an int followed by '.' would lex as a real number
    if (e.items[0]->kind == ExprKind::Int) {
      out = "(" + exprText(*e.items[0]) + ")." + e.text;
    }
    break;
  case ExprKind::Subscript:
    out = exprText(*e.items[0], PrimaryLevel) + "[";
    if (e.items[1]->kind == ExprKind::Tuple && !e.items[1]->items.empty()) {
      for (std::size_t i = 0; i < e.items[1]->items.size(); ++i) {
        out += (i > 0 ? ", " : "") + sliceText(*e.items[1]->items[i]);
      }
      if (e.items[1]->items.size() == 1) {
        out += ",";
      }
    } else {
      out += sliceText(*e.items[1]);
    }
    out += "]";
    break;
  case ExprKind::Slice:
    out = sliceText(e);
    break;
  case ExprKind::Lambda:
    out = "lambda";
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      out += (i > 1 ? ", " : " ") + e.items[i]->text;
    }
    out += ": " + exprText(*e.items[0]);
    break;
  case ExprKind::CompFor:
  case ExprKind::FormattedValue:
    break;
  }
  if (levelOf(e) < minLevel) {
    return "(" + out + ")";
  }
  return out;
}

std::string fstringText(const Expr& e) {
  std::vector<std::string> fields;
  std::string inner;
  for (const auto& part : e.items) {
    if (part->kind == ExprKind::FormattedValue) {
      inner += exprText(*part->items[0]);
    }
  }
  std::string quote = "'";
  for (const char* q : {"'", "\"", "'''", "\"\"\""}) {
    if (inner.find(q) == std::string::npos) {
      quote = q;
      break;
    }
  }
  std::string out = "f" + quote;
  for (const auto& part : e.items) {
    if (part->kind == ExprKind::FormattedValue) {
      std::string text = exprText(*part->items[0]);
      out += "{" + std::string(text.front() == '{' ? " " : "") + text;
      if (part->op != 0) {
        out += std::string("!") + static_cast<char>(part->op);
      }
      if (!part->text.empty()) {
        out += ":" + part->text;
      }
      out += "}";
      continue;
    }
    appendEscaped(out, part->text, quote.front(), EscapeStyle::FStringBody);
  }
  return out + quote;
}

// Breaks a long expression across lines: a call one argument per line aligned after its '(',
// a tuple or list one item per line. `column` is where the text starts.
std::string layout(const Expr& e, std::size_t column, int minLevel = 0, bool bareTuple = false) {
  std::string flat = exprText(e, minLevel, bareTuple);
  if (column + flat.size() <= lineWidth || flat.find('\n') != std::string::npos) {
    return flat;
  }
  auto breakItems = [&](const std::string& open, std::size_t first, const char* close, bool tuple) {
    std::string out = open;
    std::size_t itemColumn = column + open.size();
    std::string pad(itemColumn, ' ');
    for (std::size_t i = first; i < e.items.size(); ++i) {
      if (i > first) {
        out += ",\n" + pad;
      }
      const Expr& item = *e.items[i];
      if (item.kind == ExprKind::Keyword) {
        out += item.text + "=" + layout(*item.items[0], itemColumn + item.text.size() + 1);
      } else {
        out += layout(item, itemColumn);
      }
    }
    if (tuple && e.items.size() == 1) {
      out += ",";
    }
    return out + close;
  };
  if (e.kind == ExprKind::Call && e.items.size() > 1 && levelOf(e) >= minLevel) {
    return breakItems(exprText(*e.items[0], PrimaryLevel) + "(", 1, ")", false);
  }
  if (e.kind == ExprKind::Tuple && !e.items.empty()) {
    return breakItems("(", 0, ")", true);
  }
  if (e.kind == ExprKind::List && !e.items.empty()) {
    return breakItems("[", 0, "]", false);
  }
  return flat;
}

class Printer {
public:
  Printer(const std::vector<Comment>& comments) : comments_(comments) {}

  void block(const std::vector<StmtPtr>& body, int indent) {
    for (const auto& s : body) {
      statement(*s, indent);
    }
  }

  std::string finish() {
    flushComments(1 << 30, 0);
    return out_;
  }

private:
  static int endLineOf(const Stmt& s) {
    int end = std::max(s.endLine, s.pos.line);
    if (!s.orelse.empty()) {
      end = std::max(end, endLineOf(*s.orelse.back()));
    }
    if (!s.body.empty()) {
      end = std::max(end, endLineOf(*s.body.back()));
    }
    if (!s.handlers.empty()) {
      end = std::max(end, endLineOf(*s.handlers.back()));
    }
    if (!s.finalbody.empty()) {
      end = std::max(end, endLineOf(*s.finalbody.back()));
    }
    return end;
  }

  void blankLineBefore(int line) {
    if (lastLine_ > 0 && line > lastLine_ + 1 && !out_.empty()) {
      out_ += "\n";
    }
  }

  void flushComments(int beforeLine, int indent) {
    while (next_ < comments_.size() && comments_[next_].line < beforeLine) {
      const Comment& c = comments_[next_++];
      blankLineBefore(c.line);
      out_.append(static_cast<std::size_t>(indent) * 4, ' ');
      out_ += std::string(c.text) + "\n";
      lastLine_ = c.line;
    }
  }

  // Comments written after code on lines first..last.
  std::string trailingComments(int first, int last) {
    std::string out;
    while (next_ < comments_.size() && comments_[next_].line >= first && comments_[next_].line <= last) {
      out += "  " + std::string(comments_[next_].text);
      ++next_;
    }
    return out;
  }

  void emit(int indent, const std::string& text, int firstLine, int lastLine) {
    out_.append(static_cast<std::size_t>(indent) * 4, ' ');
    out_ += text + trailingComments(firstLine, lastLine) + "\n";
  }

  void statement(const Stmt& s, int indent) {
    flushComments(s.pos.line, indent);
    blankLineBefore(s.pos.line);
    std::size_t column = static_cast<std::size_t>(indent) * 4;
    int last = std::max(s.endLine, s.pos.line);
    switch (s.kind) {
    case StmtKind::Expr:
      emit(indent, layout(*s.exprs[0], column, 0, true), s.pos.line, last);
      break;
    case StmtKind::Assign: {
      std::string text;
      for (std::size_t i = 0; i + 1 < s.exprs.size(); ++i) {
        text += exprText(*s.exprs[i], 0, true) + " = ";
      }
      text += layout(*s.exprs.back(), column + text.size(), 0, true);
      emit(indent, text, s.pos.line, last);
      break;
    }
    case StmtKind::AugAssign: {
      std::string text = exprText(*s.exprs[0]) + " " + binaryOpText(static_cast<BinaryOp>(s.op)) + "= ";
      text += layout(*s.exprs[1], column + text.size(), 0, true);
      emit(indent, text, s.pos.line, last);
      break;
    }
    case StmtKind::For:
      emit(indent, "for " + exprText(*s.exprs[0], 6, true) + " in " + exprText(*s.exprs[1], 0, true) + ":",
           s.pos.line, s.pos.line);
      body(s.body, indent);
      elseBlock(s, indent);
      break;
    case StmtKind::While:
      emit(indent, "while " + exprText(*s.exprs[0]) + ":", s.pos.line, s.pos.line);
      body(s.body, indent);
      elseBlock(s, indent);
      break;
    case StmtKind::If:
      emit(indent, std::string(s.elif ? "elif " : "if ") + exprText(*s.exprs[0]) + ":", s.pos.line,
           s.pos.line);
      body(s.body, indent);
      if (s.orelse.size() == 1 && s.orelse[0]->kind == StmtKind::If && s.orelse[0]->elif) {
        flushComments(s.orelse[0]->pos.line, indent + 1);
        statement(*s.orelse[0], indent);
      } else {
        elseBlock(s, indent);
      }
      break;
    case StmtKind::Try:
      emit(indent, "try:", s.pos.line, s.pos.line);
      body(s.body, indent);
      for (const auto& h : s.handlers) {
        statement(*h, indent);
      }
      elseBlock(s, indent);
      if (!s.finalbody.empty()) {
        flushComments(s.finalbody.front()->pos.line - 1, indent + 1);
        emit(indent, "finally:", 0, -1);
        body(s.finalbody, indent);
      }
      break;
    case StmtKind::ExceptHandler: {
      std::string text = "except";
      if (!s.exprs.empty()) {
        text += " " + exprText(*s.exprs[0]);
        if (!s.name.empty()) {
          text += " as " + s.name;
        }
      }
      emit(indent, text + ":", s.pos.line, s.pos.line);
      body(s.body, indent);
      break;
    }
    case StmtKind::Raise:
      emit(indent, s.exprs.empty() ? "raise" : "raise " + exprText(*s.exprs[0]), s.pos.line, last);
      break;
    case StmtKind::Pass:
      emit(indent, "pass", s.pos.line, last);
      break;
    case StmtKind::Break:
      emit(indent, "break", s.pos.line, last);
      break;
    case StmtKind::Continue:
      emit(indent, "continue", s.pos.line, last);
      break;
    case StmtKind::Del:
    case StmtKind::Return:
    case StmtKind::Assert: {
      std::string text = s.kind == StmtKind::Del ? "del" : (s.kind == StmtKind::Return ? "return" : "assert");
      for (std::size_t i = 0; i < s.exprs.size(); ++i) {
        text += (i > 0 ? ", " : " ") + exprText(*s.exprs[i], 0, s.kind == StmtKind::Return);
      }
      emit(indent, text, s.pos.line, last);
      break;
    }
    case StmtKind::Def: {
      std::string text = "def " + s.name + "(";
      for (std::size_t i = 0; i < s.params.size(); ++i) {
        const Param& p = s.params[i];
        text += (i > 0 ? ", " : "") + std::string(p.star == 1 ? "*" : (p.star == 2 ? "**" : "")) + p.name;
        if (p.defaultValue) {
          text += "=" + exprText(*p.defaultValue);
        }
      }
      emit(indent, text + "):", s.pos.line, s.pos.line);
      body(s.body, indent);
      break;
    }
    case StmtKind::Import:
    case StmtKind::Global: {
      std::string text = s.kind == StmtKind::Import ? "import " : "global ";
      for (std::size_t i = 0; i < s.imports.size(); ++i) {
        text += (i > 0 ? ", " : "") + s.imports[i].name +
                (s.imports[i].alias.empty() ? "" : " as " + s.imports[i].alias);
      }
      emit(indent, text, s.pos.line, last);
      break;
    }
    case StmtKind::FromImport: {
      std::string text = "from " + s.name + " import ";
      for (std::size_t i = 1; i < s.imports.size(); ++i) {
        text += (i > 1 ? ", " : "") + s.imports[i].name +
                (s.imports[i].alias.empty() ? "" : " as " + s.imports[i].alias);
      }
      emit(indent, text, s.pos.line, last);
      break;
    }
    }
    lastLine_ = std::max(lastLine_, endLineOf(s));
  }

  void body(const std::vector<StmtPtr>& stmts, int indent) {
    lastLine_ = 0; // no blank line right after a header
    block(stmts, indent + 1);
  }

  void elseBlock(const Stmt& s, int indent) {
    if (s.orelse.empty()) {
      return;
    }
    flushComments(s.orelse.front()->pos.line - 1, indent + 1);
    emit(indent, "else:", 0, -1);
    body(s.orelse, indent);
  }

  const std::vector<Comment>& comments_;
  std::size_t next_ = 0;
  std::string out_;
  int lastLine_ = 0;
};

} // namespace

std::string formatModule(const Module& module, const std::vector<Comment>& comments) {
  Printer printer(comments);
  printer.block(module.body, 0);
  std::string text = printer.finish();
  // The text is UTF-8 (a file in an 8-bit encoding was decoded when read): its coding line says so.
  if (auto declaration = declaredEncoding(text);
      declaration && encodingNamed(declaration->name) != SourceEncoding::Utf8 &&
      encodingNamed(declaration->name) != SourceEncoding::Unknown) {
    std::size_t lineStart = declaration->line == 1 ? 0 : text.find('\n') + 1;
    text.replace(lineStart + declaration->column - 1, declaration->name.size(), "utf-8");
  }
  return text;
}

std::string formatExpression(const Expr& expr) {
  return exprText(expr);
}

} // namespace stella
