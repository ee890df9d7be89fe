// RealFormula: FORMULE(VALE='...', NOM_PARA=(...)) compiled to a small stack bytecode over
// doubles, evaluated per node and per time step. Constants are folded at compile time; domain
// errors (division by zero, sqrt of a negative number...) are reported with the formula, the
// place inside it and the parameter values.
#include "EmbeddedText.hpp"
#include "Interpreter.hpp"
#include "Parser.hpp"
#include "Suggest.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <unordered_map>

namespace stella {

namespace {

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

const std::unordered_map<std::string, Fn1>& unaryFunctions() {
  static const std::unordered_map<std::string, Fn1> table = {
      {"sqrt", Fn1::Sqrt}, {"exp", Fn1::Exp},     {"log", Fn1::Log},         {"log10", Fn1::Log10},
      {"sin", Fn1::Sin},   {"cos", Fn1::Cos},     {"tan", Fn1::Tan},         {"asin", Fn1::Asin},
      {"acos", Fn1::Acos}, {"atan", Fn1::Atan},   {"sinh", Fn1::Sinh},       {"cosh", Fn1::Cosh},
      {"tanh", Fn1::Tanh}, {"abs", Fn1::Abs},     {"fabs", Fn1::Abs},        {"floor", Fn1::Floor},
      {"ceil", Fn1::Ceil}, {"trunc", Fn1::Trunc}, {"degrees", Fn1::Degrees}, {"radians", Fn1::Radians}};
  return table;
}

const std::unordered_map<std::string, Fn2>& binaryFunctions() {
  static const std::unordered_map<std::string, Fn2> table = {{"atan2", Fn2::Atan2}, {"pow", Fn2::Pow},
                                                             {"hypot", Fn2::Hypot}, {"fmod", Fn2::Fmod},
                                                             {"min", Fn2::Min},     {"max", Fn2::Max}};
  return table;
}

// Why an operation has no value, or nullptr when it has one.
const char* domainProblem(Op op, double a, double b) {
  switch (op) {
  case Op::Div:
  case Op::FloorDiv:
  case Op::Mod:
    return b == 0.0 ? "division by zero" : nullptr;
  case Op::Pow:
    if (a == 0.0 && b < 0.0) {
      return "zero raised to a negative power";
    }
    return (a < 0.0 && b != std::floor(b)) ? "negative number raised to a fractional power" : nullptr;
  default:
    return nullptr;
  }
}

const char* domainProblem1(Fn1 f, double x) {
  switch (f) {
  case Fn1::Sqrt:
    return x < 0.0 ? "square root of a negative number" : nullptr;
  case Fn1::Log:
  case Fn1::Log10:
    return x <= 0.0 ? "logarithm of a number that is not positive" : nullptr;
  case Fn1::Asin:
  case Fn1::Acos:
    return (x < -1.0 || x > 1.0) ? "asin/acos of a number outside [-1, 1]" : nullptr;
  default:
    return nullptr;
  }
}

double apply1(Fn1 f, double x) {
  switch (f) {
  case Fn1::Sqrt:
    return std::sqrt(x);
  case Fn1::Exp:
    return std::exp(x);
  case Fn1::Log:
    return std::log(x);
  case Fn1::Log10:
    return std::log10(x);
  case Fn1::Sin:
    return std::sin(x);
  case Fn1::Cos:
    return std::cos(x);
  case Fn1::Tan:
    return std::tan(x);
  case Fn1::Asin:
    return std::asin(x);
  case Fn1::Acos:
    return std::acos(x);
  case Fn1::Atan:
    return std::atan(x);
  case Fn1::Sinh:
    return std::sinh(x);
  case Fn1::Cosh:
    return std::cosh(x);
  case Fn1::Tanh:
    return std::tanh(x);
  case Fn1::Abs:
    return std::fabs(x);
  case Fn1::Floor:
    return std::floor(x);
  case Fn1::Ceil:
    return std::ceil(x);
  case Fn1::Trunc:
    return std::trunc(x);
  case Fn1::Degrees:
    return x * (180.0 / std::numbers::pi);
  case Fn1::Radians:
    return x * (std::numbers::pi / 180.0);
  }
  return 0.0;
}

const char* domainProblem2(Fn2 f, double a, double b) {
  switch (f) {
  case Fn2::Pow:
    return domainProblem(Op::Pow, a, b);
  case Fn2::Fmod:
    return b == 0.0 ? "fmod by zero" : nullptr;
  case Fn2::LogBase:
    if (a <= 0.0) {
      return "logarithm of a number that is not positive";
    }
    return (b <= 0.0 || b == 1.0) ? "logarithm in a base that is not positive or is 1" : nullptr;
  default:
    return nullptr;
  }
}

double apply2(Fn2 f, double a, double b) {
  switch (f) {
  case Fn2::Atan2:
    return std::atan2(a, b);
  case Fn2::Pow:
    return std::pow(a, b);
  case Fn2::Hypot:
    return std::hypot(a, b);
  case Fn2::Fmod:
    return std::fmod(a, b);
  case Fn2::Min:
    return a < b ? a : b;
  case Fn2::Max:
    return a > b ? a : b;
  case Fn2::LogBase:
    return std::log(a) / std::log(b);
  }
  return 0.0;
}

double binary(Op op, double a, double b) {
  switch (op) {
  case Op::Add:
    return a + b;
  case Op::Sub:
    return a - b;
  case Op::Mul:
    return a * b;
  case Op::Div:
    return a / b;
  case Op::FloorDiv:
    return std::floor(a / b);
  case Op::Mod: {
    double m = std::fmod(a, b);
    return (m != 0.0 && ((m < 0.0) != (b < 0.0))) ? m + b : m;
  }
  case Op::Pow:
    return std::pow(a, b);
  case Op::Lt:
    return a < b ? 1.0 : 0.0;
  case Op::Gt:
    return a > b ? 1.0 : 0.0;
  case Op::Le:
    return a <= b ? 1.0 : 0.0;
  case Op::Ge:
    return a >= b ? 1.0 : 0.0;
  case Op::Eq:
    return a == b ? 1.0 : 0.0;
  case Op::Ne:
    return a != b ? 1.0 : 0.0;
  default:
    return 0.0;
  }
}

} // namespace

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

void FormulaProgram::domainError(std::size_t pc, const std::string& what,
                                 std::span<const double> values) const {
  std::ostringstream message;
  message << "formula '" << text << "': " << what;
  if (!parameters.empty()) {
    message << " for ";
    for (std::size_t i = 0; i < parameters.size() && i < values.size(); ++i) {
      message << (i > 0 ? ", " : "") << parameters[i] << "=" << Value(values[i]).repr();
    }
  }
  Pos p = pc < positions.size() ? positions[pc] : Pos{1, 1, 1};
  SourceLocation at{embedded.file(), p.line, p.column, p.length};
  Diagnostic d = Diagnostic::fatal("FORMULA_DOMAIN", message.str(), embedded.map(at));
  if (!embedded.mapped() && embedded.origin().known()) {
    d.withNote("in the formula written at " + embedded.origin().str());
  }
  throw UserError(std::move(d.withNote("the formula has no value there; check its parameters' range")));
}

namespace {

// Compiles an expression tree into Impl::code.
class FormulaCompiler {
public:
  FormulaCompiler(FormulaProgram& impl, const std::vector<std::pair<std::string, double>>& constants)
      : impl_(impl), constants_(constants) {}

