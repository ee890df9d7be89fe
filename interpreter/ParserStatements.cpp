// The parser's statement rules: file input, simple and compound statements, imports, blocks,
// `def`, and the checks of assignment targets.
#include "ParserClass.hpp"

#include <set>

namespace stella::parsing {

// file_input: (NEWLINE | statement)* ENDMARKER
std::vector<StmtPtr> Parser::parseFileInput() {
  std::vector<StmtPtr> body;
  while (!at(TokenKind::EndOfFile)) {
    if (accept(TokenKind::Newline)) {
      continue;
    }
    if (at(TokenKind::Dedent)) { // only after an indentation error
      advance();
      continue;
    }
    parseStatement(body);
  }
  return body;
}

// statement: compound_stmt | simple_stmts   (an unexpected INDENT is reported, its block read)
void Parser::parseStatement(std::vector<StmtPtr>& out) {
  bool compound = at(TokenKind::KwIf) || at(TokenKind::KwFor) || at(TokenKind::KwWhile) ||
                  at(TokenKind::KwDef) || at(TokenKind::KwElif) || at(TokenKind::KwElse) ||
                  at(TokenKind::KwTry) || at(TokenKind::KwClass) || at(TokenKind::KwWith) ||
                  at(TokenKind::KwExcept) || at(TokenKind::KwFinally);
  bool tryStatement = at(TokenKind::KwTry);
  try {
    if (at(TokenKind::Indent)) {
      report(cur_.pos, "SYNTAX_6", {});
      skipBlock();
      return;
    }
    switch (cur_.kind) {
    case TokenKind::KwIf:
      out.push_back(parseIf(false));
      return;
    case TokenKind::KwFor:
      out.push_back(parseFor());
      return;
    case TokenKind::KwWhile:
      out.push_back(parseWhile());
      return;
    case TokenKind::KwDef:
      out.push_back(parseDef());
      return;
    case TokenKind::KwTry:
      out.push_back(parseTry());
      return;
    case TokenKind::KwExcept:
    case TokenKind::KwFinally:
      fail("SYNTAX_1.7", {{"text", std::string(cur_.text)}});
    case TokenKind::KwElif:
    case TokenKind::KwElse:
      fail("SYNTAX_1.8", {{"text", std::string(cur_.text)}});
    case TokenKind::KwClass:
    case TokenKind::KwWith:
      fail("SYNTAX_12.2", {{"text", std::string(cur_.text)}});
    case TokenKind::At:
      fail("SYNTAX_12.3", {});
    default:
      parseSimpleStatements(out);
    }
  } catch (const ParseError&) {
    synchronize();
    if (compound && at(TokenKind::Indent)) {
      skipBlock(); // the block of a header in error: its errors would be consequences
    }
    // a `try` in error takes its remaining except/else/finally clauses with it
    while (tryStatement && (at(TokenKind::KwExcept) || at(TokenKind::KwFinally) || at(TokenKind::KwElse))) {
      synchronize();
      if (at(TokenKind::Indent)) {
        skipBlock();
      }
    }
  }
}

// Skips an indented block, INDENT to the matching DEDENT, without parsing it.
void Parser::skipBlock() {
  int level = 0;
  while (!at(TokenKind::EndOfFile)) {
    if (at(TokenKind::Indent)) {
      ++level;
    } else if (at(TokenKind::Dedent) && --level == 0) {
      advance();
      return;
    }
    advance();
  }
}

// simple_stmts: simple_stmt (';' simple_stmt)* [';'] NEWLINE
void Parser::parseSimpleStatements(std::vector<StmtPtr>& out) {
  out.push_back(parseSimpleStatement());
  while (accept(TokenKind::Semicolon)) {
    if (at(TokenKind::Newline) || at(TokenKind::EndOfFile)) {
      break;
    }
    out.push_back(parseSimpleStatement());
  }
  out.back()->endLine = prevEndLine_;
  if (!at(TokenKind::EndOfFile)) {
    if (!at(TokenKind::Newline)) {
      const bool operand = cur_.kind == TokenKind::Name || cur_.kind == TokenKind::String ||
                           cur_.kind == TokenKind::Int || cur_.kind == TokenKind::Real;
      fail(operand ? "SYNTAX_1.after_operand" : "SYNTAX_1.after", {{"token", describeToken(cur_)}});
    }
    advance();
  }
}

// simple_stmt: pass | break | continue | del targets | return [testlist] | import | from-import
//            | global NAME (',' NAME)* | assert test [',' test] | expr_stmt
StmtPtr Parser::parseSimpleStatement() {
  Pos pos = cur_.pos;
  switch (cur_.kind) {
  case TokenKind::KwPass:
    advance();
    return std::make_unique<Stmt>(StmtKind::Pass, pos);
  case TokenKind::KwBreak:
  case TokenKind::KwContinue: {
    bool isBreak = at(TokenKind::KwBreak);
    if (loopDepth_ == 0) {
      fail("SYNTAX_13", {{"value", (isBreak ? "break" : "continue")}});
    }
    advance();
    return std::make_unique<Stmt>(isBreak ? StmtKind::Break : StmtKind::Continue, pos);
  }
  case TokenKind::KwDel: {
    advance();
    auto s = std::make_unique<Stmt>(StmtKind::Del, pos);
    ExprPtr targets = parseTestList();
    checkTarget(*targets, true);
    if (targets->kind == ExprKind::Tuple) {
      for (auto& t : targets->items) {
        s->exprs.push_back(std::move(t));
      }
    } else {
      s->exprs.push_back(std::move(targets));
    }
    return s;
  }
  case TokenKind::KwReturn: {
    if (defDepth_ == 0) {
      fail("SYNTAX_13.2", {});
    }
    advance();
    auto s = std::make_unique<Stmt>(StmtKind::Return, pos);
    if (!at(TokenKind::Newline) && !at(TokenKind::Semicolon) && !at(TokenKind::EndOfFile)) {
      s->exprs.push_back(parseTestList());
    }
    return s;
  }
  case TokenKind::KwImport:
    return parseImport();
  case TokenKind::KwFrom:
    return parseFromImport();
  case TokenKind::KwGlobal: {
    advance();
    auto s = std::make_unique<Stmt>(StmtKind::Global, pos);
    do {
      Token name = expect(TokenKind::Name, "a name");
      s->imports.push_back({std::string(name.text), {}, name.pos});
    } while (accept(TokenKind::Comma));
    return s;
  }
  case TokenKind::KwAssert: {
    advance();
    auto s = std::make_unique<Stmt>(StmtKind::Assert, pos);
    s->exprs.push_back(parseTest());
    if (accept(TokenKind::Comma)) {
      s->exprs.push_back(parseTest());
    }
    return s;
  }
  case TokenKind::KwRaise:
    return parseRaise();
  case TokenKind::KwNonlocal:
  case TokenKind::KwYield:
    fail("SYNTAX_12.4", {{"text", std::string(cur_.text)}});
  default:
    return parseExpressionStatement();
  }
}

// expr_stmt: testlist (augassign testlist | ('=' testlist)*)
// augassign: '+=' | '-=' | '*=' | '/=' | '//=' | '%=' | '**='
StmtPtr Parser::parseExpressionStatement() {
  Pos pos = cur_.pos;
  ExprPtr first = parseTestList(true);
  static const std::pair<TokenKind, BinaryOp> augmented[] = {
      {TokenKind::PlusAssign, BinaryOp::Add},
      {TokenKind::MinusAssign, BinaryOp::Sub},
      {TokenKind::StarAssign, BinaryOp::Mul},
      {TokenKind::SlashAssign, BinaryOp::Div},
      {TokenKind::DoubleSlashAssign, BinaryOp::FloorDiv},
      {TokenKind::PercentAssign, BinaryOp::Mod},
      {TokenKind::DoubleStarAssign, BinaryOp::Pow}};
  for (const auto& [kind, op] : augmented) {
    if (at(kind)) {
      if (first->kind != ExprKind::Name && first->kind != ExprKind::Subscript &&
          first->kind != ExprKind::Attribute) {
        failAt(first->pos, "SYNTAX_11", {});
      }
      advance();
      auto s = std::make_unique<Stmt>(StmtKind::AugAssign, pos);
      s->op = static_cast<std::uint8_t>(op);
      s->exprs.push_back(std::move(first));
      s->exprs.push_back(parseTestList());
      return s;
    }
  }
  if (!at(TokenKind::Assign)) {
    auto s = std::make_unique<Stmt>(StmtKind::Expr, pos);
    s->exprs.push_back(std::move(first));
    return s;
  }
  auto s = std::make_unique<Stmt>(StmtKind::Assign, pos);
  s->exprs.push_back(std::move(first));
  while (accept(TokenKind::Assign)) {
    checkTarget(*s->exprs.back());
    s->exprs.push_back(parseTestList(true));
  }
  return s;
}

void Parser::checkTarget(const Expr& e, bool del) {
  switch (e.kind) {
  case ExprKind::Name:
  case ExprKind::Subscript:
  case ExprKind::Attribute:
    return;
  case ExprKind::Tuple:
  case ExprKind::List:
    for (const auto& item : e.items) {
      checkTarget(*item, del);
    }
    return;
  case ExprKind::Call:
    failAt(e.pos, del ? "SYNTAX_11.delete_call" : "SYNTAX_11.assign_call");
  default:
    failAt(e.pos, del ? "SYNTAX_11.delete" : "SYNTAX_11.assign");
  }
}

std::string Parser::dottedName() {
  std::string name(expect(TokenKind::Name, "a module name").text);
  while (accept(TokenKind::Dot)) {
    name += "." + std::string(expect(TokenKind::Name, "a module name").text);
  }
  return name;
}

// import_name: 'import' dotted_name ['as' NAME] (',' dotted_name ['as' NAME])*
StmtPtr Parser::parseImport() {
  auto s = std::make_unique<Stmt>(StmtKind::Import, cur_.pos);
  advance();
  do {
    Pos pos = cur_.pos;
    ImportName name{dottedName(), {}, pos};
    if (accept(TokenKind::KwAs)) {
      name.alias = std::string(expect(TokenKind::Name, "a name").text);
    }
    s->imports.push_back(std::move(name));
  } while (accept(TokenKind::Comma));
  return s;
}

// import_from: 'from' dotted_name 'import' ('*' | '(' names ')' | names)
// names: NAME ['as' NAME] (',' NAME ['as' NAME])* [',']
StmtPtr Parser::parseFromImport() {
  auto s = std::make_unique<Stmt>(StmtKind::FromImport, cur_.pos);
  advance();
  Pos modulePos = cur_.pos;
  s->name = dottedName();
  s->imports.push_back({"", "", modulePos}); // imports[0]: where the module was named
  expect(TokenKind::KwImport, "'import'");
  if (at(TokenKind::Star)) {
    s->imports.push_back({"*", "", cur_.pos});
    advance();
    return s;
  }
  bool paren = accept(TokenKind::LParen);
  do {
    if (paren && at(TokenKind::RParen)) {
      break;
    }
    Token name = expect(TokenKind::Name, "a name to import");
    ImportName in{std::string(name.text), {}, name.pos};
    if (accept(TokenKind::KwAs)) {
      in.alias = std::string(expect(TokenKind::Name, "a name").text);
    }
    s->imports.push_back(std::move(in));
  } while (accept(TokenKind::Comma));
  if (paren) {
    expect(TokenKind::RParen, "')'");
  }
  return s;
}

// suite: simple_stmts | NEWLINE INDENT statement+ DEDENT
std::vector<StmtPtr> Parser::parseSuite() {
  std::vector<StmtPtr> body;
  Nest nest(*this);
  if (!at(TokenKind::Newline)) {
    parseSimpleStatements(body);
    return body;
  }
  advance();
  if (!at(TokenKind::Indent)) {
    fail("SYNTAX_7", {});
  }
  advance();
  while (!at(TokenKind::Dedent) && !at(TokenKind::EndOfFile)) {
    parseStatement(body);
  }
  accept(TokenKind::Dedent);
  return body;
}

// if_stmt: 'if' test ':' suite ('elif' test ':' suite)* ['else' ':' suite]
StmtPtr Parser::parseIf(bool elif) {
  auto s = std::make_unique<Stmt>(StmtKind::If, cur_.pos);
  s->elif = elif;
  advance();
  s->exprs.push_back(parseTest());
  expect(TokenKind::Colon, "':' after the condition");
  s->body = parseSuite();
  s->endLine = prevEndLine_;
  if (at(TokenKind::KwElif)) {
    s->orelse.push_back(parseIf(true));
  } else if (accept(TokenKind::KwElse)) {
    expect(TokenKind::Colon, "':' after 'else'");
    s->orelse = parseSuite();
  }
  return s;
}

// for_stmt: 'for' targetlist 'in' testlist ':' suite ['else' ':' suite]
StmtPtr Parser::parseFor() {
  auto s = std::make_unique<Stmt>(StmtKind::For, cur_.pos);
  advance();
  s->exprs.push_back(parseTargetList());
  expect(TokenKind::KwIn, "'in'");
  s->exprs.push_back(parseTestList());
  expect(TokenKind::Colon, "':' at the end of the 'for' line");
  ++loopDepth_;
  s->body = parseSuite();
  --loopDepth_;
  if (accept(TokenKind::KwElse)) {
    expect(TokenKind::Colon, "':' after 'else'");
    s->orelse = parseSuite();
  }
  return s;
}

// while_stmt: 'while' test ':' suite ['else' ':' suite]
StmtPtr Parser::parseWhile() {
  auto s = std::make_unique<Stmt>(StmtKind::While, cur_.pos);
  advance();
  s->exprs.push_back(parseTest());
  expect(TokenKind::Colon, "':' at the end of the 'while' line");
  ++loopDepth_;
  s->body = parseSuite();
  --loopDepth_;
  if (accept(TokenKind::KwElse)) {
    expect(TokenKind::Colon, "':' after 'else'");
    s->orelse = parseSuite();
  }
  return s;
}

// try_stmt: 'try' ':' suite ((except_clause ':' suite)+ ['else' ':' suite] ['finally' ':' suite]
//                          | 'finally' ':' suite)
// except_clause: 'except' [test ['as' NAME]]
StmtPtr Parser::parseTry() {
  auto s = std::make_unique<Stmt>(StmtKind::Try, cur_.pos);
  advance();
  expect(TokenKind::Colon, "':' after 'try'");
  s->body = parseSuite();
  bool bare = false;
  while (at(TokenKind::KwExcept)) {
    auto h = std::make_unique<Stmt>(StmtKind::ExceptHandler, cur_.pos);
    if (bare) {
      fail("SYNTAX_1.9", {});
    }
    advance();
    if (!at(TokenKind::Colon)) {
      h->exprs.push_back(parseTest());
      if (accept(TokenKind::KwAs)) {
        h->name = std::string(expect(TokenKind::Name, "a name after 'as'").text);
      }
    } else {
      bare = true;
    }
    expect(TokenKind::Colon, "':' at the end of the 'except' line");
    h->body = parseSuite();
    s->handlers.push_back(std::move(h));
  }
  if (!s->handlers.empty() && accept(TokenKind::KwElse)) {
    expect(TokenKind::Colon, "':' after 'else'");
    s->orelse = parseSuite();
  }
  if (accept(TokenKind::KwFinally)) {
    expect(TokenKind::Colon, "':' after 'finally'");
    s->finalbody = parseSuite();
  }
  if (s->handlers.empty() && s->finalbody.empty()) {
    fail("SYNTAX_1.10", {{"describe_token", describeToken(cur_)}});
  }
  return s;
}

// raise_stmt: 'raise' [test]
StmtPtr Parser::parseRaise() {
  auto s = std::make_unique<Stmt>(StmtKind::Raise, cur_.pos);
  advance();
  if (!at(TokenKind::Newline) && !at(TokenKind::Semicolon) && !at(TokenKind::EndOfFile)) {
    s->exprs.push_back(parseTest());
    if (at(TokenKind::KwFrom)) {
      fail("SYNTAX_12.5", {});
    }
  }
  return s;
}

// funcdef: 'def' NAME '(' [param (',' param)* [',']] ')' ['->' test] ':' suite
// param: NAME ['=' test] | '*' NAME | '**' NAME
StmtPtr Parser::parseDef() {
  auto s = std::make_unique<Stmt>(StmtKind::Def, cur_.pos);
  advance();
  s->name = std::string(expect(TokenKind::Name, "the function's name").text);
  expect(TokenKind::LParen, "'('");
  std::set<std::string> seen;
  bool sawDefault = false;
  while (!at(TokenKind::RParen)) {
    Param p;
    if (accept(TokenKind::Star)) {
      p.star = 1;
    } else if (accept(TokenKind::DoubleStar)) {
      p.star = 2;
    }
    Token name = expect(TokenKind::Name, "a parameter name");
    p.name = std::string(name.text);
    p.pos = name.pos;
    if (!seen.insert(p.name).second) {
      failAt(name.pos, "SYNTAX_14.4", {{"name", p.name}});
    }
    if (p.star == 0 && accept(TokenKind::Assign)) {
      p.defaultValue = parseTest();
      sawDefault = true;
    } else if (p.star == 0 && sawDefault) {
      failAt(name.pos, "SYNTAX_14.5", {});
    }
    s->params.push_back(std::move(p));
    if (!accept(TokenKind::Comma)) {
      break;
    }
  }
  expect(TokenKind::RParen, "')'");
  if (accept(TokenKind::Arrow)) {
    parseTest();
  }
  expect(TokenKind::Colon, "':' after the parameters");
  int savedLoops = loopDepth_;
  loopDepth_ = 0;
  ++defDepth_;
  s->body = parseSuite();
  --defDepth_;
  loopDepth_ = savedLoops;
  return s;
}

} // namespace stella::parsing
