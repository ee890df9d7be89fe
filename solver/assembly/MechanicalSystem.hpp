#pragma once
// Everything a static mechanical analysis assembles, built once per command: the equations
// (DOFs and multipliers of the dualised relations of every EXCIT load), the behaviours of the
// cells, the eliminated DOFs of the kinematic loads, the constraint rows, and the solver that
// keeps its factorisation.

#include "solver/assembly/DofMap.hpp"
#include "solver/assembly/VolumeAssembler.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/nonlinear/CellBehaviours.hpp"
#include "solver/nonlinear/Excitation.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <memory>
#include <vector>

namespace stella {

class MechanicalSystem {
public:
  // `relations[c]`: RELATION of each cell (see CellBehaviours). Throws UserError LOAD_8 when an
  // excitation's load was built on another model, SOLVE_4 when one DOF is imposed twice by
  // elimination with different multipliers. `cara` (CARA_ELEM, may be null) gives the stiffness
  // of the discrete springs: CARA_5 when a discrete element of the model has none, CARA_6 when
  // it was built on another model. `strains[c]` (empty: PETIT everywhere): the strain measure of
  // each cell (COMPORTEMENT DEFORMATION).
  MechanicalSystem(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> materials,
                   std::vector<Excitation> excitations, const std::vector<std::string>& relations,
                   const SourceLocation& at, std::shared_ptr<const ElementCharacteristics> cara = nullptr,
                   std::vector<fem::StrainMeasure> strains = {});

  const Model& model() const { return *model_; }
  const DofMap& dofs() const { return dofs_; }
  const MaterialField& materials() const { return *materials_; }
  const CellBehaviours& behaviours() const { return behaviours_; }
  const VolumeAssembler& assembler() const { return assembler_; }
  const ElementCharacteristics* characteristics() const { return cara_.get(); }
  SaddleSolver& solver() { return *solver_; }
  const SaddleSolver& solver() const { return *solver_; }
  const std::vector<Excitation>& excitations() const { return excitations_; }
  int relationCount() const { return dofs_.lagrangeCount(); }

  // External forces at a time (physical size).
  Eigen::VectorXd externalForces(double time);
  // Right-hand sides g of the relations at a time.
  Eigen::VectorXd relationValues(double time) const;
  // Values of the eliminated DOFs at a time (physical size, zero elsewhere).
  Eigen::VectorXd eliminatedValues(double time) const;

  // Tangent assembly from triplets (physical block; the slow path, for small tests).
  Eigen::SparseMatrix<double> matrix(std::vector<Eigen::Triplet<double>>& triplets) const;
  // The tangent's physical block to assemble in place (AssemblyOutput::stiffness), zeroed. Its
  // pattern is built at the first call (counted as numbering) and kept for the whole analysis;
  // one per storage (symmetric: upper triangle; else full).
  StiffnessMatrix& stiffness(bool symmetric);

  // Phase times of the analysis (filled by the drivers; the solver keeps its own).
  PhaseTimes& phases() { return phases_; }
  // Those phase times completed with the solver's clocks: factorisation (bordering, symbolic
  // analyses, numerical factorisations) and solve.
  PhaseTimes phaseTimes() const;

private:
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const MaterialField> materials_;
  std::shared_ptr<const ElementCharacteristics> cara_;
  std::vector<Excitation> excitations_;
  DofMap dofs_;
  CellBehaviours behaviours_;
  VolumeAssembler assembler_;
  std::vector<int> relationExcitation_;
  std::vector<std::tuple<int, int, double>> eliminated_; // equation, excitation, value
  std::unique_ptr<SaddleSolver> solver_;
  std::vector<Eigen::VectorXd> forceCache_;
  std::unique_ptr<StiffnessMatrix> stiffness_[2]; // upper, full
  PhaseTimes phases_;
};

} // namespace stella