  void compile(const Expr& e) {
    expr(e);
    STELLA_ASSERT(depth_ == 1, "formula stack not balanced");
  }

private:
  [[noreturn]] void fail(const Expr& e, const std::string& message, const std::string& note = {}) {
    Diagnostic d = Diagnostic::fatal(
        "FORMULA_SYNTAX", message,
        impl_.embedded.map(SourceLocation{impl_.embedded.file(), e.pos.line, e.pos.column, e.pos.length}));
    if (!note.empty()) {
      d.withNote(note);
    }
    throw UserError(std::move(d));
  }

  void emit(Instr i, const Pos& pos, int stackEffect) {
    impl_.code.push_back(i);
    impl_.positions.push_back(pos);
    depth_ += stackEffect;
    impl_.maxStack = std::max(impl_.maxStack, depth_);
  }

  void constant(double v, const Pos& pos) { emit(Instr{Op::Const, 0, 0, v}, pos, 1); }

  bool lastTwoConstant() const {
    std::size_t n = impl_.code.size();
    return n >= 2 && impl_.code[n - 1].op == Op::Const && impl_.code[n - 2].op == Op::Const;
  }

  void binaryOp(Op op, const Pos& pos) {
    if (lastTwoConstant()) {
      double b = impl_.code.back().value;
      double a = impl_.code[impl_.code.size() - 2].value;
      double r = binary(op, a, b);
      if (domainProblem(op, a, b) == nullptr && std::isfinite(r)) {
        impl_.code.pop_back();
        impl_.positions.pop_back();
        impl_.code.back().value = r;
        --depth_;
        return;
      }
    }
    emit(Instr{op}, pos, -1);
  }

