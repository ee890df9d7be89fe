// Tabulated functions: interpolation, extensions, and a clean error outside the domain.

#include "solver/functions/RealFunction.hpp"

#include "interpreter/Diagnostics.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(TabulatedFunction, LinearInterpolation) {
  TabulatedFunction f("INST", {0.0, 1.0, 3.0}, {0.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
  EXPECT_DOUBLE_EQ(f(1.0), 2.0);
  EXPECT_DOUBLE_EQ(f(2.0), 2.5);
  EXPECT_DOUBLE_EQ(f(3.0), 3.0);
}

TEST(TabulatedFunction, Extensions) {
  TabulatedFunction f("INST", {0.0, 1.0}, {1.0, 3.0});
  f.left = Extension::Constant;
  f.right = Extension::Linear;
  EXPECT_DOUBLE_EQ(f(-5.0), 1.0);
  EXPECT_DOUBLE_EQ(f(2.0), 5.0);
}

TEST(TabulatedFunction, ExcludedOutsideDomainIsAUserError) {
  TabulatedFunction f("INST", {0.0, 1.0}, {0.0, 1.0});
  f.name = "RAMPE";
  try {
    f(1.5);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "FUNCTION_1");
    EXPECT_NE(e.first().message.find("RAMPE"), std::string::npos);
    EXPECT_NE(e.first().notes.front().find("PROL_DROITE"), std::string::npos);
  }
}

TEST(TabulatedFunction, LogLogInterpolationIsAPowerLaw) {
  TabulatedFunction f("X", {1.0, 100.0}, {1.0, 10000.0}); // y = x^2
  f.logX = true;
  f.logY = true;
  EXPECT_NEAR(f(10.0), 100.0, 1e-9);
}

} // namespace
} // namespace stella
