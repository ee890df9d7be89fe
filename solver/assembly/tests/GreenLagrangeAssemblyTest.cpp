// DEFORMATION='GROT_GDEP' through the volume assembly (total Lagrangian, ELAS = Saint-Venant-
// Kirchhoff), against independent references: a large rigid rotation gives zero stress and zero
// internal forces (PETIT does not); homogeneous uniaxial stretches give the closed-form PK2
// stress and force-stretch relation P = lambda S, S = Y' (lambda^2 - 1) / 2, in 3D, D_PLAN, C_PLAN
// and AXIS; the tangent equals central finite differences of the internal forces (material and
// geometric stiffness; the prediction's tangent at the start of a step too); small displacements
// give the PETIT forces to O(strain).

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/model/ModelBuilder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace stella {
namespace {

constexpr double kYoung = 1000.0;
constexpr double kNu = 0.3;
const std::array<double, 3> kLengths{1.0, 1.2, 0.8};

struct Case {
  CellType type;
  const char* modelling;
};

struct Study {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<MechanicalSystem> system;
  PointState zero;
};

Study study(const Case& k, fem::StrainMeasure measure) {
  Study s;
  const bool threeD = dimension(k.type) == 3;
  s.mesh = fem::toMesh(fem::boxMesh(k.type, {2, 2, threeD ? 2 : 1}, kLengths));
  s.model = std::make_shared<Model>(s.mesh);
  std::vector<CellId> all;
  for (CellId c = 0; c < s.mesh->cellCount(); ++c) {
    all.push_back(c);
  }
  assignModelling(*s.model, all, k.modelling, {});
  finishModel(*s.model, {});
  s.system = std::make_unique<MechanicalSystem>(
      s.model, testing::elasticMaterialOn(s.mesh, kYoung, kNu), std::vector<Excitation>{},
      std::vector<std::string>(s.model->cells.size(), "ELAS"), SourceLocation{}, nullptr,
      std::vector<fem::StrainMeasure>(s.model->cells.size(), measure));
  s.zero = zeroPointState(*s.model, s.system->behaviours().maxInternalVariables());
  return s;
}

// The displacement u(X) at every node (physical DOF vector).
Eigen::VectorXd nodal(const Study& s, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
  const DofMap& dofs = s.system->dofs();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dofs.physicalCount());
  for (NodeId n = 0; n < s.mesh->nodeCount(); ++n) {
    const Point3 p = s.mesh->point(n);
    const Eigen::Vector3d d = u(Eigen::Vector3d(p[0], p[1], p[2]));
    for (int c = 0; c < dofs.components(); ++c) {
      v(dofs.dof(n, c)) = d(c);
    }
  }
  return v;
}

// Internal forces (and tangent, end state) of the step 0 -> u.
Eigen::VectorXd forces(Study& s, const Eigen::VectorXd& u, PointState* end = nullptr,
                       Eigen::MatrixXd* tangent = nullptr) {
  const int n = s.system->dofs().physicalCount();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> t;
  s.system->assembler().run(Eigen::VectorXd::Zero(n), u, s.zero, behaviour::Option::Full,
                            {tangent != nullptr ? &t : nullptr, &f, end});
  if (tangent != nullptr) {
    *tangent = Eigen::MatrixXd(s.system->matrix(t));
  }
  return f;
}

const std::vector<Case> kAllCases{
    {CellType::QUAD4, "D_PLAN"}, {CellType::QUAD8, "D_PLAN"}, {CellType::TRIA6, "D_PLAN"},
    {CellType::QUAD4, "C_PLAN"}, {CellType::TRIA3, "C_PLAN"}, {CellType::QUAD8, "AXIS"},
    {CellType::TRIA3, "AXIS"},   {CellType::HEXA8, "3D"},     {CellType::HEXA20, "3D"},
    {CellType::TETRA10, "3D"},   {CellType::PENTA15, "3D"}};

std::string label(const Case& k) {
  return std::string(name(k.type)) + " " + k.modelling;
}

TEST(GreenLagrangeAssembly, LargeRigidRotationGivesNoStressNorForce) {
  // 3D: 1.2 rad about (1, 2, 3); 2D: 1 rad about z; plus a translation.
  const Eigen::Matrix3d r3 = Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d r2 = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (const Case& k : kAllCases) {
    if (std::string(k.modelling) == "AXIS") {
      continue; // a rotation is not an axisymmetric motion
    }
    const Eigen::Matrix3d r = dimension(k.type) == 3 ? r3 : r2;
    auto motion = [&](const Eigen::Vector3d& x) {
      return Eigen::Vector3d(r * x - x + Eigen::Vector3d(0.3, -2, 1));
    };
    Study large = study(k, fem::StrainMeasure::GreenLagrange);
    PointState end = large.zero;
    const Eigen::VectorXd f = forces(large, nodal(large, motion), &end);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-11 * kYoung) << label(k);
    for (std::size_t p = 0; p < end.stress.entityCount(); ++p) {
      for (double v : end.stress.entity(p)) {
        EXPECT_LT(std::abs(v), 1e-11 * kYoung) << label(k);
      }
    }
    Study small = study(k, fem::StrainMeasure::Small); // the same motion strains the small-strain model
    EXPECT_GT(forces(small, nodal(small, motion)).cwiseAbs().maxCoeff(), 1e-2 * kYoung) << label(k);
  }
}

