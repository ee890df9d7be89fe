#pragma once
// The linear static solve behind MECA_STATIQUE, on plain mesh arrays: assemble the elastic
// stiffness, dualise the imposed displacements (DDL_IMPO) with Lagrange multipliers as code_aster
// does (so that reactions exist), assemble pressures (PRES_REP) and nodal forces, solve with the
// SOLVEUR's linear solver. The operator layer maps the Mesh/model/loads concepts onto this.

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

namespace stella::nonlinear {

struct CellBlock {
  CellType type = CellType::HEXA8;
  std::vector<int> connectivity; // cellCount x nodeCount(type)
  int cellCount() const { return static_cast<int>(connectivity.size()) / nodeCount(type); }
};

struct ImposedDisplacement { // DDL_IMPO
  int node = 0;
  int component = 0; // 0 = DX, 1 = DY, 2 = DZ
  double value = 0.0;
};

// A discrete translation spring on one node (DIS_T / 2D_DIS_T on a POI1 cell, AFFE_CARA_ELEM
// DISCRET K_T_D_N: stiffnesses along X, Y[, Z] in the global axes).
struct NodalSpring {
  int node = 0;
  std::array<double, 3> stiffness{0.0, 0.0, 0.0};
};

struct PressureLoad { // PRES_REP on skin cells (normal from the skin's node order)
  CellBlock skin;
  double pressure = 0.0;
};

struct LinearStaticProblem {
  fem::Modelling modelling = fem::Modelling::ThreeD;
  fem::VolumeStrain volumeStrain = fem::VolumeStrain::Pointwise;
  Eigen::MatrixXd coordinates; // nodeCount x spaceDimension
  std::vector<CellBlock> volumes;
  behaviour::ElasticParameters material;
  std::vector<ImposedDisplacement> imposed;
  std::vector<NodalSpring> springs;
  std::vector<PressureLoad> pressures;
  Eigen::VectorXd nodalForces; // FORCE_NODALE, nodeCount*dim (empty: none)
  linalg::SolverOptions solver;
};

struct LinearStaticResult {
  std::shared_ptr<linalg::DofNumbering> numbering;
  Eigen::VectorXd solution;     // every equation, multipliers included
  Eigen::MatrixXd displacement; // nodeCount x dim
  Eigen::MatrixXd reactions;    // nodeCount x dim: K u - f (REAC_NODA), non-zero on supports
};

// Throws linalg::SingularMatrixError (the caller names result.numbering->describeText(eq)) or
// fem::DegenerateElementError.
LinearStaticResult solveLinearStatic(const LinearStaticProblem& problem);

} // namespace stella::nonlinear
