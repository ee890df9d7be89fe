// Compiles a FORMULE's expression tree to the bytecode of RealFormulaProgram.hpp, folding constants
// and reporting what is not a real-valued formula with suggestions for misspelt names.
#include "Diagnostics.hpp"
#include "RealFormulaProgram.hpp"
#include "Suggest.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace stella::formula {

namespace {

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
  // Throws catalogue entry `key` (messages/language.msg) at `e`, then `suggestion` if not empty.
  [[noreturn]] void fail(const Expr& e, std::string_view key, msg::Args args = {},
                         const std::string& suggestion = {}) {
    Diagnostic d = msg::make(
        key, args,
        impl_.embedded.map(SourceLocation{impl_.embedded.file(), e.pos.line, e.pos.column, e.pos.length}));
    if (!suggestion.empty()) {
      d.withNote(suggestion);
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
    const std::string suggestion = suggestionNote(e.text, known);
    if (suggestion.empty()) {
      fail(e, "FORMULA_SYNTAX.name", {{"name", e.text}});
    }
    fail(e, "FORMULA_SYNTAX.name_suggested", {{"name", e.text}}, suggestion);
  }

  void call(const Expr& e) {
    const Expr& callee = *e.items[0];
    if (callee.kind != ExprKind::Name) {
      fail(callee, "FORMULA_SYNTAX", {});
    }
    std::size_t n = e.items.size() - 1;
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      ExprKind k = e.items[i]->kind;
      if (k == ExprKind::Keyword || k == ExprKind::Star || k == ExprKind::DoubleStar) {
        fail(*e.items[i], "FORMULA_SYNTAX.2", {});
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
      fail(callee, "FORMULA_SYNTAX.3", {{"text", callee.text}, {"n", std::to_string(n)}});
    }
    std::vector<std::string> known;
    for (const auto& [k, v] : unaryFunctions()) {
      known.push_back(k);
    }
    for (const auto& [k, v] : binaryFunctions()) {
      known.push_back(k);
    }
    const std::string suggestion = suggestionNote(callee.text, known);
    if (suggestion.empty()) {
      fail(callee, "FORMULA_SYNTAX.function", {{"name", callee.text}});
    }
    fail(callee, "FORMULA_SYNTAX.function_suggested", {{"name", callee.text}}, suggestion);
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
        fail(e, "FORMULA_SYNTAX.4", {});
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
        fail(e, "FORMULA_SYNTAX.5", {{"binary_op_text", binaryOpText(op)}});
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
          fail(e, "FORMULA_SYNTAX.6", {{"compare_op_text", compareOpText(e.compareOp(i))}});
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
      fail(e, "FORMULA_SYNTAX.7", {});
    }
  }

  FormulaProgram& impl_;
  const std::vector<std::pair<std::string, double>>& constants_;
  int depth_ = 0;
};

} // namespace

void compileFormula(FormulaProgram& program, const Expr& e,
                    const std::vector<std::pair<std::string, double>>& constants) {
  FormulaCompiler(program, constants).compile(e);
}

} // namespace stella::formula
