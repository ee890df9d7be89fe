// CALC_CHAMP's derived fields on box meshes of every volume cell type:
//   - a constant stress at the Gauss points gives that stress exactly in SIEF_ELNO and SIEF_NOEU
//     (distorted meshes, 1e-12 relative);
//   - a stress linear in x gives its exact nodal values (undistorted meshes: the field is then in
//     the span of the extrapolation; one-point cells excepted);
//   - a linear displacement u = A x gives EPSI_ELGA / EPSI_NOEU = sym(A) exactly, in 3D, D_PLAN,
//     AXIS (hoop strain u_r / r) and C_PLAN (EPZZ = -nu / (1 - nu) (EPXX + EPYY));
//   - GROUP_MA restricts ELNO and NOEU to the cells of the group.

#include "solver/post/DerivedFields.hpp"

#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ShapeTable.hpp"
#include "solver/model/ModelBuilder.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella {
namespace {

std::shared_ptr<Mesh> toMesh(fem::PlainMesh p, bool distort) {
  for (int n = 0; n < p.nodeCount(); ++n) {
    auto x = p.coordinates.row(n);
    if (distort) { // smooth, small, keeps cells valid; r stays > 0 for AXIS (x >= 1)
      const double z = p.dimension == 3 ? x(2) : 0.0;
      x(0) += 0.03 * std::sin(7.0 * x(0) + 3.0 * x(1));
      x(1) += 0.03 * std::cos(5.0 * x(0) - 4.0 * x(1) + z);
    }
    x(0) += 1.0; // AXIS needs r > 0
  }
  return fem::toMesh(p);
}

using testing::modelOn;

struct Case {
  CellType type;
  std::string modelisation;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (CellType t : {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    out.push_back({t, "D_PLAN"});
    out.push_back({t, "AXIS"});
  }
  for (CellType t :
       {CellType::TETRA4, CellType::TETRA10, CellType::PENTA6, CellType::PENTA15, CellType::PYRAM5,
        CellType::PYRAM13, CellType::HEXA8, CellType::HEXA20, CellType::HEXA27}) {
    out.push_back({t, "3D"});
  }
  return out;
}

std::shared_ptr<Model> boxModel(const Case& c, bool distort) {
  return modelOn(toMesh(fem::boxMesh(c.type, {2, 2, 2}, {1.0, 1.0, 1.0}), distort), c.modelisation);
}

Field constantStress(const Model& model, const std::vector<double>& sigma) {
  Field f = zeroPointState(model, 0).stress;
  for (std::size_t e = 0; e < f.entityCount(); ++e) {
    for (std::size_t i = 0; i < f.componentCount(); ++i) {
      f.value(e, i) = sigma[i];
    }
  }
  return f;
}

TEST(DerivedFields, ConstantStressIsExactInElnoAndNoeu) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(info(c.type).name) + " " + c.modelisation);
    auto model = boxModel(c, true);
    const std::vector<double> sigma{100.0, -40.0, 25.0, 12.0, -7.0, 3.0};
    const Field elga = constantStress(*model, sigma);
    const auto cells = selectedVolumeCells(*model, {});
    const Field elno = extrapolateToCellNodes(*model, elga, cells);
    ASSERT_EQ(elno.support(), FieldSupport::CellNode);
    for (std::size_t e = 0; e < elno.entityCount(); ++e) {
      for (std::size_t i = 0; i < elno.componentCount(); ++i) {
        ASSERT_NEAR(elno.value(e, i), sigma[i], 1e-12 * 100.0) << "point " << e << " cmp " << i;
      }
    }
    const Field noeu = averageAtNodes(*model->mesh, elno);
    for (std::size_t n = 0; n < noeu.entityCount(); ++n) {
      for (std::size_t i = 0; i < noeu.componentCount(); ++i) {
        ASSERT_TRUE(noeu.defined(n, i));
        ASSERT_NEAR(noeu.value(n, i), sigma[i], 1e-12 * 100.0);
      }
    }
    const Field sieq = equivalentStressField(noeu);
    EXPECT_EQ(sieq.componentCount(), 17u);
  }
}

