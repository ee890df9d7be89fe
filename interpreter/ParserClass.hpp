#pragma once
// Internal to the parser's source files (Parser*.cpp): the recursive-descent Parser class. The
// public interface is Parser.hpp.

#include "Parser.hpp"

namespace stella::parsing {

// Thrown at a syntax error; caught at the statement level, which records the error and skips to
// the next statement.
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
      fail("SYNTAX_1.expect", {{"what", what}, {"token", describeToken(cur_)}});
    }
    Token t = std::move(cur_);
    advance();
    return t;
  }
  // Catalogue entry `key` (messages/language.msg) with `args`, at the current token or at `pos`.
  [[noreturn]] void fail(std::string_view key, msg::Args args = {}) { failAt(cur_.pos, key, args); }
  [[noreturn]] void failAt(Pos pos, std::string_view key, msg::Args args = {}) {
    Diagnostic d = msg::make(key, args, lexer_.location(pos));
    // an invalid character, or a line end after an unclosed bracket, is already reported
    if ((cur_.kind != TokenKind::Error && !cur_.recovered) || d.id != "SYNTAX_1") {
      errors_.push_back(std::move(d));
    }
    throw ParseError{};
  }
  void report(Pos pos, std::string_view key, msg::Args args = {}) {
    errors_.push_back(msg::make(key, args, lexer_.location(pos)));
  }
  void synchronize();
  void skipBlock();

  struct Nest {
    Parser& p;
    explicit Nest(Parser& parser) : p(parser) {
      if (++p.depth_ > maxParseNesting) {
        --p.depth_;
        p.fail("SYNTAX_10.nesting", {{"max", maxParseNesting}});
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
  StmtPtr parseTry();
  StmtPtr parseRaise();
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

} // namespace stella::parsing
