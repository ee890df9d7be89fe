// Recursive-descent parser of the command language (the part of Python that command files use).
// Each function states the grammar rule it parses. A syntax error throws ParseError, caught at
// the statement level, which records it and skips to the next statement.
#include "Parser.hpp"

#include <algorithm>
#include <set>

namespace stella {

namespace {

struct ParseError {};

class Parser {
public:
  Parser(Lexer& lexer, int depth, std::pmr::memory_resource* arena)
      : lexer_(lexer), arena_(arena), depth_(depth) {
    advance();
  }

  std::vector<StmtPtr> parseFileInput();
  ExprPtr parseStandaloneExpression();
  std::vector<Diagnostic>& errors() { return errors_; }

private:
  // --- tokens ---
  void advance() {
    prevEndLine_ = cur_.pos.line;
    cur_ = lexer_.next();
  }
  bool at(TokenKind k) const { return cur_.kind == k; }
  bool accept(TokenKind k) {
    if (at(k)) {
      advance();
      return true;
    }
    return false;
  }
  Token expect(TokenKind k, const char* what) {
    if (!at(k)) {
      fail("expected " + std::string(what) + ", found " + describeToken(cur_));
    }
    Token t = std::move(cur_);
    advance();
    return t;
  }
  [[noreturn]] void fail(const std::string& message, const std::string& id = "SYNTAX_1",
                         const std::string& note = {}) {
    failAt(cur_.pos, message, id, note);
  }
  [[noreturn]] void failAt(Pos pos, const std::string& message, const std::string& id = "SYNTAX_1",
                           const std::string& note = {}) {
    // an invalid character, or a line end after an unclosed bracket, is already reported
    if ((cur_.kind != TokenKind::Error && !cur_.recovered) || id != "SYNTAX_1") {
      Diagnostic d = Diagnostic::syntax(id, message, lexer_.location(pos));
      if (!note.empty()) {
        d.withNote(note);
      }
      errors_.push_back(std::move(d));
    }
    throw ParseError{};
  }
  void report(Pos pos, const std::string& message, const std::string& id, const std::string& note = {}) {
    Diagnostic d = Diagnostic::syntax(id, message, lexer_.location(pos));
    if (!note.empty()) {
      d.withNote(note);
    }
    errors_.push_back(std::move(d));
  }
  void synchronize();
  void skipBlock();

  struct Nest {
    Parser& p;
    explicit Nest(Parser& parser) : p(parser) {
      if (++p.depth_ > maxParseNesting) {
        --p.depth_;
        p.fail("too deeply nested (more than " + std::to_string(maxParseNesting) + " levels)", "SYNTAX_10",
               "split the expression or the blocks into smaller parts");
      }
    }
    ~Nest() { --p.depth_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;
  };

  ExprPtr node(ExprKind kind, Pos pos) {
    void* memory = arena_->allocate(sizeof(Expr), alignof(Expr));
    ExprPtr e(new (memory) Expr(kind, pos, arena_));
    e->items.reserve(childrenHint(kind)); // the arena never reuses a grown vector's old storage
    return e;
  }
  static std::size_t childrenHint(ExprKind kind) {
    switch (kind) {
    case ExprKind::Unary:
    case ExprKind::Not:
    case ExprKind::Keyword:
    case ExprKind::Attribute:
    case ExprKind::Star:
    case ExprKind::DoubleStar:
    case ExprKind::FormattedValue:
      return 1;
    case ExprKind::Binary:
    case ExprKind::Subscript:
    case ExprKind::Compare:
    case ExprKind::And:
    case ExprKind::Or:
      return 2;
    case ExprKind::Conditional:
    case ExprKind::Slice:
    case ExprKind::CompFor:
      return 3;
    case ExprKind::Call:
    case ExprKind::Tuple:
    case ExprKind::List:
    case ExprKind::Dict:
      return 4;
    default:
      return 0;
    }
  }
  ExprPtr finish(ExprPtr e);

  // --- statements ---
  void parseStatement(std::vector<StmtPtr>& out);
  void parseSimpleStatements(std::vector<StmtPtr>& out);
  StmtPtr parseSimpleStatement();
  StmtPtr parseExpressionStatement();
  StmtPtr parseImport();
  StmtPtr parseFromImport();
  StmtPtr parseIf(bool elif);
  StmtPtr parseFor();
  StmtPtr parseWhile();
  StmtPtr parseDef();
  std::vector<StmtPtr> parseSuite();
  void checkTarget(const Expr& e, bool del = false);
  std::string dottedName();