  void name(const Expr& e) {
    for (std::size_t i = 0; i < impl_.parameters.size(); ++i) {
      if (impl_.parameters[i] == e.text) {
        emit(Instr{Op::Param, 0, static_cast<std::int32_t>(i)}, e.pos, 1);
        return;
      }
    }
    for (const auto& [n, v] : constants_) {
      if (n == e.text) {
        constant(v, e.pos);
        return;
      }
    }
    if (e.text == "pi") {
      constant(std::numbers::pi, e.pos);
      return;
    }
    if (e.text == "e") {
      constant(std::numbers::e, e.pos);
      return;
    }
    std::vector<std::string> known = impl_.parameters;
    for (const auto& [n, v] : constants_) {
      known.push_back(n);
    }
    known.emplace_back("pi");
    std::string note = suggestionNote(e.text, known);
    if (note.empty()) {
      note = "a formula reads its parameters (NOM_PARA), the constants given to FORMULE, pi and e";
    }
    fail(e, "name '" + e.text + "' is not a parameter of the formula", note);
  }

  void call(const Expr& e) {
    const Expr& callee = *e.items[0];
    if (callee.kind != ExprKind::Name) {
      fail(callee, "a formula can call only math functions (sqrt, exp, sin...)");
    }
    std::size_t n = e.items.size() - 1;
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      ExprKind k = e.items[i]->kind;
      if (k == ExprKind::Keyword || k == ExprKind::Star || k == ExprKind::DoubleStar) {
        fail(*e.items[i], "math functions take positional arguments only");
      }
    }
    auto u = unaryFunctions().find(callee.text);
    if (u != unaryFunctions().end() && (n == 1 || (n == 2 && callee.text == "log"))) {
      expr(*e.items[1]);
      if (n == 2) {
        expr(*e.items[2]);
        emit(Instr{Op::Call2, static_cast<std::uint8_t>(Fn2::LogBase)}, callee.pos, -1);
        return;
      }
      if (!impl_.code.empty() && impl_.code.back().op == Op::Const &&
          domainProblem1(u->second, impl_.code.back().value) == nullptr) {
        impl_.code.back().value = apply1(u->second, impl_.code.back().value);
        return;
      }
      emit(Instr{Op::Call1, static_cast<std::uint8_t>(u->second)}, callee.pos, 0);
      return;
    }
    auto b = binaryFunctions().find(callee.text);
    bool variadic = callee.text == "min" || callee.text == "max";
    if (b != binaryFunctions().end() && (n == 2 || (variadic && n > 2))) {
      expr(*e.items[1]);
      for (std::size_t i = 2; i <= n; ++i) {
        expr(*e.items[i]);
        emit(Instr{Op::Call2, static_cast<std::uint8_t>(b->second)}, callee.pos, -1);
      }
      return;
    }
    if (u != unaryFunctions().end() || b != binaryFunctions().end()) {
      fail(callee, callee.text + "() called with " + std::to_string(n) + " arguments");
    }
    std::vector<std::string> known;
    for (const auto& [k, v] : unaryFunctions()) {
      known.push_back(k);
    }
    for (const auto& [k, v] : binaryFunctions()) {
      known.push_back(k);
    }
    std::string note = suggestionNote(callee.text, known);
    fail(callee, "'" + callee.text + "' is not a math function available in formulas",
         note.empty()
             ? "available: sqrt exp log log10 sin cos tan asin acos atan atan2 sinh cosh tanh abs fabs "
               "floor ceil pow hypot fmod min max"
             : note);
  }

  // Emits a jump whose target is patched later; returns its index.
  std::size_t jump(Op op, const Pos& pos, int stackEffect) {
    emit(Instr{op}, pos, stackEffect);
    return impl_.code.size() - 1;
  }
  void patch(std::size_t at) { impl_.code[at].arg = static_cast<std::int32_t>(impl_.code.size()); }

