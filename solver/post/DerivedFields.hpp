#pragma once
// Fields CALC_CHAMP derives from the stored fields of a result step:
//   - ELNO from ELGA (SIEF_ELNO, SIGM_ELNO, EPSI_ELNO, VARI_ELNO): each volume cell's Gauss values
//     extrapolated to its nodes with fem::gaussToNodeMatrix (code_aster's least-squares method);
//   - NOEU from ELNO (SIEF_NOEU, SIGM_NOEU, EPSI_NOEU, SIEQ_NOEU, VARI_NOEU): at each node, the
//     arithmetic mean of the ELNO values of the selected cells that share the node; nodes of no
//     selected cell carry no value;
//   - EPSI_ELGA: the small strain of DEPL at the Gauss points, tensor components EPXX, EPYY, EPZZ,
//     EPXY = (du/dy + dv/dx) / 2 [, EPXZ, EPYZ]; in AXIS EPZZ is the hoop strain u_r / r; in
//     C_PLAN EPZZ = -nu / (1 - nu) (EPXX + EPYY) with the cell's elastic NU (as code_aster);
//   - SIEQ (from a stress field of any support): the 17 equivalent values of TensorInvariants.
// `cells` selects the cells (GROUP_MA); an empty selection means every volume cell of the model.

#include "solver/database/Field.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/Model.hpp"

#include <vector>

namespace stella {

// Volume cells of the model, restricted to `group` when it is not empty (mesh order).
std::vector<bool> selectedVolumeCells(const Model& model, const std::vector<CellId>& group);

Field extrapolateToCellNodes(const Model& model, const Field& elga, const std::vector<bool>& cells);
Field averageAtNodes(const Mesh& mesh, const Field& elno);

// Throws UserError CALC_7 naming the cell when a C_PLAN cell has no elastic material.
Field strainAtGaussPoints(const Model& model, const Field& depl, const MaterialField* materials,
                          const std::vector<bool>& cells);

Field equivalentStressField(const Field& stress);

} // namespace stella