  // --- expressions ---
  ExprPtr parseTestList(bool allowStar = false);
  ExprPtr parseTest();
  ExprPtr parseLambda();
  ExprPtr parseOrTest();
  ExprPtr parseAndTest();
  ExprPtr parseNotTest();
  ExprPtr parseComparison();
  ExprPtr parseBinary(int minPrecedence);
  ExprPtr parseFactor();
  ExprPtr parsePower();
  ExprPtr parsePrimary();
  ExprPtr parseAtom();
  ExprPtr parseStrings();
  ExprPtr joinStrings(Pos pos, std::vector<Token> parts);
  void parseFStringInto(const Token& t, Expr& out);
  ExprPtr parseParenthesized(Pos open);
  ExprPtr parseListDisplay(Pos open);
  ExprPtr parseDictDisplay(Pos open);
  ExprPtr parseComprehension(ExprPtr element, Pos pos);
  ExprPtr parseCall(ExprPtr callee);
  ExprPtr parseSubscript(ExprPtr value);
  ExprPtr parseSliceItem();
  ExprPtr parseTargetList();

  Lexer& lexer_;
  std::pmr::memory_resource* arena_;
  Token cur_;
  int prevEndLine_ = 0;
  int depth_ = 0;
  int loopDepth_ = 0;
  int defDepth_ = 0;
  std::vector<Diagnostic> errors_;
};

ExprPtr Parser::finish(ExprPtr e) {
  int depth = 0;
  for (const auto& c : e->items) {
    if (c) {
      depth = std::max(depth, c->depth);
    }
  }
  e->depth = depth + 1;
  if (e->depth > maxTreeDepth) {
    failAt(e->pos, "expression too deeply nested (more than " + std::to_string(maxTreeDepth) + " levels)",
           "SYNTAX_10", "split it into several assignments");
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
                  at(TokenKind::KwTry) || at(TokenKind::KwClass) || at(TokenKind::KwWith);
  bool refusedTry = at(TokenKind::KwTry);
  try {
    if (at(TokenKind::Indent)) {
      report(cur_.pos, "unexpected indent", "SYNTAX_6",
             "a statement is indented only inside a block (after a ':')");
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
    case TokenKind::KwElif:
    case TokenKind::KwElse:
      fail("'" + std::string(cur_.text) + "' without a matching 'if' at the same indentation", "SYNTAX_1",
           "align it with its 'if'");
    case TokenKind::KwTry:
    case TokenKind::KwClass:
    case TokenKind::KwWith:
      fail("'" + std::string(cur_.text) + "' statements are not part of the command language", "SYNTAX_12",
           "command files use assignments, calls, if/for/while and def only");
    case TokenKind::At:
      fail("decorators are not part of the command language", "SYNTAX_12");
    default:
      parseSimpleStatements(out);
    }
  } catch (const ParseError&) {
    synchronize();
    if (compound && at(TokenKind::Indent)) {
      skipBlock(); // the block of a header in error: its errors would be consequences
    }
    // a refused `try` takes its except/else/finally clauses with it
    while (refusedTry && (at(TokenKind::KwExcept) || at(TokenKind::KwFinally) || at(TokenKind::KwElse))) {
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
      std::string note;
      if (cur_.kind == TokenKind::Name || cur_.kind == TokenKind::String || cur_.kind == TokenKind::Int ||
          cur_.kind == TokenKind::Real) {
        note = "is a ',' or an operator missing before it?";
      }
      fail("unexpected " + describeToken(cur_) + " after the end of the statement", "SYNTAX_1", note);
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
      fail(std::string("'") + (isBreak ? "break" : "continue") + "' outside a loop", "SYNTAX_13");
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
      fail("'return' outside a function", "SYNTAX_13");
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
  case TokenKind::KwNonlocal:
  case TokenKind::KwYield:
    fail("'" + std::string(cur_.text) + "' is not part of the command language", "SYNTAX_12");
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
        failAt(first->pos, "cannot use an augmented assignment on this expression", "SYNTAX_11",
               "the target of '+=' is a name or an indexed element");
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
    failAt(e.pos, del ? "cannot delete a function call" : "cannot assign to a function call", "SYNTAX_11",
           del ? ""
               : "did you mean '==' (comparison) instead of '='? A keyword argument is written inside the "
                 "call's "
                 "parentheses");
  default:
    failAt(e.pos, del ? "cannot delete this expression" : "cannot assign to this expression", "SYNTAX_11",
           del ? "" : "the left-hand side of '=' is a name, an indexed element X[i] or a tuple of them");
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
    fail("expected an indented block", "SYNTAX_7", "indent the statements of the block (4 spaces)");
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
      failAt(name.pos, "duplicate parameter '" + p.name + "'", "SYNTAX_14");
    }
    if (p.star == 0 && accept(TokenKind::Assign)) {
      p.defaultValue = parseTest();
      sawDefault = true;
    } else if (p.star == 0 && sawDefault) {
      failAt(name.pos, "a parameter without a default follows one with a default", "SYNTAX_14");
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
      failAt(name.pos, "duplicate parameter '" + std::string(name.text) + "'", "SYNTAX_14");
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
          fail("a keyword argument's name must be a plain name", "SYNTAX_1",
               "did you mean '==' (comparison) instead of '='?");
        }
        advance();
        bool repeated = std::any_of(call->items.begin() + 1, call->items.end(), [&](const ExprPtr& a) {
          return a->kind == ExprKind::Keyword && a->text == value->text;
        });
        if (repeated) {
          failAt(
              value->pos, "keyword argument '" + value->text + "' repeated", "SYNTAX_14",
              "give each keyword once; for several occurrences of a factor keyword use a tuple of _F(...)");
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
          failAt(value->pos, "positional argument after a keyword argument", "SYNTAX_14",
                 "put positional arguments first, or give this one a keyword");
        }
        call->items.push_back(std::move(value));
      }
    }
    if (!accept(TokenKind::Comma)) {
      break;
    }
  }
  if (!at(TokenKind::RParen)) {
    std::string note;
    if (cur_.pos.line != open.line) {
      note = "the '(' at line " + std::to_string(open.line) + " column " + std::to_string(open.column) +
             " is still open: is a ',' or a ')' missing?";
    } else if (cur_.kind == TokenKind::Name || cur_.kind == TokenKind::String) {
      note = "is a ',' missing before it?";
    }
    fail("expected ',' or ')' in the call, found " + describeToken(cur_), "SYNTAX_1", note);
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
    fail("expected an expression, found " + describeToken(cur_), "SYNTAX_1", "the statement is incomplete");
  default:
    fail("expected an expression, found " + describeToken(cur_));
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
    fail("expected ',' or ')', found " + describeToken(cur_), "SYNTAX_1",
         cur_.pos.line != open.line ? "the '(' at line " + std::to_string(open.line) + " is still open" : "");
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
    fail("expected ',' or ']', found " + describeToken(cur_), "SYNTAX_1",
         cur_.pos.line != open.line ? "the '[' at line " + std::to_string(open.line) + " is still open" : "");
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
        fail(at(TokenKind::Comma) || at(TokenKind::RBrace)
                 ? "sets are not part of the command language"
                 : "expected ':' in the dictionary, found " + describeToken(cur_),
             at(TokenKind::Comma) || at(TokenKind::RBrace) ? "SYNTAX_12" : "SYNTAX_1");
      }
      advance();
      dict->items.push_back(std::move(key));
      dict->items.push_back(parseTest());
      if (at(TokenKind::KwFor)) {
        fail("dictionary comprehensions are not part of the command language", "SYNTAX_12");
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
      failAt(Pos{line, col, 1}, "single '}' in an f-string", "SYNTAX_15", "write '}}' for a literal brace");
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
      failAt(open, "empty expression in an f-string", "SYNTAX_15");
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
        failAt(Pos{line, col, 1}, "expected 'r' or 's' after '!' in an f-string", "SYNTAX_15");
      }
    }
    if (i < body.size() && body[i] == ':') {
      step(':');
      ++i;
      std::size_t specBegin = i;
      while (i < body.size() && body[i] != '}') {
        if (body[i] == '{') {
          failAt(Pos{line, col, 1}, "nested replacement fields in a format spec are not supported",
                 "SYNTAX_15");
        }
        step(body[i]);
        ++i;
      }
      fv->text = std::string(body.substr(specBegin, i - specBegin));
    }
    if (i >= body.size() || body[i] != '}') {
      failAt(open, "'{' in an f-string is not closed", "SYNTAX_15", "write '{{' for a literal brace");
    }
    step('}');
    ++i;
    out.items.push_back(finish(std::move(fv)));
  }
  flushLiteral();
}

// A whole input holding one expression (f-string fields, FORMULE bodies).
ExprPtr Parser::parseStandaloneExpression() {
  ExprPtr e = parseTestList();
  if (!at(TokenKind::EndOfFile)) {
    fail("unexpected " + describeToken(cur_) + " after the expression");
  }
  return e;
}

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
