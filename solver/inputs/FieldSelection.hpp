#pragma once
// Values of one component of a result field picked the way TEST_RESU and POST_RELEVE_T designate
// them: a node (NOEUD, or a GROUP_NO of one node), a cell and a point (MAILLE / GROUP_MA of one
// cell, POINT, SOUS_POINT), or every defined value (optionally restricted to GROUP_NO / GROUP_MA)
// reduced by TYPE_TEST (MIN, MAX, SOMM, SOMM_ABS).

#include "catalog/KeywordTree.hpp"
#include "solver/database/Result.hpp"

#include <string>
#include <vector>

namespace stella {

// The step of RESULTAT designated by NUME_ORDRE or INST in `occurrence`, the last one when neither
// is given (UserError RESU_1 with the stored steps when absent). `precision`: tolerance on INST,
// relative (CRITERE='RELATIF') unless `absolute` (CRITERE='ABSOLU').
const ResultStep& selectStep(const Result& result, const std::string& resultName,
                             const KeywordTree& occurrence, double precision = 1.0e-6, bool absolute = false);

// The field NOM_CHAM of a step (RESU_2 listing the stored fields when absent).
const Field& selectField(const ResultStep& step, const std::string& resultName, const std::string& fieldName,
                         const KeywordTree& occurrence);

// The index of component NOM_CMP (RESU_3 listing the components when absent).
std::size_t selectComponent(const Field& field, const std::string& fieldName, const std::string& component,
                            const KeywordTree& occurrence);

// The entities (nodes of a nodal field, points of a per-point field) designated by the
// occurrence's NOEUD / GROUP_NO / MAILLE / GROUP_MA / POINT / SOUS_POINT, or all of them.
// `single` is true when the keywords designate exactly one value (a node, or a cell's point).
struct EntitySelection {
  std::vector<std::size_t> entities;
  bool single = false;
  std::string label; // "N12" or "M3 point 2" for headers
};
EntitySelection selectEntities(const Mesh& mesh, const Field& field, const KeywordTree& occurrence);

// MIN / MAX / SOMM / SOMM_ABS of the defined values of a component over entities.
double reduceValues(const Field& field, std::size_t component, const std::vector<std::size_t>& entities,
                    const std::string& type, const KeywordTree& occurrence);

} // namespace stella
