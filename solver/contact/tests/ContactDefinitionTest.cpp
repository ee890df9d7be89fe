// DEFI_CONTACT's definition: keywords read into the ContactDefinition, and the definition-time
// checks (unknown group, shared master/slave nodes, overlapping slave surfaces, inward normals).

#include "solver/contact/ContactDefinition.hpp"
#include "catalog/KeywordTree.hpp"
#include "catalog/tests/CatalogRun.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/inputs/ContactReader.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <gtest/gtest.h>

namespace stella::contact {
namespace {

// DEFI_CONTACT's keyword tree as the catalogue validates it (defaults filled in active blocks),
// from the keywords of the call after MODELE=: the reader reads what validation gives it.
KeywordTree definitionTree(const std::string& keywords) {
  auto r = catalog_test::run("CONT = DEFI_CONTACT(MODELE=MO, " + keywords + ")\n");
  EXPECT_TRUE(catalog_test::valid(*r));
  EXPECT_EQ(r->handler.calls.back().first, "DEFI_CONTACT");
  return r->last().keywords;
}

std::string zone(const std::string& master, const std::string& slave, const std::string& extra = "") {
  return "_F(GROUP_MA_MAIT='" + master + "', GROUP_MA_ESCL='" + slave + "'" + (extra.empty() ? "" : ", ") +
         extra + ")";
}

std::shared_ptr<const Mesh> blocks(double gap) {
  return std::make_shared<const Mesh>(testing::twoBlocks(CellType::QUAD4, 2, 3, gap));
}

std::string errorId(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.first().id + ": " + e.first().message;
  }
  return "";
}

TEST(ContactDefinition, ReadsZonesAndGlobalSettings) {
  auto kw =
      definitionTree("FORMULATION='DISCRETE', FROTTEMENT='COULOMB', REAC_GEOM='CONTROLE', NB_ITER_GEOM=3, "
                     "RESI_ABSO=1e-5, LISSAGE='OUI', ZONE=" +
                     zone("A_YMAX", "B_YMIN",
                          "ALGO_CONT='PENALISATION', E_N=1.0e6, APPARIEMENT='NODAL', DIST_APPA=0.2, "
                          "TOLE_PROJ_EXT=0.1, COULOMB=0.3, E_T=1.0e5, COEF_MATR_FROT=0.5"));
  auto def = readContactDefinition(kw, blocks(0.0));
  ASSERT_EQ(def->zones.size(), 1u);
  const auto& z = def->zones[0];
  EXPECT_EQ(z.algorithm, ContactAlgorithm::Penalty);
  EXPECT_EQ(z.normalPenalty, 1.0e6);
  EXPECT_EQ(z.pairing, Pairing::Nodal);
  EXPECT_EQ(z.pairingDistance, 0.2);
  EXPECT_EQ(z.extensionTolerance, 0.1);
  EXPECT_TRUE(z.friction);
  EXPECT_EQ(z.coulomb, 0.3);
  EXPECT_EQ(z.tangentPenalty, 1.0e5);
  EXPECT_EQ(z.frictionMatrixCoefficient, 0.5);
  EXPECT_EQ(def->settings.geometricUpdate, GeometricUpdate::Controlled);
  EXPECT_EQ(def->settings.geometricIterations, 3);
  ASSERT_TRUE(def->settings.gcpTolerance.has_value());
  EXPECT_EQ(*def->settings.gcpTolerance, 1e-5);
  EXPECT_TRUE(def->settings.smoothing);
  EXPECT_NO_THROW(checkContactDefinition(*def));
}

TEST(ContactDefinition, KeepsContinueFormulation) {
  auto kw = definitionTree("FORMULATION='CONTINUE', ZONE=" +
                           zone("A_YMAX", "B_YMIN", "ALGO_CONT='LAC', CONTACT_INIT='OUI'"));
  auto def = readContactDefinition(kw, blocks(0.1));
  EXPECT_EQ(def->settings.formulation, Formulation::Continue);
  EXPECT_EQ(def->zones[0].algorithm, ContactAlgorithm::Lac);
}

TEST(ContactDefinition, UnknownGroupIsNamed) {
  auto def = readContactDefinition(definitionTree("ZONE=" + zone("A_YMAX", "B_BOTTOM")), blocks(0.1));
  const auto e = errorId([&] { checkContactDefinition(*def); });
  EXPECT_EQ(e.substr(0, 9), "CONTACT_1");
  EXPECT_NE(e.find("B_BOTTOM"), std::string::npos) << e;
}

TEST(ContactDefinition, SharedNodesAreFatalUnlessExcluded) {
  // Master and slave on the same block: A_YMAX and A_XMAX share the corner node (1, 1).
  auto def = readContactDefinition(definitionTree("ZONE=" + zone("A_YMAX", "A_XMAX")), blocks(0.1));
  const auto e = errorId([&] { checkContactDefinition(*def); });
  EXPECT_EQ(e.substr(0, 9), "CONTACT_2") << e;
  EXPECT_NE(e.find("share 1 node"), std::string::npos) << e;
  // Excluding A_XMAX's nodes on A_YMAX (group of the shared corner) lifts the error.
  auto mesh = std::make_shared<Mesh>(testing::twoBlocks(CellType::QUAD4, 2, 3, 0.1));
  mesh->setNodeGroup("CORNER", {*mesh->findNode(mesh->nodeName(2 * 3 + 2))}); // (1,1) of a 2x2 block
  auto def2 = readContactDefinition(
      definitionTree("VERI_NORM='NON', ZONE=" + zone("A_YMAX", "A_XMAX", "SANS_GROUP_NO='CORNER'")), mesh);
  def2->settings.checkNormals = false;
  EXPECT_NO_THROW(checkContactDefinition(*def2));
}

TEST(ContactDefinition, SlaveSurfacesOfZonesMustBeDisjoint) {
  auto def = readContactDefinition(
      definitionTree("ZONE=(" + zone("A_YMAX", "B_YMIN") + ", " + zone("A_XMAX", "B_YMIN") + ")"),
      blocks(0.1));
  const auto e = errorId([&] { checkContactDefinition(*def); });
  EXPECT_EQ(e.substr(0, 9), "CONTACT_3") << e;
  EXPECT_NE(e.find("B_YMIN"), std::string::npos) << e;
}

TEST(ContactDefinition, InwardNormalsPointToOrientation) {
  auto mesh = std::make_shared<Mesh>(testing::twoBlocks(CellType::QUAD4, 2, 3, 0.1));
  // Reverse the first edge of B_YMIN.
  const CellId c = mesh->cellGroup("B_YMIN")->front();
  auto nodes = mesh->mutableCellNodes(c);
  std::swap(nodes[0], nodes[1]);
  auto def = readContactDefinition(definitionTree("ZONE=" + zone("A_YMAX", "B_YMIN")), mesh);
  const auto e = errorId([&] { checkContactDefinition(*def); });
  EXPECT_EQ(e.substr(0, 9), "CONTACT_5") << e;
  EXPECT_NE(e.find("B_YMIN"), std::string::npos) << e;
  def->settings.checkNormals = false;
  EXPECT_NO_THROW(checkContactDefinition(*def));
}

// A 2D mesh whose cells are numbered clockwise (as Salome writes them), contact edges as the
// mesher left them: after ORIE_PEAU on both groups, VERI_NORM accepts them (one definition of
// "outward"), and the normals point out of each block (A_YMAX +y, B_YMIN -y).
TEST(ContactDefinition, OrientedSkinOfClockwiseCellsPassesVeriNorm) {
  for (const CellType t : {CellType::QUAD4, CellType::QUAD8, CellType::TRIA3, CellType::TRIA6}) {
    auto mesh = std::make_shared<Mesh>(testing::twoBlocks(t, 2, 3, 0.1));
    for (CellId c = 0; c < mesh->cellCount(); ++c) {
      if (info(mesh->cellType(c)).dimension == 2) {
        reverseCell(*mesh, c);
      }
    }
    reverseCell(*mesh, mesh->cellGroup("A_YMAX")->front()); // one edge mis-oriented
    for (const char* g : {"A_YMAX", "B_YMIN"}) {
      orientSkin(*mesh, *mesh->cellGroup(g), {});
    }
    auto def = readContactDefinition(definitionTree("ZONE=" + zone("A_YMAX", "B_YMIN")), mesh);
    EXPECT_NO_THROW(checkContactDefinition(*def)) << name(t);
    for (const CellId c : *mesh->cellGroup("A_YMAX")) {
      EXPECT_GT(cellNormal(*mesh, c)[1], 0.0) << name(t);
    }
    for (const CellId c : *mesh->cellGroup("B_YMIN")) {
      EXPECT_LT(cellNormal(*mesh, c)[1], 0.0) << name(t);
    }
  }
}

TEST(ContactDefinition, ThreeDimensionalFacesAccepted) {
  auto mesh = std::make_shared<const Mesh>(testing::twoBlocks(CellType::HEXA8, 2, 2, 0.0));
  auto def = readContactDefinition(definitionTree("ZONE=" + zone("A_ZMAX", "B_ZMIN")), mesh);
  EXPECT_NO_THROW(checkContactDefinition(*def));
  EXPECT_EQ(zoneSlaveNodes(*mesh, def->zones[0]).size(), 9u);
}

} // namespace
} // namespace stella::contact
