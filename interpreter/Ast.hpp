#pragma once
// The syntax tree of a command file. Every node keeps its place in the file (Pos; the file is
// the Module's). Expressions and statements are plain structs with a kind and children.

#include "Token.hpp"
#include "Value.hpp"

#include <cstdint>
#include <memory>
#include <memory_resource>
#include <string>
#include <vector>

namespace stella {

enum class ExprKind : std::uint8_t {
  Name,
  Int,
  Real,
  Imaginary,
  String,
  FString,        // items: String and FormattedValue parts
  FormattedValue, // items[0]: expression; text: format spec; op: conversion ('r', 's' or 0)
  None,
  True,
  False,
  Tuple,
  List,
  Dict,     // items: key0, value0, key1, value1...; a null key is `**mapping`
  ListComp, // items[0]: element; then CompFor nodes
  CompFor,  // items[0]: target, items[1]: iterable, then `if` conditions
  Unary,    // op: UnaryOp; items[0]
  Binary,   // op: BinaryOp; items[0], items[1]
  Compare,  // items[0..n]; compareOp(0..n-1)
  And,      // items: operands (two or more)
  Or,
  Not,
  Conditional, // items: body, test, orelse (`body if test else orelse`)
  Call,        // items[0]: callee; then arguments (plain expressions, Keyword, Star, DoubleStar)
  Keyword,     // text: name; items[0]: value (only inside Call)
  Star,        // `*args` inside Call; items[0]
  DoubleStar,  // `**kwargs` inside Call; items[0]
  Attribute,   // items[0].text
  Subscript,   // items[0][items[1]]
  Slice,       // items: lower, upper, step (each may be null)
  Lambda       // text unused; params in Lambda node: items[0] body, names in `params`
};

enum class BinaryOp : std::uint8_t {
  Add,
  Sub,
  Mul,
  Div,
  FloorDiv,
  Mod,
  Pow,
  BitAnd,
  BitOr,
  BitXor,
  LShift,
  RShift
};
enum class UnaryOp : std::uint8_t { Neg, Plus, Invert };
enum class CompareOp : std::uint8_t { Lt, Gt, Le, Ge, Eq, Ne, In, NotIn, Is, IsNot };

struct Expr;
// Expression nodes live in their Module's arena: deleting one runs its destructor only.
struct ExprDeleter {
  void operator()(Expr* e) const;
};
using ExprPtr = std::unique_ptr<Expr, ExprDeleter>;

struct Expr {
  ExprKind kind;
  std::uint8_t op = 0;
  Pos pos;
  int depth = 1;    // height of the subtree, bounded by the parser
  std::string text; // a Compare node keeps its operators here, one CompareOp per char
  union {
    std::int64_t intValue = 0; // Int
    double realValue;          // Real, Imaginary
  };
  std::pmr::vector<ExprPtr> items;

  Expr(ExprKind k, Pos p, std::pmr::memory_resource* arena) : kind(k), pos(p), items(arena) {}
  std::size_t compareCount() const { return text.size(); }
  CompareOp compareOp(std::size_t i) const { return static_cast<CompareOp>(text[i]); }
  void addCompareOp(CompareOp c) { text += static_cast<char>(c); }
};

inline void ExprDeleter::operator()(Expr* e) const {
  e->~Expr();
}

enum class StmtKind : std::uint8_t {
  Expr,      // exprs[0]
  Assign,    // exprs: target1, ..., targetN, value
  AugAssign, // op: BinaryOp; exprs: target, value
  For,       // exprs: target, iterable; body; orelse
  While,     // exprs[0]: condition; body; orelse
  If,        // exprs[0]: condition; body; orelse (an `elif` is an If alone in orelse, `elif` set)
  Pass,
  Break,
  Continue,
  Del,           // exprs: targets
  Def,           // name, params, body
  Return,        // exprs: [value]
  Import,        // imports: module (dotted), alias
  FromImport,    // module; imports: name, alias ("*" for all)
  Global,        // names in imports[i].name
  Assert,        // exprs: test, [message]
  Try,           // body; handlers (ExceptHandler); orelse: the `else:` suite; finalbody
  ExceptHandler, // exprs: [type]; name: the `as` name (may be empty); body
  Raise          // exprs: [exception] (none: re-raise the exception being handled)
};

struct Param {
  std::string name;
  Pos pos;
  ExprPtr defaultValue; // may be null
  int star = 0;         // 1 for *args, 2 for **kwargs
};

struct ImportName {
  std::string name;
  std::string alias;
  Pos pos;
};

struct Stmt;
using StmtPtr = std::unique_ptr<Stmt>;

struct Stmt {
  StmtKind kind;
  std::uint8_t op = 0;
  bool elif = false;
  Pos pos;
  int endLine = 0;
  std::vector<ExprPtr> exprs;
  std::vector<StmtPtr> body;
  std::vector<StmtPtr> orelse;
  std::vector<StmtPtr> handlers;  // Try: its `except` clauses
  std::vector<StmtPtr> finalbody; // Try: its `finally:` suite
  std::string name;               // def name; from-import module; `except ... as NAME`
  std::vector<Param> params;
  std::vector<ImportName> imports;

  Stmt(StmtKind k, Pos p) : kind(k), pos(p) {}
};

// A parsed file. Statements refer to it for their locations; user functions keep it alive.
struct Module {
  std::shared_ptr<const SourceFile> file;
  // Memory of the expression nodes (declared before `body`, so destroyed after it).
  std::unique_ptr<std::pmr::monotonic_buffer_resource> arena =
      std::make_unique<std::pmr::monotonic_buffer_resource>(4096);
  std::vector<StmtPtr> body;
};

// Text dumps of the tree. With locations: "Name MAIL @3:1"; without: the structure alone, used to
// check that the pretty-printer's output re-parses to the same tree.
std::string dumpModule(const Module& module, bool withLocations);
std::string dumpExpr(const Expr& expr, bool withLocations);

const char* binaryOpText(BinaryOp op);
const char* unaryOpText(UnaryOp op);
const char* compareOpText(CompareOp op);
int binaryPrecedence(BinaryOp op);

} // namespace stella
