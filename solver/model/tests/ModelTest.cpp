// The user errors of the model layer: modelisations that no cell can carry, unknown ones,
// components the model does not have, groups the mesh does not have, nodes outside the model.

#include "interpreter/Diagnostics.hpp"
#include "solver/inputs/LoadReader.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/ModelBuilder.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace stella {
namespace {

// Two QUAD4 cells side by side, an edge group RIGHT, a free node N7 outside every cell.
std::shared_ptr<Mesh> twoQuads() {
  auto m = std::make_shared<Mesh>();
  m->setDimension(2);
  for (double y : {0.0, 1.0}) {
    for (double x : {0.0, 1.0, 2.0}) {
      m->addNode({x, y, 0.0});
    }
  }
  m->addNode({5.0, 5.0, 0.0});
  const NodeId q1[] = {0, 1, 4, 3};
  const NodeId q2[] = {1, 2, 5, 4};
  const NodeId e[] = {2, 5};
  m->setCellGroup("ALL", {m->addCell(CellType::QUAD4, q1), m->addCell(CellType::QUAD4, q2)});
  m->setCellGroup("RIGHT", {m->addCell(CellType::SEG2, e)});
  return m;
}

std::string errorId(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.diagnostics().front().id;
  }
  return "none";
}

KeywordTree occurrence(std::vector<std::pair<std::string, Value>> simples) {
  KeywordTree t;
  for (auto& [name, v] : simples) {
    t.addSimple({name, {v}, {}, false});
  }
  return t;
}

TEST(Model, AssignsVolumeAndSkinElements) {
  auto mesh = twoQuads();
  Model model(mesh);
  const std::vector<CellId> all{0, 1, 2};
  assignModelling(model, all, "D_PLAN", {});
  finishModel(model, {});
  EXPECT_EQ(model.cellsOfKind(ElementKind::Volume).size(), 2u);
  EXPECT_EQ(model.cellsOfKind(ElementKind::Skin).size(), 1u);
  EXPECT_EQ(model.components, 2);
  EXPECT_FALSE(model.nodeActive(6));
}

// 'AXIS_SI' is the AXIS modelling with the mean-dilatation volumetric strain on its volume cells.
TEST(Model, SelectiveIntegrationVariantsKeepTheModelling) {
  auto mesh = twoQuads();
  Model model(mesh);
  const std::vector<CellId> all{0, 1, 2};
  assignModelling(model, all, "AXIS_SI", {});
  finishModel(model, {});
  EXPECT_EQ(model.modelling, fem::Modelling::Axisymmetric);
  for (CellId c : model.cellsOfKind(ElementKind::Volume)) {
    EXPECT_EQ(model.cell(c).volumeStrain, fem::VolumeStrain::CellMean);
  }
  Model plain(mesh);
  assignModelling(plain, all, "D_PLAN", {});
  EXPECT_EQ(plain.cell(0).volumeStrain, fem::VolumeStrain::Pointwise);
  Model noStress(mesh);
  EXPECT_EQ(errorId([&] { assignModelling(noStress, all, "C_PLAN_SI", {}); }), "MODEL_1");
}

TEST(Model, RefusesWhatCannotBeCarried) {
  auto mesh = twoQuads();
  Model model(mesh);
  const std::vector<CellId> all{0, 1, 2};
  EXPECT_EQ(errorId([&] { assignModelling(model, all, "3D", {}); }), "MODEL_2");
  EXPECT_EQ(errorId([&] { assignModelling(model, all, "COQUE_3D", {}); }), "MODEL_1");
  EXPECT_EQ(errorId([&] { assignModelling(model, all, "DIS_T", {}); }), "MODEL_2");
  auto shifted = std::make_shared<Mesh>(*mesh);
  shifted->setPoint(0, {-0.5, 0.0, 0.0});
  Model bad(shifted);
  assignModelling(bad, all, "AXIS", {});
  EXPECT_EQ(errorId([&] { finishModel(bad, {}); }), "MODEL_5");
}

TEST(Model, LoadErrorsNameWhatIsMissing) {
  auto mesh = twoQuads();
  auto model = std::make_shared<Model>(mesh);
  const std::vector<CellId> all{0, 1, 2};
  assignModelling(*model, all, "D_PLAN", {});
  finishModel(*model, {});
  // DZ on a 2D model.
  EXPECT_EQ(errorId([&] { imposedComponents(*model, occurrence({{"DZ", Value(0.0)}})); }), "LOAD_1");
  // A rotation on a solid model.
  EXPECT_EQ(errorId([&] { imposedComponents(*model, occurrence({{"DRX", Value(0.0)}})); }), "LOAD_1");
  // A group the mesh does not have.
  EXPECT_EQ(errorId([&] {
              selectCells(*mesh, occurrence({{"GROUP_MA", Value(std::string("LEFT"))}}));
            }),
            "GROUP_1");
  EXPECT_EQ(errorId([&] {
              selectNodes(*mesh, occurrence({{"GROUP_NO", Value(std::string("RIGHT"))}}));
            }),
            "GROUP_2");
  // A node outside the model.
  EXPECT_EQ(errorId([&] {
              modelNodes(*model, occurrence({{"NOEUD", Value(std::string("N7"))}}));
            }),
            "LOAD_2");
  // Pressure on volume cells only.
  EXPECT_EQ(errorId([&] {
              MechanicalLoad load;
              load.model = model;
              KeywordTree kw;
              FactorKeyword f{"PRES_REP",
                              {occurrence({{"GROUP_MA", Value(std::string("ALL"))}, {"PRES", Value(1.0)}})},
                              {},
                              false};
              kw.addFactor(f);
              readMechanicalLoad(kw, load);
            }),
            "LOAD_3");
}

} // namespace
} // namespace stella