TEST(DerivedFields, LinearStressIsExtrapolatedExactly) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(info(c.type).name) + " " + c.modelisation);
    auto model = boxModel(c, false);
    const Mesh& mesh = *model->mesh;
    Field elga = zeroPointState(*model, 0).stress;
    if (elga.pointCount(0) == 1) {
      continue; // one Gauss point carries a constant only
    }
    // sigma_xx = 3 + 2 x - y at the physical Gauss points.
    for (CellId cell = 0; cell < mesh.cellCount(); ++cell) {
      const auto& role =
          c.modelisation == "AXIS" ? fem::IntegrationRole::AxisymmetricVolume : fem::IntegrationRole::Volume;
      const fem::ShapeTable& table = fem::shapeTable(mesh.cellType(cell), role);
      const auto nodes = mesh.cellNodes(cell);
      for (int q = 0; q < table.pointCount(); ++q) {
        double x = 0.0;
        double y = 0.0;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          const double n = table.values[static_cast<std::size_t>(q)](static_cast<Eigen::Index>(k));
          x += n * mesh.point(nodes[k])[0];
          y += n * mesh.point(nodes[k])[1];
        }
        elga.value(elga.firstPoint(static_cast<std::size_t>(cell)) + static_cast<std::size_t>(q), 0) =
            3.0 + 2.0 * x - y;
      }
    }
    const Field noeu =
        averageAtNodes(mesh, extrapolateToCellNodes(*model, elga, selectedVolumeCells(*model, {})));
    for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
      const Point3 p = mesh.point(n);
      ASSERT_NEAR(noeu.value(static_cast<std::size_t>(n), 0), 3.0 + 2.0 * p[0] - p[1], 1e-11) << "node " << n;
    }
  }
}

TEST(DerivedFields, LinearDisplacementGivesExactStrain) {
  // u = A x (+ a rigid translation); in AXIS u_r = a r, u_z = b r + c z.
  const Eigen::Matrix3d a{{1e-3, 2e-4, -3e-4}, {4e-4, -5e-4, 6e-4}, {-1e-4, 2e-4, 7e-4}};
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(info(c.type).name) + " " + c.modelisation);
    for (const std::string& modelisation :
         {c.modelisation, std::string(c.modelisation == "D_PLAN" ? "C_PLAN" : "")}) {
      if (modelisation.empty()) {
        continue;
      }
      auto model = modelOn(toMesh(fem::boxMesh(c.type, {2, 2, 2}, {1.0, 1.0, 1.0}), true), modelisation);
      const Mesh& mesh = *model->mesh;
      const int dim = model->components;
      const bool axis = modelisation == "AXIS";
      Field depl =
          Field::nodal("DEPL_R", model->componentNames(), static_cast<std::size_t>(mesh.nodeCount()));
      for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
        const Point3 p = mesh.point(n);
        const Eigen::Vector3d x(p[0], p[1], p[2]);
        Eigen::Vector3d u = a * x + Eigen::Vector3d(1e-3, -2e-3, 5e-4);
        if (axis) {
          u(0) = a(0, 0) * x(0); // no radial translation in AXIS
        }
        for (int k = 0; k < dim; ++k) {
          depl.value(static_cast<std::size_t>(n), static_cast<std::size_t>(k)) = u(k);
        }
      }
      auto steel = std::make_shared<Material>();
      steel->elastic = ElasticMaterial{200000.0, 0.3, {}, {}};
      MaterialField materials;
      materials.mesh = model->mesh;
      materials.materials.push_back(steel);
      materials.cellMaterial.assign(static_cast<std::size_t>(mesh.cellCount()), 0);
      const auto cells = selectedVolumeCells(*model, {});
      const Field epsi = strainAtGaussPoints(*model, depl, &materials, cells);
      const Eigen::Matrix3d e = 0.5 * (a + a.transpose());
      std::vector<double> expected{e(0, 0), e(1, 1), e(2, 2), e(0, 1), e(0, 2), e(1, 2)};
      if (dim == 2) {
        expected.resize(4);
        expected[2] = 0.0;
        if (axis) {
          expected[2] = a(0, 0);       // hoop strain u_r / r
          expected[3] = 0.5 * a(1, 0); // u_r does not depend on z
        }
        if (modelisation == "C_PLAN") {
          expected[2] = -0.3 / 0.7 * (e(0, 0) + e(1, 1));
        }
      }
      const Field noeu = averageAtNodes(mesh, extrapolateToCellNodes(*model, epsi, cells));
      for (const Field* f : {&epsi, &noeu}) {
        ASSERT_EQ(f->componentCount(), expected.size());
        for (std::size_t p = 0; p < f->entityCount(); ++p) {
          for (std::size_t i = 0; i < expected.size(); ++i) {
            ASSERT_NEAR(f->value(p, i), expected[i], 1e-14) << f->components()[i] << " at " << p;
          }
        }
      }
    }
  }
}

TEST(DerivedFields, GroupRestrictsElnoAndNoeu) {
  auto model = boxModel({CellType::QUAD4, "D_PLAN"}, false);
  const Mesh& mesh = *model->mesh;
  const auto cells = selectedVolumeCells(*model, {0});
  const Field elno = extrapolateToCellNodes(*model, constantStress(*model, {1, 2, 3, 4}), cells);
  EXPECT_EQ(elno.pointCount(0), 4);
  EXPECT_EQ(elno.pointCount(1), 0);
  const Field noeu = averageAtNodes(mesh, elno);
  int defined = 0;
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    defined += noeu.defined(static_cast<std::size_t>(n), 0) ? 1 : 0;
  }
  EXPECT_EQ(defined, 4);
}

} // namespace
} // namespace stella
