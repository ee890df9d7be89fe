// MESHCHECK_1 (nodes at the same position) does not count the touching nodes of two bodies that a
// DEFI_CONTACT zone joins (one node on the slave surface, the other on the master surface), and
// still counts every other coincident pair. Before, LIRE_MAILLAGE raised it for every pair, so
// that every contact study of bodies meshed touching ended <A>_ALARM.
//
// Mesh (plane strain): LOWER = [0,1]x[0,1], UPPER = [0,1]x[1,2] with its own nodes on y = 1
// (2 pairs, joined by the zone UPPER_BOT -> LOWER_TOP), and optionally SIDE = [1,2]x[-1,0],
// touching LOWER at the corner (1, 0) only (L2 = S4: 1 pair that no contact joins).

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>

namespace stella {
namespace {

Mesh touchingSquares(bool withSide) {
  Mesh m;
  m.setDimension(2);
  const auto square = [&](double x0, double y0, const std::string& name) {
    std::vector<NodeId> n;
    const std::array<std::pair<double, double>, 4> corners{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
    for (const auto& [dx, dy] : corners) {
      n.push_back(m.addNode({x0 + dx, y0 + dy, 0.0}, fmt::format("{}{}", name, n.size() + 1)));
    }
    const CellId c = m.addCell(CellType::QUAD4, n);
    return std::pair{c, n};
  };
  const auto [lower, ln] = square(0.0, 0.0, "L");
  const auto [upper, un] = square(0.0, 1.0, "U");
  const CellId top = m.addCell(CellType::SEG2, std::vector<NodeId>{ln[2], ln[3]});
  const CellId bottom = m.addCell(CellType::SEG2, std::vector<NodeId>{un[0], un[1]});
  std::vector<CellId> all{lower, upper};
  if (withSide) {
    all.push_back(square(1.0, -1.0, "S").first);
  }
  m.setCellGroup("BODIES", all);
  m.setCellGroup("LOWER_TOP", {top});
  m.setCellGroup("UPPER_BOT", {bottom});
  m.setNodeGroup("FIXED", {ln[0], ln[1]});
  return m;
}

std::string study(bool contact) {
  return std::string("DEBUT()\n"
                     "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
                     "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', "
                     "MODELISATION='D_PLAN'))\n") +
         (contact ? "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE',\n"
                    "                    ZONE=_F(GROUP_MA_MAIT='LOWER_TOP', GROUP_MA_ESCL='UPPER_BOT'))\n"
                  : "") +
         "FIN()\n";
}

TEST(CoincidentNodesContact, PairsJoinedByContactAreNotAnAlarm) {
  const auto dir = testing::tempDir("coincident_contact");
  writeAsterMesh(dir / "two.mail", touchingSquares(false), {"two squares"});
  writeAsterMesh(dir / "three.mail", touchingSquares(true), {"three squares"});

  const auto joined = testing::runComm(dir, "joined", study(true), {{20, dir / "two.mail"}});
  EXPECT_EQ(joined.diagnostic, JobDiagnostic::Ok) << joined.message;
  EXPECT_EQ(joined.message.find("MESHCHECK_1"), std::string::npos) << joined.message;

  // Without the contact, the same two pairs are an alarm, located at LIRE_MAILLAGE.
  const auto alone = testing::runComm(dir, "alone", study(false), {{20, dir / "two.mail"}});
  EXPECT_EQ(alone.diagnostic, JobDiagnostic::Alarm) << alone.message;
  EXPECT_NE(alone.message.find("2 pair(s) of nodes at the same position"), std::string::npos)
      << alone.message;
  EXPECT_NE(alone.message.find("alone.comm:2"), std::string::npos) << alone.message;

  // With the contact, the corner that SIDE shares with LOWER (joined by nothing) is still one.
  const auto side = testing::runComm(dir, "side", study(true), {{20, dir / "three.mail"}});
  EXPECT_EQ(side.diagnostic, JobDiagnostic::Alarm) << side.message;
  EXPECT_NE(side.message.find("1 pair(s) of nodes at the same position: L2=S4"), std::string::npos)
      << side.message;
}

} // namespace
} // namespace stella
