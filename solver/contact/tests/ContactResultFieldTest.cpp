// CONT_NOEU: components, sign conventions, partial support on slave nodes, RESOLUTION='NON'
// gaps equal to the geometric gaps.

#include "solver/contact/ContactResultField.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"

#include <gtest/gtest.h>

namespace stella::contact {
namespace {

std::vector<ContactLink> flatLinks(const Mesh& mesh) {
  ContactZone z;
  z.masterGroup = "A_YMAX";
  z.slaveGroup = "B_YMIN";
  PairingOptions o;
  o.dimension = 2;
  return pairZone(mesh, meshPositions(mesh, nullptr), 0, z, o);
}

std::size_t cmp(const Field& f, const char* name) {
  return *f.componentIndex(name);
}

TEST(ContNoeu, ComponentsInReferenceOrder) {
  const auto& c = contNoeuComponents();
  ASSERT_EQ(c.size(), 30u);
  EXPECT_EQ(c.front(), "CONT");
  EXPECT_EQ(c[1], "JEU");
  EXPECT_EQ(c[18], "R");
  EXPECT_EQ(c.back(), "PROJ_Z");
}

TEST(ContNoeu, MeasuredGapsOnlyWhenNotResolved) {
  // Block B interpenetrates block A by 0.01: every slave node reports JEU = -0.01, no force.
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 3, -0.01);
  const auto links = flatLinks(mesh);
  const Field f =
      buildContNoeu(static_cast<std::size_t>(mesh.nodeCount()), links, measuredGaps(links), false);
  EXPECT_TRUE(f.partial());
  int defined = 0;
  for (std::size_t n = 0; n < f.entityCount(); ++n) {
    defined += f.defined(n, 0) ? 1 : 0;
  }
  EXPECT_EQ(defined, 4);
  for (const auto& l : links) {
    const auto n = static_cast<std::size_t>(l.slave);
    EXPECT_DOUBLE_EQ(f.value(n, cmp(f, "JEU")), l.gap);
    EXPECT_NEAR(f.value(n, cmp(f, "JEU")), -0.01, 1e-14);
    EXPECT_EQ(f.value(n, cmp(f, "CONT")), 0.0);
    EXPECT_EQ(f.value(n, cmp(f, "RN")), 0.0);
    EXPECT_NEAR(f.value(n, cmp(f, "PROJ_Y")), 1.0, 1e-14);
    EXPECT_NEAR(f.value(n, cmp(f, "PROJ_X")), mesh.point(l.slave)[0], 1e-14);
  }
}

TEST(ContNoeu, ForcesAndStatuses) {
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 1, 0.0);
  auto links = flatLinks(mesh); // two slave nodes
  ASSERT_EQ(links.size(), 2u);
  std::vector<LinkState> states(2);
  states[0].status = LinkStatus::Sticking;
  states[0].normalForce = 10.0;
  states[0].friction = {-2.0, 0.0};
  states[0].slip = {1e-4, 0.0};
  states[1].status = LinkStatus::Sliding;
  states[1].normalForce = 5.0;
  states[1].friction = {1.5, 0.0};
  states[1].slip = {-0.02, 0.0};
  const Field f = buildContNoeu(static_cast<std::size_t>(mesh.nodeCount()), links, states, true);
  const auto n0 = static_cast<std::size_t>(links[0].slave);
  const auto n1 = static_cast<std::size_t>(links[1].slave);
  const double t1x = links[0].tangent1[0]; // +-1
  EXPECT_EQ(f.value(n0, cmp(f, "CONT")), 1.0);
  EXPECT_EQ(f.value(n1, cmp(f, "CONT")), 2.0);
  EXPECT_NEAR(f.value(n0, cmp(f, "RNY")), 10.0, 1e-14); // master normal +y pushes the slave up
  EXPECT_NEAR(f.value(n0, cmp(f, "RN")), 10.0, 1e-14);
  EXPECT_NEAR(f.value(n0, cmp(f, "RTAX")), -2.0 * t1x, 1e-14);
  EXPECT_EQ(f.value(n0, cmp(f, "RTGX")), 0.0);
  EXPECT_NEAR(f.value(n1, cmp(f, "RTGX")), 1.5 * t1x, 1e-14);
  EXPECT_EQ(f.value(n1, cmp(f, "RTAX")), 0.0);
  EXPECT_NEAR(f.value(n0, cmp(f, "R")), std::hypot(10.0, 2.0), 1e-12);
  EXPECT_NEAR(f.value(n1, cmp(f, "GLI")), 0.02, 1e-14);
  // Without friction an active link is CONT = 2 and no tangential force is written.
  const Field g = buildContNoeu(static_cast<std::size_t>(mesh.nodeCount()), links, states, false);
  EXPECT_EQ(g.value(n0, cmp(g, "CONT")), 2.0);
  EXPECT_EQ(g.value(n0, cmp(g, "RTAX")), 0.0);
  EXPECT_NEAR(g.value(n0, cmp(g, "R")), 10.0, 1e-14);
}

TEST(ContNoeu, UnpairedNodeIsMinusOne) {
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 1, 0.5);
  auto links = flatLinks(mesh);
  links[0].paired = false;
  const Field f =
      buildContNoeu(static_cast<std::size_t>(mesh.nodeCount()), links, measuredGaps(links), false);
  EXPECT_EQ(f.value(static_cast<std::size_t>(links[0].slave), 0), -1.0);
}

} // namespace
} // namespace stella::contact
