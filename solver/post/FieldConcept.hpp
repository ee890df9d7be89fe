#pragma once
// A field concept (code_aster's cham_no, cham_elem): one Field on a mesh, made by CREA_CHAMP
// (OPERATION='EXTR' from a result) and tested by TEST_RESU CHAM_NO / CHAM_ELEM.

#include "interpreter/Value.hpp"
#include "solver/database/Field.hpp"
#include "solver/mesh/Mesh.hpp"

#include <memory>
#include <string>

namespace stella {

class FieldConcept : public ConceptData {
public:
  std::shared_ptr<const Field> field;
  std::shared_ptr<const Mesh> mesh;
  std::string fieldType; // TYPE_CHAM, e.g. NOEU_DEPL_R, ELGA_SIEF_R
  std::string origin;    // NOM_CHAM it came from (DEPL, SIEF_ELGA...)
};

// The TYPE_CHAM prefix of a support: NOEU, ELEM, ELGA, ELNO.
std::string supportPrefix(FieldSupport support);

// The TYPE_CHAM of a field: prefix _ quantity (NOEU_DEPL_R).
std::string fieldTypeName(const Field& field);

} // namespace stella