// Uniaxial stress along axis `a` (x, or y = the axis in AXIS) at stretch `lambda`: the lateral
// stretch, the stress and the force-stretch relation of Saint-Venant-Kirchhoff in closed form.
void checkUniaxialStretch(const Case& k, int a, double lambda) {
  const std::string m = k.modelling;
  const double ea = 0.5 * (lambda * lambda - 1.0); // E along a
  // lateral E = -nu' ea, and S_aa = Y' ea: uniaxial stress in 3D, C_PLAN and AXIS; plane strain
  const double nuLateral = m == "D_PLAN" ? kNu / (1.0 - kNu) : kNu;
  const double young = m == "D_PLAN" ? kYoung / (1.0 - kNu * kNu) : kYoung;
  const double lateral = std::sqrt(1.0 - 2.0 * nuLateral * ea);
  Study s = study(k, fem::StrainMeasure::GreenLagrange);
  const int dim = s.system->dofs().components();
  auto motion = [&](const Eigen::Vector3d& x) {
    Eigen::Vector3d u = (lateral - 1.0) * x;
    u(a) = (lambda - 1.0) * x(a);
    if (dim == 2) {
      u(2) = 0.0;
    }
    return u;
  };
  PointState end = s.zero;
  const Eigen::VectorXd f = forces(s, nodal(s, motion), &end);
  const double saa = young * ea;
  for (std::size_t p = 0; p < end.stress.entityCount(); ++p) {
    const auto sig = end.stress.entity(p);
    for (std::size_t c = 0; c < sig.size(); ++c) {
      const double expected = static_cast<int>(c) == a ? saa : (m == "D_PLAN" && c == 2 ? kNu * saa : 0.0);
      EXPECT_NEAR(sig[c], expected, 1e-10 * kYoung) << label(k) << " point " << p << " component " << c;
    }
  }
  // P = F S: the force on the face X_a = L_a is lambda S_aa times its reference area (per unit
  // thickness in 2D, per radian in AXIS: R^2 / 2); no lateral force anywhere.
  double area = dim == 3 ? kLengths[1] * kLengths[2] : kLengths[1 - a];
  if (m == "AXIS") {
    area = 0.5 * kLengths[0] * kLengths[0];
  }
  double total = 0.0;
  for (NodeId n = 0; n < s.mesh->nodeCount(); ++n) {
    const Point3 x = s.mesh->point(n);
    for (int c = 0; c < dim; ++c) {
      const double fc = f(s.system->dofs().dof(n, c));
      if (c == a && x[static_cast<std::size_t>(a)] > kLengths[static_cast<std::size_t>(a)] - 1e-12) {
        total += fc;
      } else if (c != a || x[static_cast<std::size_t>(a)] > 1e-12) {
        EXPECT_NEAR(fc, 0.0, 1e-10 * kYoung) << label(k) << " node " << n << " component " << c;
      }
    }
  }
  EXPECT_NEAR(total, lambda * saa * area, 1e-10 * kYoung) << label(k);
}

