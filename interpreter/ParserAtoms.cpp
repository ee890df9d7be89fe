// The parser's rules for calls, subscripts and slices, atoms, parenthesised forms, list and
// dict displays and comprehensions.
#include "ParserClass.hpp"

#include <algorithm>

namespace stella::parsing {

// arglist: argument (',' argument)* [',']
// argument: test [comp_for] | NAME '=' test | '*' test | '**' test
ExprPtr Parser::parseCall(ExprPtr callee) {
  Pos open = cur_.pos;
  advance();
  ExprPtr call = node(ExprKind::Call, callee->pos);
  call->items.push_back(std::move(callee));
  bool sawKeyword = false;
  while (!at(TokenKind::RParen)) {
    Pos pos = cur_.pos;
    if (at(TokenKind::DoubleStar) || at(TokenKind::Star)) {
      bool dict = at(TokenKind::DoubleStar);
      advance();
      ExprPtr a = node(dict ? ExprKind::DoubleStar : ExprKind::Star, pos);
      a->items.push_back(parseTest());
      if (dict) {
        sawKeyword = true;
      }
      call->items.push_back(finish(std::move(a)));
    } else {
      ExprPtr value = parseTest();
      if (at(TokenKind::Assign)) {
        if (value->kind != ExprKind::Name) {
          fail("SYNTAX_1.4", {});
        }
        advance();
        bool repeated = std::any_of(call->items.begin() + 1, call->items.end(), [&](const ExprPtr& a) {
          return a->kind == ExprKind::Keyword && a->text == value->text;
        });
        if (repeated) {
          failAt(value->pos, "SYNTAX_14", {{"text", value->text}});
        }
        ExprPtr kw = node(ExprKind::Keyword, value->pos);
        kw->text = value->text;
        kw->items.push_back(parseTest());
        call->items.push_back(finish(std::move(kw)));
        sawKeyword = true;
      } else if (at(TokenKind::KwFor)) {
        call->items.push_back(parseComprehension(std::move(value), pos));
      } else {
        if (sawKeyword) {
          failAt(value->pos, "SYNTAX_14.2", {});
        }
        call->items.push_back(std::move(value));
      }
    }
    if (!accept(TokenKind::Comma)) {
      break;
    }
  }
  if (!at(TokenKind::RParen)) {
    if (cur_.pos.line != open.line) {
      fail("SYNTAX_1.call_open",
           {{"token", describeToken(cur_)}, {"line", open.line}, {"column", open.column}});
    }
    fail(cur_.kind == TokenKind::Name || cur_.kind == TokenKind::String ? "SYNTAX_1.call_comma"
                                                                        : "SYNTAX_1.call",
         {{"token", describeToken(cur_)}});
  }
  advance();
  return finish(std::move(call));
}

// subscript: test | [test] ':' [test] [':' [test]]   (several, separated by ',', make a tuple)
ExprPtr Parser::parseSubscript(ExprPtr value) {
  Pos pos = cur_.pos;
  advance();
  ExprPtr e = node(ExprKind::Subscript, pos);
  e->items.push_back(std::move(value));
  ExprPtr index = parseSliceItem();
  if (at(TokenKind::Comma)) {
    ExprPtr tuple = node(ExprKind::Tuple, index->pos);
    tuple->items.push_back(std::move(index));
    while (accept(TokenKind::Comma) && !at(TokenKind::RBracket)) {
      tuple->items.push_back(parseSliceItem());
    }
    index = finish(std::move(tuple));
  }
  e->items.push_back(std::move(index));
  expect(TokenKind::RBracket, "']'");
  return finish(std::move(e));
}

ExprPtr Parser::parseSliceItem() {
  Pos pos = cur_.pos;
  ExprPtr lower;
  if (!at(TokenKind::Colon)) {
    lower = parseTest();
    if (!at(TokenKind::Colon)) {
      return lower;
    }
  }
  ExprPtr s = node(ExprKind::Slice, pos);
  advance();
  ExprPtr upper;
  ExprPtr step;
  if (!at(TokenKind::Colon) && !at(TokenKind::RBracket) && !at(TokenKind::Comma)) {
    upper = parseTest();
  }
  if (accept(TokenKind::Colon) && !at(TokenKind::RBracket) && !at(TokenKind::Comma)) {
    step = parseTest();
  }
  s->items.push_back(std::move(lower));
  s->items.push_back(std::move(upper));
  s->items.push_back(std::move(step));
  return finish(std::move(s));
}

// atom: '(' [testlist_comp] ')' | '[' [testlist_comp] ']' | '{' [dictmaker] '}'
//     | NAME | NUMBER | STRING+ | 'None' | 'True' | 'False'
ExprPtr Parser::parseAtom() {
  Pos pos = cur_.pos;
  switch (cur_.kind) {
  case TokenKind::Name: {
    ExprPtr e = node(ExprKind::Name, pos);
    e->text = std::string(cur_.text);
    advance();
    return e;
  }
  case TokenKind::Int: {
    ExprPtr e = node(ExprKind::Int, pos);
    e->intValue = cur_.intValue;
    e->text = std::string(cur_.text);
    advance();
    return e;
  }
  case TokenKind::Real:
  case TokenKind::Imaginary: {
    ExprPtr e = node(at(TokenKind::Real) ? ExprKind::Real : ExprKind::Imaginary, pos);
    e->realValue = cur_.realValue;
    e->text = std::string(cur_.text);
    advance();
    return e;
  }
  case TokenKind::String:
    return parseStrings();
  case TokenKind::KwNone:
    advance();
    return node(ExprKind::None, pos);
  case TokenKind::KwTrue:
    advance();
    return node(ExprKind::True, pos);
  case TokenKind::KwFalse:
    advance();
    return node(ExprKind::False, pos);
  case TokenKind::LParen:
    advance();
    return parseParenthesized(pos);
  case TokenKind::LBracket:
    advance();
    return parseListDisplay(pos);
  case TokenKind::LBrace:
    advance();
    return parseDictDisplay(pos);
  case TokenKind::Newline:
  case TokenKind::EndOfFile:
    fail("SYNTAX_1.5", {{"describe_token", describeToken(cur_)}});
  default:
    fail("SYNTAX_1.6", {{"describe_token", describeToken(cur_)}});
  }
}

// '(' [testlist_comp] ')'   testlist_comp: test (comp_for | (',' test)* [','])
ExprPtr Parser::parseParenthesized(Pos open) {
  if (accept(TokenKind::RParen)) {
    return node(ExprKind::Tuple, open);
  }
  ExprPtr first = parseTest();
  if (at(TokenKind::KwFor)) {
    ExprPtr comp = parseComprehension(std::move(first), open);
    expect(TokenKind::RParen, "')'");
    return comp;
  }
  if (accept(TokenKind::RParen)) {
    return first;
  }
  ExprPtr tuple = node(ExprKind::Tuple, open);
  tuple->items.push_back(std::move(first));
  while (accept(TokenKind::Comma)) {
    if (at(TokenKind::RParen)) {
      break;
    }
    tuple->items.push_back(parseTest());
  }
  if (!at(TokenKind::RParen)) {
    fail(cur_.pos.line != open.line ? "SYNTAX_1.tuple_open" : "SYNTAX_1.tuple",
         {{"token", describeToken(cur_)}, {"line", open.line}});
  }
  advance();
  return finish(std::move(tuple));
}

// '[' [test (comp_for | (',' test)* [','])] ']'
ExprPtr Parser::parseListDisplay(Pos open) {
  ExprPtr list = node(ExprKind::List, open);
  if (accept(TokenKind::RBracket)) {
    return list;
  }
  ExprPtr first = parseTest();
  if (at(TokenKind::KwFor)) {
    ExprPtr comp = parseComprehension(std::move(first), open);
    expect(TokenKind::RBracket, "']'");
    return comp;
  }
  list->items.push_back(std::move(first));
  while (accept(TokenKind::Comma)) {
    if (at(TokenKind::RBracket)) {
      break;
    }
    list->items.push_back(parseTest());
  }
  if (!at(TokenKind::RBracket)) {
    fail(cur_.pos.line != open.line ? "SYNTAX_1.list_open" : "SYNTAX_1.list",
         {{"token", describeToken(cur_)}, {"line", open.line}});
  }
  advance();
  return finish(std::move(list));
}

// '{' [(test ':' test | '**' expr) (',' ...)* [',']] '}'
ExprPtr Parser::parseDictDisplay(Pos open) {
  ExprPtr dict = node(ExprKind::Dict, open);
  while (!at(TokenKind::RBrace)) {
    if (accept(TokenKind::DoubleStar)) {
      dict->items.push_back(nullptr);
      dict->items.push_back(parseBinary(0));
    } else {
      ExprPtr key = parseTest();
      if (!at(TokenKind::Colon)) {
        if (at(TokenKind::Comma) || at(TokenKind::RBrace)) {
          fail("SYNTAX_12.set");
        }
        fail("SYNTAX_1.dict", {{"token", describeToken(cur_)}});
      }
      advance();
      dict->items.push_back(std::move(key));
      dict->items.push_back(parseTest());
      if (at(TokenKind::KwFor)) {
        fail("SYNTAX_12", {});
      }
    }
    if (!accept(TokenKind::Comma)) {
      break;
    }
  }
  expect(TokenKind::RBrace, "'}'");
  return finish(std::move(dict));
}

// comp_for: 'for' targetlist 'in' or_test ('if' or_test)* [comp_for]
ExprPtr Parser::parseComprehension(ExprPtr element, Pos pos) {
  ExprPtr comp = node(ExprKind::ListComp, pos);
  comp->items.push_back(std::move(element));
  while (at(TokenKind::KwFor)) {
    ExprPtr clause = node(ExprKind::CompFor, cur_.pos);
    advance();
    clause->items.push_back(parseTargetList());
    expect(TokenKind::KwIn, "'in'");
    clause->items.push_back(parseOrTest());
    while (accept(TokenKind::KwIf)) {
      clause->items.push_back(parseOrTest());
    }
    comp->items.push_back(finish(std::move(clause)));
  }
  return finish(std::move(comp));
}

} // namespace stella::parsing
