// CompiledExpression (block conditions, FORMULE bodies) and RealFormula (fast real evaluation).
#include "interpreter/Interpreter.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace stella {
namespace {

TEST(CompiledExpression, ResolvesNamesThroughTheLookup) {
  auto e = CompiledExpression::compile("FORMULATION == 'CONTINUE' and E_N > 1e3");
  EXPECT_EQ(e.freeNames(), (std::vector<std::string>{"FORMULATION", "E_N"}));
  auto lookup = [](const std::string& n) -> std::optional<Value> {
    if (n == "FORMULATION") {
      return Value("CONTINUE");
    }
    if (n == "E_N") {
      return Value(1e6);
    }
    return std::nullopt;
  };
  EXPECT_TRUE(e.evaluate(lookup).truthy());
  auto math = CompiledExpression::compile("sqrt(X) + cos(pi)");
  EXPECT_DOUBLE_EQ(math.evaluate([](const std::string& n) -> std::optional<Value> {
                         return n == "X" ? std::optional<Value>(Value(16.0)) : std::nullopt;
                       })
                       .asReal(),
                   3.0);
}

TEST(CompiledExpression, SyntaxErrorsPointInsideTheStringInTheCommandFile) {
  auto file = SourceFile::fromText("f.comm", "F = FORMULE(VALE='X * (Y + ', NOM_PARA='X')\n");
  SourceLocation origin{file, 1, 18, 12};
  try {
    CompiledExpression::compile("X * (Y + ", origin);
    FAIL() << "expected a UserError";
  } catch (const UserError& e) {
    const Diagnostic& d = e.diagnostics().back();
    EXPECT_EQ(d.location.file, file);
    EXPECT_EQ(d.location.line, 1);
    EXPECT_EQ(d.location.column, 28); // just after the '+', where the expression ends
  }
}

TEST(CompiledExpression, RuntimeErrorsNameTheUnknownName) {
  auto e = CompiledExpression::compile("A + B");
  try {
    e.evaluate([](const std::string& n) -> std::optional<Value> {
      return n == "A" ? std::optional<Value>(Value(1)) : std::nullopt;
    });
    FAIL();
  } catch (const UserError& err) {
    EXPECT_EQ(err.first().id, "LANG_NAME");
    EXPECT_EQ(err.first().location.column, 5);
  }
}

TEST(RealFormula, MatchesDirectEvaluation) {
  RealFormula f("A * sin(X) * exp(-Y / 2.) + X**2 - (Y if X > Y else -Y) + min(X, Y, 0.5) + 10 // 3 + 7 % 3",
                {"X", "Y"}, {{"A", 2.0}});
  for (double x : {-1.5, 0.0, 0.3, 2.0}) {
    for (double y : {-2.0, 0.25, 1.0}) {
      double expected = 2.0 * std::sin(x) * std::exp(-y / 2.0) + x * x - (x > y ? y : -y) +
                        std::min({x, y, 0.5}) + 3.0 + 1.0;
      double values[] = {x, y};
      EXPECT_NEAR(f(values), expected, 1e-14 * (1.0 + std::fabs(expected))) << x << " " << y;
    }
  }
}

TEST(RealFormula, LogicalOperatorsAndChains) {
  RealFormula f("1. if 0 < X <= 1 and not X == 0.5 or X > 10 else 0.", {"X"}, {});
  auto at = [&](double x) {
    double v[] = {x};
    return f(v);
  };
  EXPECT_EQ(at(0.25), 1.0);
  EXPECT_EQ(at(0.5), 0.0);
  EXPECT_EQ(at(1.5), 0.0);
  EXPECT_EQ(at(11.0), 1.0);
  EXPECT_EQ(at(-1.0), 0.0);
}

TEST(RealFormula, DomainErrorsNameTheFormulaAndValues) {
  RealFormula f("sqrt(X - 1.) + 1. / Y", {"X", "Y"}, {});
  double bad[] = {0.0, 1.0};
  try {
    f(bad);
    FAIL();
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "FORMULA_DOMAIN");
    EXPECT_NE(e.first().message.find("X=0.0, Y=1.0"), std::string::npos) << e.first().message;
    EXPECT_EQ(e.first().location.column, 1); // sqrt
  }
  double zero[] = {2.0, 0.0};
  EXPECT_THROW(f(zero), UserError);
  RealFormula overflow("exp(X)", {"X"}, {});
  double big[] = {1000.0};
  EXPECT_THROW(overflow(big), UserError);
}

TEST(RealFormula, UnknownNamesAreRefusedAtCompileTime) {
  try {
    RealFormula f("X + INTS", {"X", "INST"}, {});
    FAIL();
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "FORMULA_SYNTAX");
    ASSERT_FALSE(e.first().notes.empty());
    EXPECT_EQ(e.first().notes[0], "did you mean 'INST'?");
  }
  EXPECT_THROW(RealFormula("'text'", {}, {}), UserError);
  EXPECT_THROW(RealFormula("X +", {"X"}, {}), UserError);
}

TEST(RealFormula, ConstantsAreFolded) {
  RealFormula f("2 * pi * 0.5", {}, {});
  EXPECT_DOUBLE_EQ(f({}), std::numbers::pi);
}

} // namespace
} // namespace stella
