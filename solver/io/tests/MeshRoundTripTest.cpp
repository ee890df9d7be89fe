// Round trips through every writer and reader: MED -> mesh -> MED keeps nodes, cells, groups and
// names; .mail and .msh keep what their format can hold; MED node orderings follow code_aster's
// tables (checked on the raw file through h5py, an independent reader).

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshConvert.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace stella {
namespace {

using testing::expectSameMesh;
using testing::tempDir;
using testing::zooMesh;

std::vector<CellType> allTypes() {
  std::vector<CellType> v;
  for (const auto& i : cellTypeTable) {
    v.push_back(i.type);
  }
  return v;
}

// The MED order of types, so that a read-back mesh has the same cell order.
std::vector<CellType> medOrderedTypes() {
  return {CellType::POI1,    CellType::SEG2,    CellType::SEG3,    CellType::SEG4,   CellType::TRIA3,
          CellType::QUAD4,   CellType::TRIA6,   CellType::TRIA7,   CellType::QUAD8,  CellType::QUAD9,
          CellType::TETRA4,  CellType::PYRAM5,  CellType::PENTA6,  CellType::HEXA8,  CellType::TETRA10,
          CellType::PYRAM13, CellType::PENTA15, CellType::PENTA18, CellType::HEXA20, CellType::HEXA27};
}

TEST(MeshRoundTrip, MedKeepsEverything) {
  const auto dir = tempDir("med_rt");
  Mesh m = zooMesh(medOrderedTypes());
  Mesh named;
  for (NodeId n = 0; n < m.nodeCount(); ++n) {
    named.addNode(m.point(n), "P" + std::to_string(n + 7));
  }
  for (CellId c = 0; c < m.cellCount(); ++c) {
    named.addCell(m.cellType(c), m.cellNodes(c), "C" + std::to_string(c + 3));
  }
  for (const auto& [g, ids] : m.cellGroups()) {
    named.setCellGroup(g, ids);
  }
  named.setNodeGroup("FIRST", *m.nodeGroup("FIRST"));
  named.setName("ZOO");
  writeMedMesh(dir / "zoo.med", named);
  const Mesh back = readMedMesh(dir / "zoo.med");
  EXPECT_EQ(back.name(), "ZOO");
  expectSameMesh(named, back);
  // Again: MED -> mesh -> MED -> mesh.
  writeMedMesh(dir / "zoo2.med", back);
  expectSameMesh(named, readMedMesh(dir / "zoo2.med"));
}

TEST(MeshRoundTrip, MedReordersCellsByTypeButKeepsNames) {
  const auto dir = tempDir("med_order");
  const Mesh m = zooMesh(allTypes()); // not in MED order
  writeMedMesh(dir / "zoo.med", m, "Z");
  const Mesh back = readMedMesh(dir / "zoo.med");
  ASSERT_EQ(back.cellCount(), m.cellCount());
  for (CellId c = 0; c < m.cellCount(); ++c) {
    const auto id = back.findCell(m.cellName(c));
    ASSERT_TRUE(id.has_value()) << m.cellName(c);
    EXPECT_EQ(back.cellType(*id), m.cellType(c));
    const auto a = m.cellNodes(c);
    const auto b = back.cellNodes(*id);
    EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
  }
  EXPECT_EQ(back.cellGroup("ALL")->size(), m.cellGroup("ALL")->size());
}

TEST(MeshRoundTrip, MedFileUsesCodeAsterPermutations) {
  // A single HEXA8 in code_aster order 0..7 is stored in MED as 1 4 3 2 5 8 7 6 (lrmtyp);
  // read the raw connectivity with h5py.
  const auto dir = tempDir("med_perm");
  const Mesh m = zooMesh({CellType::HEXA8, CellType::TETRA4});
  writeMedMesh(dir / "h.med", m, "H");
  const auto script = dir / "read.py";
  std::ofstream(script) << "import h5py,sys\n"
                           "f=h5py.File(sys.argv[1],'r')\n"
                           "g=f['ENS_MAA/H']\n"
                           "k=list(g.keys())[0]\n"
                           "h=g[k]['MAI']['HE8']['NOD'][()]\n"
                           "t=g[k]['MAI']['TE4']['NOD'][()]\n"
                           "print(' '.join(str(int(v)) for v in list(h)+list(t)))\n";
  const auto out = dir / "out.txt";
  const std::string cmd =
      "/usr/bin/python3 " + script.string() + " " + (dir / "h.med").string() + " > " + out.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(out);
  std::vector<int> v;
  for (int x; in >> x;) {
    v.push_back(x);
  }
  // HEXA8 nodes 1..8, TETRA4 nodes 9..12 (MED stores connectivity by node, one cell each).
  EXPECT_EQ(v, (std::vector<int>{1, 4, 3, 2, 5, 8, 7, 6, 9, 11, 10, 12}));
}

TEST(MeshRoundTrip, AsterMailKeepsEverything) {
  const auto dir = tempDir("mail_rt");
  const Mesh m = zooMesh(allTypes());
  writeAsterMesh(dir / "zoo.mail", m);
  expectSameMesh(m, readAsterMesh(dir / "zoo.mail"));
}

TEST(MeshRoundTrip, GmshKeepsCellsAndGroups) {
  const auto dir = tempDir("msh_rt");
  auto types = allTypes();
  std::erase(types, CellType::TRIA7); // no Gmsh equivalent
  const Mesh m = zooMesh(types);
  writeGmshMesh(dir / "zoo.msh", m);
  const Mesh back = readGmshMesh(dir / "zoo.msh");
  ASSERT_EQ(back.cellCount(), m.cellCount());
  for (CellId c = 0; c < m.cellCount(); ++c) {
    const auto a = m.cellNodes(c);
    const auto b = back.cellNodes(c);
    EXPECT_EQ(back.cellType(c), m.cellType(c));
    EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin())) << name(m.cellType(c));
  }
  auto groups = m.cellGroups();
  std::erase_if(groups, [](const auto& g) { return g.second.empty(); }); // Gmsh cannot hold them
  EXPECT_EQ(back.cellGroups(), groups);
  // Gmsh node groups are made from the cells of each physical group.
  EXPECT_EQ(*back.nodeGroup("ALL"), m.nodesOfCells(*m.cellGroup("ALL")));
}

