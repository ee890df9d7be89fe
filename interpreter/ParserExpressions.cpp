// The parser's expression rules from target and test lists down to primaries: lambda,
// conditional, or/and/not, comparisons, binary operators by precedence, unary, power.
#include "ParserClass.hpp"

#include <set>

namespace stella::parsing {

// targetlist: target (',' target)* [',']   target: primary (a name, X[i], X.a) | '(' targetlist ')'
ExprPtr Parser::parseTargetList() {
  Pos pos = cur_.pos;
  std::vector<ExprPtr> items;
  bool tuple = false;
  for (;;) {
    ExprPtr t = parseBinary(0);
    checkTarget(*t);
    items.push_back(std::move(t));
    if (!accept(TokenKind::Comma)) {
      break;
    }
    tuple = true;
    if (at(TokenKind::KwIn)) {
      break;
    }
  }
  if (!tuple) {
    return std::move(items.front());
  }
  ExprPtr e = node(ExprKind::Tuple, pos);
  for (auto& item : items) {
    e->items.push_back(std::move(item));
  }
  return finish(std::move(e));
}

// testlist: test (',' test)* [',']   (a tuple when there is a comma)
ExprPtr Parser::parseTestList(bool allowStar) {
  (void)allowStar;
  Pos pos = cur_.pos;
  ExprPtr first = parseTest();
  if (!at(TokenKind::Comma)) {
    return first;
  }
  ExprPtr e = node(ExprKind::Tuple, pos);
  e->items.push_back(std::move(first));
  while (accept(TokenKind::Comma)) {
    if (at(TokenKind::Newline) || at(TokenKind::Assign) || at(TokenKind::Semicolon) ||
        at(TokenKind::EndOfFile) || at(TokenKind::RParen) || at(TokenKind::Colon)) {
      break;
    }
    e->items.push_back(parseTest());
  }
  return finish(std::move(e));
}

// test: or_test ['if' or_test 'else' test] | lambdef
ExprPtr Parser::parseTest() {
  Nest nest(*this);
  if (at(TokenKind::KwLambda)) {
    return parseLambda();
  }
  ExprPtr body = parseOrTest();
  if (!at(TokenKind::KwIf)) {
    return body;
  }
  Pos pos = cur_.pos;
  advance();
  ExprPtr test = parseOrTest();
  expect(TokenKind::KwElse, "'else' in the conditional expression");
  ExprPtr orelse = parseTest();
  ExprPtr e = node(ExprKind::Conditional, pos);
  e->items.push_back(std::move(body));
  e->items.push_back(std::move(test));
  e->items.push_back(std::move(orelse));
  return finish(std::move(e));
}

// lambdef: 'lambda' [NAME (',' NAME)*] ':' test
ExprPtr Parser::parseLambda() {
  ExprPtr e = node(ExprKind::Lambda, cur_.pos);
  advance();
  std::vector<ExprPtr> params;
  std::set<std::string> seen;
  while (!at(TokenKind::Colon)) {
    Token name = expect(TokenKind::Name, "a parameter name");
    if (!seen.insert(std::string(name.text)).second) {
      failAt(name.pos, "SYNTAX_14.3", {{"text", std::string(name.text)}});
    }
    ExprPtr p = node(ExprKind::Name, name.pos);
    p->text = std::string(name.text);
    params.push_back(std::move(p));
    if (!accept(TokenKind::Comma)) {
      break;
    }
  }
  expect(TokenKind::Colon, "':' in the lambda");
  e->items.push_back(parseTest());
  for (auto& p : params) {
    e->items.push_back(std::move(p));
  }
  return finish(std::move(e));
}

// or_test: and_test ('or' and_test)*
ExprPtr Parser::parseOrTest() {
  ExprPtr first = parseAndTest();
  if (!at(TokenKind::KwOr)) {
    return first;
  }
  ExprPtr e = node(ExprKind::Or, cur_.pos);
  e->items.push_back(std::move(first));
  while (accept(TokenKind::KwOr)) {
    e->items.push_back(parseAndTest());
  }
  return finish(std::move(e));
}

// and_test: not_test ('and' not_test)*
ExprPtr Parser::parseAndTest() {
  ExprPtr first = parseNotTest();
  if (!at(TokenKind::KwAnd)) {
    return first;
  }
  ExprPtr e = node(ExprKind::And, cur_.pos);
  e->items.push_back(std::move(first));
  while (accept(TokenKind::KwAnd)) {
    e->items.push_back(parseNotTest());
  }
  return finish(std::move(e));
}

// not_test: 'not' not_test | comparison
ExprPtr Parser::parseNotTest() {
  if (!at(TokenKind::KwNot)) {
    return parseComparison();
  }
  Nest nest(*this);
  ExprPtr e = node(ExprKind::Not, cur_.pos);
  advance();
  e->items.push_back(parseNotTest());
  return finish(std::move(e));
}

// comparison: expr (comp_op expr)*
// comp_op: '<' | '>' | '==' | '>=' | '<=' | '!=' | 'in' | 'not' 'in' | 'is' | 'is' 'not'
ExprPtr Parser::parseComparison() {
  ExprPtr first = parseBinary(0);
  ExprPtr e;
  for (;;) {
    CompareOp op;
    Pos pos = cur_.pos;
    switch (cur_.kind) {
    case TokenKind::Less:
      op = CompareOp::Lt;
      break;
    case TokenKind::Greater:
      op = CompareOp::Gt;
      break;
    case TokenKind::LessEqual:
      op = CompareOp::Le;
      break;
    case TokenKind::GreaterEqual:
      op = CompareOp::Ge;
      break;
    case TokenKind::EqualEqual:
      op = CompareOp::Eq;
      break;
    case TokenKind::NotEqual:
      op = CompareOp::Ne;
      break;
    case TokenKind::KwIn:
      op = CompareOp::In;
      break;
    case TokenKind::KwIs:
      op = CompareOp::Is;
      break;
    case TokenKind::KwNot:
      op = CompareOp::NotIn;
      break;
    default:
      return e ? finish(std::move(e)) : std::move(first);
    }
    advance();
    if (op == CompareOp::NotIn) {
      expect(TokenKind::KwIn, "'in' after 'not'");
    } else if (op == CompareOp::Is && accept(TokenKind::KwNot)) {
      op = CompareOp::IsNot;
    }
    if (!e) {
      e = node(ExprKind::Compare, pos);
      e->items.push_back(std::move(first));
    }
    e->addCompareOp(op);
    e->items.push_back(parseBinary(0));
  }
}

namespace {
// Binary operators below unary minus, with their precedence (higher binds tighter).
bool binaryOperator(TokenKind k, BinaryOp& op) {
  switch (k) {
  case TokenKind::Pipe:
    op = BinaryOp::BitOr;
    return true;
  case TokenKind::Caret:
    op = BinaryOp::BitXor;
    return true;
  case TokenKind::Ampersand:
    op = BinaryOp::BitAnd;
    return true;
  case TokenKind::LeftShift:
    op = BinaryOp::LShift;
    return true;
  case TokenKind::RightShift:
    op = BinaryOp::RShift;
    return true;
  case TokenKind::Plus:
    op = BinaryOp::Add;
    return true;
  case TokenKind::Minus:
    op = BinaryOp::Sub;
    return true;
  case TokenKind::Star:
    op = BinaryOp::Mul;
    return true;
  case TokenKind::Slash:
    op = BinaryOp::Div;
    return true;
  case TokenKind::DoubleSlash:
    op = BinaryOp::FloorDiv;
    return true;
  case TokenKind::Percent:
    op = BinaryOp::Mod;
    return true;
  default:
    return false;
  }
}
} // namespace

// expr: xor_expr ('|' xor_expr)* ... arith_expr: term (('+'|'-') term)*
// term: factor (('*'|'/'|'//'|'%') factor)*       (precedence climbing, left associative)
ExprPtr Parser::parseBinary(int minPrecedence) {
  ExprPtr left = parseFactor();
  BinaryOp op;
  while (binaryOperator(cur_.kind, op) && binaryPrecedence(op) >= minPrecedence) {
    Pos pos = cur_.pos;
    advance();
    ExprPtr right = parseBinary(binaryPrecedence(op) + 1);
    ExprPtr e = node(ExprKind::Binary, pos);
    e->op = static_cast<std::uint8_t>(op);
    e->items.push_back(std::move(left));
    e->items.push_back(std::move(right));
    left = finish(std::move(e));
  }
  return left;
}

// factor: ('+'|'-'|'~') factor | power
ExprPtr Parser::parseFactor() {
  UnaryOp op;
  switch (cur_.kind) {
  case TokenKind::Minus:
    op = UnaryOp::Neg;
    break;
  case TokenKind::Plus:
    op = UnaryOp::Plus;
    break;
  case TokenKind::Tilde:
    op = UnaryOp::Invert;
    break;
  default:
    return parsePower();
  }
  Nest nest(*this);
  ExprPtr e = node(ExprKind::Unary, cur_.pos);
  e->op = static_cast<std::uint8_t>(op);
  advance();
  e->items.push_back(parseFactor());
  return finish(std::move(e));
}

// power: primary ['**' factor]
ExprPtr Parser::parsePower() {
  ExprPtr base = parsePrimary();
  if (!at(TokenKind::DoubleStar)) {
    return base;
  }
  ExprPtr e = node(ExprKind::Binary, cur_.pos);
  e->op = static_cast<std::uint8_t>(BinaryOp::Pow);
  advance();
  Nest nest(*this);
  e->items.push_back(std::move(base));
  e->items.push_back(parseFactor());
  return finish(std::move(e));
}

// primary: atom trailer*    trailer: '(' [arglist] ')' | '[' subscript ']' | '.' NAME
ExprPtr Parser::parsePrimary() {
  ExprPtr e = parseAtom();
  for (;;) {
    if (at(TokenKind::LParen)) {
      e = parseCall(std::move(e));
    } else if (at(TokenKind::LBracket)) {
      e = parseSubscript(std::move(e));
    } else if (at(TokenKind::Dot)) {
      advance();
      Token name = expect(TokenKind::Name, "an attribute name after '.'");
      ExprPtr a = node(ExprKind::Attribute, name.pos);
      a->text = std::string(name.text);
      a->items.push_back(std::move(e));
      e = finish(std::move(a));
    } else {
      return e;
    }
  }
}

} // namespace stella::parsing
