// FieldConcept: TYPE_CHAM names of fields.

#include "solver/post/FieldConcept.hpp"

namespace stella {

std::string supportPrefix(FieldSupport support) {
  switch (support) {
  case FieldSupport::Node:
    return "NOEU";
  case FieldSupport::Cell:
    return "ELEM";
  case FieldSupport::GaussPoint:
    return "ELGA";
  case FieldSupport::CellNode:
    return "ELNO";
  }
  return "NOEU";
}

std::string fieldTypeName(const Field& field) {
  return supportPrefix(field.support()) + "_" + field.quantity();
}

} // namespace stella
