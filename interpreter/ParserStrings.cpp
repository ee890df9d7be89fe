// The parser's string rules: adjacent literals joined, f-strings split into literal parts and
// formatted fields (each field parsed as an expression of its own).
#include "ParserClass.hpp"

namespace stella::parsing {

// STRING+ : adjacent literals are joined; an f-string makes the result an FString.
ExprPtr Parser::parseStrings() {
  Pos pos = cur_.pos;
  if (!cur_.fString) { // one plain literal: the common case, without a token list
    Token t = std::move(cur_);
    advance();
    if (!at(TokenKind::String)) {
      ExprPtr e = node(ExprKind::String, pos);
      e->text = std::move(t.value);
      return e;
    }
    std::vector<Token> parts;
    parts.push_back(std::move(t));
    return joinStrings(pos, std::move(parts));
  }
  return joinStrings(pos, {});
}

ExprPtr Parser::joinStrings(Pos pos, std::vector<Token> parts) {
  bool anyF = false;
  for (const auto& t : parts) {
    anyF = anyF || t.fString;
  }
  while (at(TokenKind::String)) {
    anyF = anyF || cur_.fString;
    parts.push_back(std::move(cur_));
    advance();
  }
  if (!anyF) {
    ExprPtr e = node(ExprKind::String, pos);
    for (const auto& t : parts) {
      e->text += t.value;
    }
    return e;
  }
  ExprPtr e = node(ExprKind::FString, pos);
  for (const auto& t : parts) {
    if (t.fString) {
      parseFStringInto(t, *e);
    } else if (!t.value.empty()) {
      if (!e->items.empty() && e->items.back()->kind == ExprKind::String) {
        e->items.back()->text += t.value;
      } else {
        ExprPtr s = node(ExprKind::String, t.pos);
        s->text = t.value;
        e->items.push_back(std::move(s));
      }
    }
  }
  return finish(std::move(e));
}

// f-string body: literal text with '{{' '}}' escapes and replacement fields
// '{' expression ['!' ('r'|'s')] [':' format_spec] '}'
void Parser::parseFStringInto(const Token& t, Expr& out) {
  bool raw = t.value == "r";
  std::size_t prefixAndQuote = static_cast<std::size_t>(t.contentColumn - t.pos.column);
  std::size_t quoteLength = (t.text.size() >= 6 && (t.text.substr(t.text.size() - 3) == "'''" ||
                                                    t.text.substr(t.text.size() - 3) == "\"\"\""))
                                ? 3
                                : 1;
  if (t.text.size() < prefixAndQuote + quoteLength) {
    return; // unterminated: already reported
  }
  std::string_view body = t.text.substr(prefixAndQuote, t.text.size() - prefixAndQuote - quoteLength);
  int line = t.pos.line;
  int col = t.contentColumn;
  std::string literal;
  Pos literalPos{line, col, 1};
  auto flushLiteral = [&] {
    if (literal.empty()) {
      return;
    }
    std::string decoded = raw ? literal : decodeEscapes(literal);
    if (!out.items.empty() && out.items.back()->kind == ExprKind::String) {
      out.items.back()->text += decoded;
    } else {
      ExprPtr s = node(ExprKind::String, literalPos);
      s->text = std::move(decoded);
      out.items.push_back(std::move(s));
    }
    literal.clear();
  };
  auto step = [&](char c) {
    if (c == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  };
  std::size_t i = 0;
  while (i < body.size()) {
    char c = body[i];
    if ((c == '{' || c == '}') && i + 1 < body.size() && body[i + 1] == c) {
      if (literal.empty()) {
        literalPos = Pos{line, col, 1};
      }
      literal += c;
      step(c);
      step(c);
      i += 2;
      continue;
    }
    if (c == '}') {
      failAt(Pos{line, col, 1}, "SYNTAX_15", {});
    }
    if (c != '{') {
      if (literal.empty()) {
        literalPos = Pos{line, col, 1};
      }
      literal += c;
      step(c);
      ++i;
      continue;
    }
    flushLiteral();
    Pos open{line, col, 1};
    step(c);
    ++i;
    // the expression runs to the first top-level '!', ':' or '}'
    std::size_t exprBegin = i;
    int exprLine = line;
    int exprCol = col;
    int nesting = 0;
    char quote = 0;
    while (i < body.size()) {
      char d = body[i];
      if (quote != 0) {
        if (d == quote) {
          quote = 0;
        }
      } else if (d == '\'' || d == '"') {
        quote = d;
      } else if (d == '(' || d == '[' || d == '{') {
        ++nesting;
      } else if (d == ')' || d == ']' || d == '}') {
        if (nesting == 0) {
          break;
        }
        --nesting;
      } else if (nesting == 0 && (d == ':' || (d == '!' && (i + 1 >= body.size() || body[i + 1] != '=')))) {
        break;
      }
      step(d);
      ++i;
    }
    std::string_view exprText = body.substr(exprBegin, i - exprBegin);
    if (exprText.find_first_not_of(" \t\n") == std::string_view::npos) {
      failAt(open, "SYNTAX_15.2", {});
    }
    ExprPtr fv = node(ExprKind::FormattedValue, open);
    Lexer sub(lexer_.file(), exprText, exprLine, exprCol);
    Parser subParser(sub, depth_ + 1, arena_);
    ExprPtr value;
    try {
      value = subParser.parseStandaloneExpression();
    } catch (const ParseError&) {
    }
    for (auto& d : sub.errors()) {
      errors_.push_back(std::move(d));
    }
    for (auto& d : subParser.errors()) {
      errors_.push_back(std::move(d));
    }
    if (!value) {
      throw ParseError{};
    }
    fv->items.push_back(std::move(value));
    if (i < body.size() && body[i] == '!') {
      step('!');
      ++i;
      if (i < body.size() && (body[i] == 'r' || body[i] == 's' || body[i] == 'a')) {
        fv->op = static_cast<std::uint8_t>(body[i]);
        step(body[i]);
        ++i;
      } else {
        failAt(Pos{line, col, 1}, "SYNTAX_15.3", {});
      }
    }
    if (i < body.size() && body[i] == ':') {
      step(':');
      ++i;
      std::size_t specBegin = i;
      while (i < body.size() && body[i] != '}') {
        if (body[i] == '{') {
          failAt(Pos{line, col, 1}, "SYNTAX_15.4", {});
        }
        step(body[i]);
        ++i;
      }
      fv->text = std::string(body.substr(specBegin, i - specBegin));
    }
    if (i >= body.size() || body[i] != '}') {
      failAt(open, "SYNTAX_15.5", {});
    }
    step('}');
    ++i;
    out.items.push_back(finish(std::move(fv)));
  }
  flushLiteral();
}

} // namespace stella::parsing
