#pragma once
// The loop over the model's volume cells: kinematics, behaviour integration at every Gauss
// point, element internal forces B^T sigma and tangents B^T D B (a GROT_GDEP cell, CellBehaviours::
// strainMeasure: Green-Lagrange strain, B_F^T S and B_F^T D B_F + the geometric stiffness, total
// Lagrangian, fem/GreenLagrange.hpp), scattered into global vectors
// and into the stiffness matrix in place (StiffnessMatrix: precomputed positions; or as triplets,
// the slow path kept for small tests) (physical DOFs only); then the discrete springs (AFFE_CARA_ELEM
// K_T_D_N), whose constant stiffness k adds k to the matrix and k (uStart + du) to the internal forces.

#include "solver/assembly/DofMap.hpp"
#include "solver/assembly/StiffnessMatrix.hpp"
#include "solver/behaviour/Behaviour.hpp"
#include "solver/model/ElementCharacteristics.hpp"
#include "solver/nonlinear/CellBehaviours.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <optional>
#include <vector>

namespace stella {

struct AssemblyOutput {
  std::vector<Eigen::Triplet<double>>* matrix = nullptr; // tangent entries (null: not wanted)
  Eigen::VectorXd* internalForces = nullptr;             // physical size (null: not wanted)
  PointState* end = nullptr;                             // state at the end (null: not wanted)
  StiffnessMatrix* stiffness = nullptr; // tangent added in place (null: not wanted); built on cells()
};

// The first cell whose behaviour failed to integrate (a step-cutting event), if any.
struct AssemblyStatus {
  std::optional<CellId> failedCell;
  bool ok() const { return !failedCell; }
};

class VolumeAssembler {
public:
  // `springs` (may be null): the characteristics of the model's discrete elements.
  VolumeAssembler(const Model& model, const DofMap& dofs, const CellBehaviours& behaviours,
                  const ElementCharacteristics* springs = nullptr);

  // Integrates over the step from displacement `uStart` with increment `du` (physical size) and
  // the state `start`. Throws UserError ELEM_1 naming a cell with a non-positive Jacobian.
  AssemblyStatus run(const Eigen::VectorXd& uStart, const Eigen::VectorXd& du, const PointState& start,
                     behaviour::Option option, AssemblyOutput out) const;

  // Element DOFs (global equations) of a cell.
  void cellDofs(CellId c, std::vector<int>& dofs) const;
  // The volume cells in assembly order (the cell list of the StiffnessMatrix).
  const std::vector<CellId>& cells() const { return cells_; }

private:
  void addSprings(const Eigen::VectorXd& uStart, const Eigen::VectorXd& du, AssemblyOutput out) const;

  const Model& model_;
  const DofMap& dofs_;
  const CellBehaviours& behaviours_;
  std::vector<CellId> cells_;
  const ElementCharacteristics* springs_;
};

} // namespace stella