  void expr(const Expr& e) {
    switch (e.kind) {
    case ExprKind::Int:
      constant(static_cast<double>(e.intValue), e.pos);
      return;
    case ExprKind::Real:
      constant(e.realValue, e.pos);
      return;
    case ExprKind::True:
    case ExprKind::False:
      constant(e.kind == ExprKind::True ? 1.0 : 0.0, e.pos);
      return;
    case ExprKind::Name:
      name(e);
      return;
    case ExprKind::Unary:
      expr(*e.items[0]);
      if (static_cast<UnaryOp>(e.op) == UnaryOp::Neg) {
        if (impl_.code.back().op == Op::Const) {
          impl_.code.back().value = -impl_.code.back().value;
        } else {
          emit(Instr{Op::Neg}, e.pos, 0);
        }
      } else if (static_cast<UnaryOp>(e.op) == UnaryOp::Invert) {
        fail(e, "'~' is not a real operation");
      }
      return;
    case ExprKind::Not:
      expr(*e.items[0]);
      emit(Instr{Op::Not}, e.pos, 0);
      return;
    case ExprKind::Binary: {
      static const Op ops[] = {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::FloorDiv, Op::Mod, Op::Pow};
      auto op = static_cast<BinaryOp>(e.op);
      if (static_cast<int>(op) > static_cast<int>(BinaryOp::Pow)) {
        fail(e, std::string("operator '") + binaryOpText(op) + "' is not a real operation");
      }
      expr(*e.items[0]);
      expr(*e.items[1]);
      binaryOp(ops[static_cast<int>(op)], e.pos);
      return;
    }
    case ExprKind::Compare: {
      // a < b < c  ==  (a < b) and (b < c)
      std::vector<std::size_t> exits;
      for (std::size_t i = 0; i < e.compareCount(); ++i) {
        static const Op ops[] = {Op::Lt, Op::Gt, Op::Le, Op::Ge, Op::Eq, Op::Ne};
        auto c = static_cast<int>(e.compareOp(i));
        if (c > static_cast<int>(CompareOp::Ne)) {
          fail(e, std::string("'") + compareOpText(e.compareOp(i)) + "' is not a real comparison");
        }
        expr(*e.items[i]);
        expr(*e.items[i + 1]);
        emit(Instr{ops[c]}, e.pos, -1);
        if (i + 1 < e.compareCount()) {
          exits.push_back(jump(Op::JumpIfFalseKeep, e.pos, -1));
        }
      }
      for (std::size_t at : exits) {
        patch(at);
      }
      return;
    }
    case ExprKind::And:
    case ExprKind::Or: {
      std::vector<std::size_t> exits;
      for (std::size_t i = 0; i < e.items.size(); ++i) {
        expr(*e.items[i]);
        if (i + 1 < e.items.size()) {
          exits.push_back(
              jump(e.kind == ExprKind::And ? Op::JumpIfFalseKeep : Op::JumpIfTrueKeep, e.pos, -1));
        }
      }
      for (std::size_t at : exits) {
        patch(at);
      }
      return;
    }
    case ExprKind::Conditional: {
      expr(*e.items[1]);
      std::size_t toElse = jump(Op::JumpIfFalse, e.pos, -1);
      expr(*e.items[0]);
      std::size_t toEnd = jump(Op::Jump, e.pos, -1); // the else branch pushes the same slot again
      patch(toElse);
      expr(*e.items[2]);
      patch(toEnd);
      return;
    }
    case ExprKind::Call:
      call(e);
      return;
    default:
      fail(e, "this expression is not a real-valued formula",
           "a formula uses numbers, its parameters, + - * / ** //, comparisons and math functions");
    }
  }

  FormulaProgram& impl_;
  const std::vector<std::pair<std::string, double>>& constants_;
  int depth_ = 0;
};

} // namespace

struct RealFormula::Impl : FormulaProgram {
  using FormulaProgram::FormulaProgram;
};

RealFormula::RealFormula(const std::string& text, std::vector<std::string> parameters,
                         std::vector<std::pair<std::string, double>> constants, const SourceLocation& origin)
    : impl_(std::make_unique<Impl>(text, origin)) {
  impl_->parameters = std::move(parameters);
  ParseResult parsed = parseExpressionFile(impl_->embedded.file());
  if (!parsed.errors.empty() || parsed.module->body.empty()) {
    if (parsed.errors.empty()) {
      parsed.errors.push_back(Diagnostic::syntax("SYNTAX_1", "empty formula", origin));
    }
    throw UserError(impl_->embedded.map(std::move(parsed.errors)));
  }
  FormulaCompiler(*impl_, constants).compile(*parsed.module->body[0]->exprs[0]);
}

