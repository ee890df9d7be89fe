// Single-DOF relations (DDL_IMPO) eliminated by the SaddleSolver instead of dualised: the same
// displacements and multipliers as the dualised system (the former path), an SPD matrix when no
// other relation needs a multiplier, and a multiplier row kept only for the relations that need one.

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/model/ModelBuilder.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

struct Study {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<MechanicalSystem> system;
  int relationsNeedingMultiplier = 0;
};

// HEXA8 box [0,1]x[0,1.2]x[0,0.8]: DDL_IMPO on x = 0 (DX = 1e-4 written 2 DX = 2e-4, DY = DZ = 0),
// FY = 1 and FX = 1 on x = 1. `mixed` adds relations that must keep a multiplier: a LIAISON_DDL
// DY(a) - DY(b) = 0 on x = 1, a DDL_IMPO DZ(a) = 1e-5 with LIAISON_DDL DZ(a) - DZ(b) = 0 on the same
// DOF, and a LIAISON_DDL DX(c) - DX(d) = 0 where d is also eliminated by AFFE_CHAR_CINE.
Study study(bool mixed) {
  Study s;
  const fem::PlainMesh p = fem::boxMesh(CellType::HEXA8, {3, 4, 3}, {1.0, 1.2, 0.8});
  s.mesh = std::make_shared<Mesh>();
  s.mesh->setDimension(3);
  for (int i = 0; i < p.nodeCount(); ++i) {
    s.mesh->addNode({p.coordinates(i, 0), p.coordinates(i, 1), p.coordinates(i, 2)});
  }
  for (int c = 0; c < p.cellCount(); ++c) {
    s.mesh->addCell(p.cellType,
                    std::span<const NodeId>(p.cell(c), static_cast<std::size_t>(p.nodesPerCell())));
  }
  s.model = std::make_shared<Model>(s.mesh);
  std::vector<CellId> all;
  for (CellId c = 0; c < s.mesh->cellCount(); ++c) {
    all.push_back(c);
  }
  assignModelling(*s.model, all, "3D", {});
  finishModel(*s.model, {});
  auto load = std::make_shared<MechanicalLoad>();
  load->model = s.model;
  auto kin = std::make_shared<KinematicLoad>();
  kin->model = s.model;
  std::vector<NodeId> right;
  for (NodeId node = 0; node < s.mesh->nodeCount(); ++node) {
    const Point3 x = s.mesh->point(node);
    if (x[0] < 1e-12) {
      load->relations.push_back({{{node, 0, 2.0}}, 2e-4, "DDL_IMPO"});
      load->relations.push_back({{{node, 1, 1.0}}, 0.0, "DDL_IMPO"});
      load->relations.push_back({{{node, 2, 1.0}}, 0.0, "DDL_IMPO"});
    } else if (x[0] > 1.0 - 1e-12) {
      load->nodalForces.push_back({node, 1, 1.0});
      load->nodalForces.push_back({node, 0, 1.0});
      right.push_back(node);
    }
  }
  std::vector<Excitation> ex{{load, nullptr, nullptr}};
  if (mixed) {
    const NodeId a = right[0];
    const NodeId b = right[5];
    const NodeId c = right[7];
    const NodeId d = right[9];
    load->relations.push_back({{{a, 1, 1.0}, {b, 1, -1.0}}, 0.0, "LIAISON_DDL"});
    load->relations.push_back({{{a, 2, 1.0}}, 1e-5, "DDL_IMPO"});
    load->relations.push_back({{{a, 2, 1.0}, {b, 2, -1.0}}, 0.0, "LIAISON_DDL"});
    load->relations.push_back({{{c, 0, 1.0}, {d, 0, -1.0}}, 0.0, "LIAISON_DDL"});
    kin->imposed.push_back({d, 0, 2e-5});
    ex.push_back({nullptr, kin, nullptr});
    s.relationsNeedingMultiplier = 4;
  }
  auto material = std::make_shared<Material>();
  material->name = "STEEL";
  material->elastic = ElasticMaterial{210000.0, 0.3, {}, {}};
  auto field = std::make_shared<MaterialField>();
  field->mesh = s.mesh;
  field->materials.push_back(material);
  field->cellMaterial.assign(static_cast<std::size_t>(s.mesh->cellCount()), 0);
  s.system = std::make_unique<MechanicalSystem>(
      s.model, field, ex, std::vector<std::string>(s.model->cells.size(), "ELAS"), SourceLocation{});
  return s;
}

