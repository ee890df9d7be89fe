// The compiled form of a RealFormula, shared by its compiler (RealFormulaCompiler.cpp) and its
// evaluator (RealFormula.cpp): a small stack bytecode over doubles, with the operations' domains.
#pragma once

#include "Ast.hpp"
#include "EmbeddedText.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace stella::formula {

enum class Op : std::uint8_t {
  Const,
  Param,
  Add,
  Sub,
  Mul,
  Div,
  FloorDiv,
  Mod,
  Pow,
  Neg,
  Not,
  Lt,
  Gt,
  Le,
  Ge,
  Eq,
  Ne,
  Call1,
  Call2,
  JumpIfFalse,     // pops the condition
  JumpIfFalseKeep, // `and`: jumps keeping the value when false, else pops it
  JumpIfTrueKeep,  // `or`
  Jump
};

enum class Fn1 : std::uint8_t {
  Sqrt,
  Exp,
  Log,
  Log10,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sinh,
  Cosh,
  Tanh,
  Abs,
  Floor,
  Ceil,
  Trunc,
  Degrees,
  Radians
};
enum class Fn2 : std::uint8_t { Atan2, Pow, Hypot, Fmod, Min, Max, LogBase };

struct Instr {
  Op op;
  std::uint8_t fn = 0;
  std::int32_t arg = 0; // parameter index or jump target
  double value = 0.0;
};

// Why an operation has no value, or nullptr when it has one.
const char* domainProblem(Op op, double a, double b);
const char* domainProblem1(Fn1 f, double x);
const char* domainProblem2(Fn2 f, double a, double b);
double apply1(Fn1 f, double x);
double apply2(Fn2 f, double a, double b);
double binary(Op op, double a, double b);

struct FormulaProgram {
  std::string text;
  std::vector<std::string> parameters;
  std::vector<Instr> code;
  std::vector<Pos> positions; // of each instruction, inside the text
  int maxStack = 0;
  EmbeddedText embedded;

  FormulaProgram(const std::string& t, const SourceLocation& origin) : text(t), embedded(t, origin) {}

  [[noreturn]] void domainError(std::size_t pc, const std::string& what,
                                std::span<const double> values) const;
};

// Compiles the expression `e` into program.code, folding constants; UserError on what is not a
// real-valued formula.
void compileFormula(FormulaProgram& program, const Expr& e,
                    const std::vector<std::pair<std::string, double>>& constants);

} // namespace stella::formula