TEST(GreenLagrangeAssembly, UniaxialStretchFollowsSaintVenantKirchhoff) {
  for (const Case& k : kAllCases) {
    const int a = std::string(k.modelling) == "AXIS" ? 1 : 0;
    checkUniaxialStretch(k, a, 1.4); // 40 % stretch
    checkUniaxialStretch(k, a, 0.7); // 30 % compression
  }
}

// A smooth displacement with strains and rotations of order `amplitude`.
Eigen::Vector3d wavy(const Eigen::Vector3d& x, double amplitude) {
  return amplitude * Eigen::Vector3d(std::sin(1.3 * x(1) + 0.4 * x(0)) + 0.5 * x(2),
                                     std::cos(0.9 * x(0)) * x(1) - x(2), 0.7 * x(0) * x(1) + std::sin(x(2)));
}

TEST(GreenLagrangeAssembly, TangentEqualsFiniteDifferencesOfTheForces) {
  for (const Case& k : kAllCases) {
    Study s = study(k, fem::StrainMeasure::GreenLagrange);
    const bool axis = std::string(k.modelling) == "AXIS";
    // AXIS: u_r must vanish on the axis (r = 0): scale it by r
    const Eigen::VectorXd u = nodal(s, [&](const Eigen::Vector3d& x) {
      Eigen::Vector3d d = wavy(x, 0.15);
      if (axis) {
        d(0) *= x(0);
      }
      return d;
    });
    Eigen::MatrixXd k0;
    PointState end = s.zero;
    forces(s, u, &end, &k0);
    const double h = 1e-6;
    const double scale = k0.cwiseAbs().maxCoeff();
    // about 40 columns, spread over every node and component (each column costs two assemblies:
    // the whole matrix took minutes under the sanitizers on the quadratic 3D cells)
    Eigen::Index stride = std::max<Eigen::Index>(1, u.size() / 40);
    while (stride > 1 && (stride % 2 == 0 || stride % 3 == 0)) { // coprime with 2 and 3: every component
      ++stride;
    }
    double worst = 0.0;
    for (Eigen::Index j = 0; j < u.size(); j += stride) {
      Eigen::VectorXd up = u, um = u;
      up(j) += h;
      um(j) -= h;
      const Eigen::VectorXd fd = (forces(s, up) - forces(s, um)) / (2.0 * h);
      worst = std::max(worst, (k0.col(j) - fd).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-6 * scale) << label(k);
    // the prediction's tangent at the start u (state `end`) is the same matrix
    std::vector<Eigen::Triplet<double>> t;
    s.system->assembler().run(u, Eigen::VectorXd::Zero(u.size()), end, behaviour::Option::PredictionTangent,
                              {&t, nullptr, nullptr});
    EXPECT_LT((Eigen::MatrixXd(s.system->matrix(t)) - k0).cwiseAbs().maxCoeff(), 1e-12 * scale) << label(k);
  }
}

TEST(GreenLagrangeAssembly, SmallDisplacementsGiveThePetitForces) {
  for (const Case& k : kAllCases) {
    Study large = study(k, fem::StrainMeasure::GreenLagrange);
    Study small = study(k, fem::StrainMeasure::Small);
    for (double amplitude : {1e-7, 1e-4}) {
      auto motion = [&](const Eigen::Vector3d& x) { return wavy(x, amplitude); };
      const Eigen::VectorXd fs = forces(small, nodal(small, motion));
      const double gap = (forces(large, nodal(large, motion)) - fs).norm() / fs.norm();
      // the difference is the quadratic part of E: O(strain), 1-10 times the amplitude here
      EXPECT_LT(gap, 20.0 * amplitude) << label(k) << " amplitude " << amplitude;
      EXPECT_GT(gap, 0.1 * amplitude) << label(k) << " amplitude " << amplitude;
    }
  }
}

} // namespace
} // namespace stella
