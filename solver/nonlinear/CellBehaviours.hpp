#pragma once
// The constitutive behaviour of every volume cell: RELATION ('ELAS', 'VMIS_ISOT_LINE') per
// group (COMPORTEMENT), with the parameters of the cell's material (AFFE_MATERIAU). One
// Behaviour object per (material, relation) pair, shared by its cells.

#include "solver/behaviour/Behaviour.hpp"
#include "solver/fem/GreenLagrange.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/Model.hpp"

#include <memory>
#include <string>
#include <vector>

namespace stella {

class CellBehaviours {
public:
  // `relations[c]` is the RELATION of volume cell c ("ELAS" for every cell of MECA_STATIQUE).
  // Throws UserError: MATER_6 (a cell without material), MATER_7 (material without ELAS),
  // MATER_8 (VMIS_ISOT_LINE without ECRO_LINE), a relation outside the catalogue's implemente= list is an
  // internal error.
  // `strains[c]` (empty: PETIT everywhere) is the strain measure (DEFORMATION) of cell c.
  CellBehaviours(const Model& model, const MaterialField& materials,
                 const std::vector<std::string>& relations, const SourceLocation& at,
                 std::vector<fem::StrainMeasure> strains = {});

  const behaviour::Behaviour* of(CellId c) const { return cells_[static_cast<std::size_t>(c)]; }
  fem::StrainMeasure strainMeasure(CellId c) const {
    return strains_.empty() ? fem::StrainMeasure::Small : strains_[static_cast<std::size_t>(c)];
  }
  // The strain measure of every cell (empty: PETIT everywhere).
  const std::vector<fem::StrainMeasure>& strainMeasures() const { return strains_; }
  // Some cell has DEFORMATION='GROT_GDEP': the problem is nonlinear whatever the relations.
  bool largeDisplacements() const { return largeDisplacements_; }
  int maxInternalVariables() const { return maxVariables_; }
  bool allLinear() const { return allLinear_; }
  bool allSymmetric() const { return allSymmetric_; }
  // Names of the relations used, e.g. {"ELAS", "VMIS_ISOT_LINE"}.
  std::vector<std::string> relationNames() const;

private:
  std::vector<std::unique_ptr<behaviour::Behaviour>> owned_;
  std::vector<std::pair<std::pair<const Material*, std::string>, const behaviour::Behaviour*>> made_;
  std::vector<const behaviour::Behaviour*> cells_;
  std::vector<fem::StrainMeasure> strains_;
  bool largeDisplacements_ = false;
  int maxVariables_ = 1;
  bool allLinear_ = true;
  bool allSymmetric_ = true;
};

} // namespace stella