RealFormula::~RealFormula() = default;
RealFormula::RealFormula(RealFormula&&) noexcept = default;
RealFormula& RealFormula::operator=(RealFormula&&) noexcept = default;

const std::vector<std::string>& RealFormula::parameters() const {
  return impl_->parameters;
}

double RealFormula::operator()(std::span<const double> values) const {
  const Impl& impl = *impl_;
  if (values.size() != impl.parameters.size()) {
    throw UserError(Diagnostic::fatal(
        "FORMULA_ARGS", "formula '" + impl.text + "' takes " + std::to_string(impl.parameters.size()) +
                            " values, " + std::to_string(values.size()) + " were given"));
  }
  constexpr int smallStack = 32;
  double small[smallStack];
  std::vector<double> large;
  double* stack = small;
  if (impl.maxStack > smallStack) {
    large.resize(static_cast<std::size_t>(impl.maxStack));
    stack = large.data();
  }
  int sp = 0; // next free slot
  const Instr* code = impl.code.data();
  const std::size_t n = impl.code.size();
  for (std::size_t pc = 0; pc < n; ++pc) {
    const Instr& in = code[pc];
    switch (in.op) {
    case Op::Const:
      stack[sp++] = in.value;
      break;
    case Op::Param:
      stack[sp++] = values[static_cast<std::size_t>(in.arg)];
      break;
    case Op::Add:
      --sp;
      stack[sp - 1] += stack[sp];
      break;
    case Op::Sub:
      --sp;
      stack[sp - 1] -= stack[sp];
      break;
    case Op::Mul:
      --sp;
      stack[sp - 1] *= stack[sp];
      break;
    case Op::Div:
    case Op::FloorDiv:
    case Op::Mod:
    case Op::Pow: {
      --sp;
      double a = stack[sp - 1];
      double b = stack[sp];
      if (const char* problem = domainProblem(in.op, a, b)) {
        impl.domainError(pc, problem, values);
      }
      stack[sp - 1] = binary(in.op, a, b);
      break;
    }
    case Op::Lt:
    case Op::Gt:
    case Op::Le:
    case Op::Ge:
    case Op::Eq:
    case Op::Ne:
      --sp;
      stack[sp - 1] = binary(in.op, stack[sp - 1], stack[sp]);
      break;
    case Op::Neg:
      stack[sp - 1] = -stack[sp - 1];
      break;
    case Op::Not:
      stack[sp - 1] = stack[sp - 1] == 0.0 ? 1.0 : 0.0;
      break;
    case Op::Call1: {
      auto f = static_cast<Fn1>(in.fn);
      if (const char* problem = domainProblem1(f, stack[sp - 1])) {
        impl.domainError(pc, problem, values);
      }
      stack[sp - 1] = apply1(f, stack[sp - 1]);
      break;
    }
    case Op::Call2: {
      --sp;
      auto f = static_cast<Fn2>(in.fn);
      if (const char* problem = domainProblem2(f, stack[sp - 1], stack[sp])) {
        impl.domainError(pc, problem, values);
      }
      stack[sp - 1] = apply2(f, stack[sp - 1], stack[sp]);
      break;
    }
    case Op::JumpIfFalse:
      if (stack[--sp] == 0.0) {
        pc = static_cast<std::size_t>(in.arg) - 1;
      }
      break;
    case Op::JumpIfFalseKeep:
      if (stack[sp - 1] == 0.0) {
        pc = static_cast<std::size_t>(in.arg) - 1;
      } else {
        --sp;
      }
      break;
    case Op::JumpIfTrueKeep:
      if (stack[sp - 1] != 0.0) {
        pc = static_cast<std::size_t>(in.arg) - 1;
      } else {
        --sp;
      }
      break;
    case Op::Jump:
      pc = static_cast<std::size_t>(in.arg) - 1;
      break;
    }
  }
  double result = stack[0];
  if (!std::isfinite(result)) {
    impl.domainError(n, "the result is not a finite number (" + Value(result).repr() + ")", values);
  }
  return result;
}

} // namespace stella
