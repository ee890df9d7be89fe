#pragma once
// Reading the keywords of AFFE_CHAR_MECA and AFFE_CHAR_CINE into load data, with the checks:
// the nodes belong to the model (LOAD_2), the components exist in the model (LOAD_1), the cells
// carry the right kind of element (LOAD_3), the feature is implemented (LOAD_4).

#include "catalog/KeywordTree.hpp"
#include "solver/model/KinematicLoad.hpp"
#include "solver/model/MechanicalLoad.hpp"
#include "solver/model/Model.hpp"

namespace stella {

// Fills `load` from every supported factor keyword of an AFFE_CHAR_MECA call.
void readMechanicalLoad(const KeywordTree& keywords, MechanicalLoad& load);

// Fills `load` from the MECA_IMPO occurrences of an AFFE_CHAR_CINE call.
void readKinematicLoad(const KeywordTree& keywords, KinematicLoad& load);

// The imposed components of one DDL_IMPO / FACE_IMPO / MECA_IMPO occurrence: (component, value),
// refusing components the model does not have.
std::vector<std::pair<int, double>> imposedComponents(const Model& model, const KeywordTree& occurrence);

// Nodes of an occurrence, each checked to carry DOFs in the model.
std::vector<NodeId> modelNodes(const Model& model, const KeywordTree& occurrence);

} // namespace stella