struct Solution {
  Eigen::VectorXd u;
  Eigen::VectorXd lambda;
  Eigen::VectorXd residual; // K u + C^T lambda - f, zero at the AFFE_CHAR_CINE DOFs
  Eigen::VectorXd gap;      // C u - g
  int bordered = 0;
  std::string backend;
};

Solution solve(bool mixed, bool condense, const char* method) {
  Study s = study(mixed);
  MechanicalSystem& system = *s.system;
  linalg::SolverOptions o;
  o.method = *linalg::solverMethodFromName(method);
  system.solver().setOptions(o);
  system.solver().condenseSingleDofRelations(condense);
  const int n = system.dofs().physicalCount();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  StiffnessMatrix& k = system.stiffness(true);
  system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                         {nullptr, nullptr, nullptr, &k});
  const Eigen::VectorXd f = system.externalForces(0.0);
  const Eigen::VectorXd g = system.relationValues(0.0);
  const Eigen::VectorXd p = system.eliminatedValues(0.0);
  system.solver().factorize(k);
  Solution out;
  system.solver().solve(f, g, p, out.u, out.lambda);
  const Eigen::SparseMatrix<double> kk = k.toEigen();
  const Eigen::SparseMatrix<double> full = kk.selfadjointView<Eigen::Upper>();
  out.residual = full * out.u + system.solver().transposeTimes(out.lambda) - f;
  for (int i = 0; i < n; ++i) {
    if (system.solver().eliminated()[static_cast<std::size_t>(i)]) {
      out.residual(i) = 0.0;
    }
  }
  out.gap = system.solver().times(out.u) - g;
  out.bordered = system.solver().borderedRelationCount();
  out.backend = system.solver().backendName();
  EXPECT_EQ(out.lambda.size(), system.relationCount());
  return out;
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(DirichletElimination, SameDisplacementsAndMultipliersAsTheDualisedSystem) {
  for (const char* method : {"MUMPS", "MULT_FRONT"}) {
    for (bool mixed : {false, true}) {
      const Solution dualised = solve(mixed, false, method);
      const Solution eliminated = solve(mixed, true, method);
      const int expected = mixed ? 4 : 0;
      EXPECT_GT(dualised.bordered, expected) << method;
      EXPECT_EQ(eliminated.bordered, expected) << method << " mixed " << mixed;
      EXPECT_LE(relative(eliminated.u, dualised.u), 1e-10) << method << " mixed " << mixed;
      EXPECT_LE(relative(eliminated.lambda, dualised.lambda), 1e-10) << method << " mixed " << mixed;
      // and the solution satisfies the dualised equations (the reactions balance the forces)
      EXPECT_LE(eliminated.residual.cwiseAbs().maxCoeff(), 1e-9 * eliminated.lambda.cwiseAbs().maxCoeff())
          << method << " mixed " << mixed;
      EXPECT_LE(eliminated.gap.cwiseAbs().maxCoeff(), 1e-12 * eliminated.u.cwiseAbs().maxCoeff())
          << method << " mixed " << mixed;
    }
  }
}

TEST(DirichletElimination, OnlyDdlImpoGivesTheSpdFactorisation) {
  // MULT_FRONT: CHOLMOD for an SPD matrix, UMFPACK (LU) for the dualised one
  const Solution dualised = solve(false, false, "MULT_FRONT");
  const Solution eliminated = solve(false, true, "MULT_FRONT");
  EXPECT_EQ(eliminated.backend.find("CHOLMOD"), 0U) << eliminated.backend;
  EXPECT_EQ(dualised.backend.find("CHOLMOD"), std::string::npos) << dualised.backend;
  // GCPC needs an SPD matrix: refused for the dualised system, accepted now
  const Solution gcpc = solve(false, true, "GCPC");
  EXPECT_LE(relative(gcpc.u, eliminated.u), 1e-5);
}

} // namespace
} // namespace stella