TEST(MeshRoundTrip, ConvertByExtension) {
  const auto dir = tempDir("convert");
  const Mesh m = zooMesh({CellType::QUAD4, CellType::SEG2});
  writeGmshMesh(dir / "a.msh", m);
  convertMesh((dir / "a.msh").string(), (dir / "a.med").string());
  const Mesh back = readMedMesh(dir / "a.med");
  EXPECT_EQ(back.cellCount(), 2);
  EXPECT_EQ(*back.cellGroup("ALL"), (std::vector<CellId>{0, 1}));
  try {
    convertMesh((dir / "a.msh").string(), (dir / "a.xyz").string());
    FAIL() << "expected an error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "MESHCONV_1");
  }
}

TEST(MeshRoundTrip, MultipleMeshesAndNomMed) {
  const auto dir = tempDir("multi");
  writeMedMesh(dir / "two.med", zooMesh({CellType::QUAD4}), "FIRST");
  writeMedMesh(dir / "two.med", zooMesh({CellType::HEXA8, CellType::TRIA3}), "SECOND", true);
  EXPECT_EQ(medMeshNames(dir / "two.med"), (std::vector<std::string>{"FIRST", "SECOND"}));
  EXPECT_EQ(readMedMesh(dir / "two.med").cellCount(), 1);
  EXPECT_EQ(readMedMesh(dir / "two.med", "SECOND").cellCount(), 2);
  try {
    readMedMesh(dir / "two.med", "THIRD");
    FAIL() << "expected an error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "MESHFILE_6");
    EXPECT_NE(e.first().notes.at(0).find("SECOND"), std::string::npos);
  }
}

} // namespace
} // namespace stella
