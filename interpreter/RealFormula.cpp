// RealFormula: FORMULE(VALE='...', NOM_PARA=(...)) compiled to a small stack bytecode over
// doubles, evaluated per node and per time step. Constants are folded at compile time; domain
// errors (division by zero, sqrt of a negative number...) are reported with the formula, the
// place inside it and the parameter values.
// The compiler is in RealFormulaCompiler.cpp.
#include "EmbeddedText.hpp"
#include "Interpreter.hpp"
#include "Parser.hpp"
#include "RealFormulaProgram.hpp"
#include "messages/Messages.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace stella {

namespace formula {

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

void FormulaProgram::domainError(std::size_t pc, const std::string& what,
                                 std::span<const double> values) const {
  std::ostringstream shown; // X=1.5, Y=2.0
  for (std::size_t i = 0; i < parameters.size() && i < values.size(); ++i) {
    shown << (i > 0 ? ", " : "") << parameters[i] << "=" << Value(values[i]).repr();
  }
  Pos p = pc < positions.size() ? positions[pc] : Pos{1, 1, 1};
  SourceLocation at{embedded.file(), p.line, p.column, p.length};
  Diagnostic d =
      parameters.empty()
          ? msg::make("FORMULA_DOMAIN", {{"formula", text}, {"what", what}}, embedded.map(at))
          : msg::make("FORMULA_DOMAIN.values", {{"formula", text}, {"what", what}, {"values", shown.str()}},
                      embedded.map(at));
  if (!embedded.mapped() && embedded.origin().known()) {
    d.withNote(msg::text("FORMULA_DOMAIN.n2", {{"origin", embedded.origin().str()}}));
  }
  throw UserError(std::move(d.withNote(msg::text("FORMULA_DOMAIN.n1"))));
}

} // namespace formula

using namespace formula;

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
      parsed.errors.push_back(msg::make("SYNTAX_1.2", {}, origin));
    }
    throw UserError(impl_->embedded.map(std::move(parsed.errors)));
  }
  compileFormula(*impl_, *parsed.module->body[0]->exprs[0], constants);
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
    throw UserError(msg::make("FORMULA_ARGS", {{"text", impl.text},
                                               {"parameters_count", std::to_string(impl.parameters.size())},
                                               {"values_count", std::to_string(values.size())}}));
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
