// Fields of the result database: layout, partial components, per-point offsets; result steps.

#include "solver/database/Field.hpp"
#include "solver/database/Result.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(Field, NodalLayoutIsEntityMajor) {
  Field f = Field::nodal("DEPL_R", {"DX", "DY"}, 3);
  f.value(2, 1) = 5.0;
  EXPECT_EQ(f.values()[5], 5.0);
  EXPECT_EQ(f.entity(2)[1], 5.0);
  EXPECT_EQ(*f.componentIndex("DY"), 1u);
  EXPECT_FALSE(f.componentIndex("DZ").has_value());
}

TEST(Field, PartialComponents) {
  Field f = Field::nodal("DEPL_R", {"DX", "DY", "LAGS_C"}, 4);
  EXPECT_TRUE(f.defined(0, 2));
  f.setDefined(0, 2, false); // LAGS_C only on slave nodes
  EXPECT_FALSE(f.defined(0, 2));
  EXPECT_TRUE(f.defined(1, 2));
  EXPECT_TRUE(f.partial());
}

TEST(Field, PerPointOffsets) {
  Field f = Field::perPoint(FieldSupport::GaussPoint, "SIEF_R", {"SIXX", "SIYY"}, {4, 0, 9});
  EXPECT_EQ(f.entityCount(), 13u);
  EXPECT_EQ(f.cellCount(), 3u);
  EXPECT_EQ(f.pointCount(1), 0);
  EXPECT_EQ(f.firstPoint(2), 4u);
}

TEST(Result, StepsByTimeAndNumber) {
  Result r;
  r.addStep(0.0);
  r.addStep(0.5);
  r.addStep(1.0);
  EXPECT_EQ(r.stepAtTime(0.5)->number, 1);
  EXPECT_EQ(r.stepAtTime(1.0 + 1e-9)->number, 2);
  EXPECT_EQ(r.stepAtTime(0.7), nullptr);
  EXPECT_DOUBLE_EQ(r.stepNumber(2)->time, 1.0);
}

} // namespace
} // namespace stella
