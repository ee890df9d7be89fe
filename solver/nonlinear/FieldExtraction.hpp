#pragma once
// What an OBSERVATION occurrence of STAT_NON_LINE (and SUIVI_DDL) extracts from a field of the
// current state: NOM_CHAM (DEPL, CONT_NOEU on the nodes; SIEF_ELGA, VARI_ELGA, EPSI_ELGA at
// the Gauss points), NOM_CMP, the nodes (NOEUD, GROUP_NO, MAILLE, GROUP_MA, TOUT) or cells
// (MAILLE, GROUP_MA, TOUT), EVAL_ELGA (VALE at the POINTs, or MIN / MAX over the points of each
// cell) and EVAL_CHAM (VALE: one value per node or cell; MIN, MAX, MOY, MAXI_ABS, MINI_ABS: one
// value over them), as code_aster does. What the catalogue has and stella does not (NOM_VARI,
// EVAL_CMP='FORMULE', SOUS_POINT, the fields of dynamics) is refused by name.
// The keywords are read by solver/inputs/StatNonLineOutputs.

#include "interpreter/SourceFile.hpp"
#include "solver/database/Field.hpp"
#include "solver/mesh/Mesh.hpp"

#include <string>
#include <vector>

namespace stella {

struct ExtractedValue {
  std::string component;
  std::string node; // EVAL_CHAM='VALE' on a nodal field
  std::string cell; // EVAL_CHAM='VALE' on a Gauss-point field
  int point = 0;    // EVAL_ELGA='VALE': the point number (from 1)
  double value = 0.0;
};

struct FieldExtraction {
  std::string field;                   // NOM_CHAM
  std::vector<std::string> components; // NOM_CMP
  std::string evalField = "VALE";      // EVAL_CHAM
  std::string evalPoint = "VALE";      // EVAL_ELGA
  std::vector<int> points;             // POINT
  std::vector<NodeId> nodes;           // nodal fields
  std::vector<CellId> cells;           // Gauss-point fields
  SourceLocation at;                   // the occurrence

  bool nodal() const { return field == "DEPL" || field == "CONT_NOEU"; }
  // SIEF_ELGA, VARI_ELGA, EPSI_ELGA: the fields extracted at the Gauss points.
  static bool gaussPointField(const std::string& name);

  // The values at this instant; SNL_20 when a component or point is not in the field.
  std::vector<ExtractedValue> extract(const Field& f, const Mesh& mesh) const;
};

} // namespace stella
