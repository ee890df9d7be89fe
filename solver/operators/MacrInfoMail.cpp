// MACR_INFO_MAIL: prints the counts of cells by type, the group sizes and a quality histogram
// (aspect ratio, cells with a negative jacobian) of a mesh to the message file.

#include "solver/mesh/MeshSummary.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

Value runMacrInfoMail(OperatorCall& call) {
  const auto data = meshConceptOf(call.keywords);
  const auto mesh = call.keywords.conceptValue("MAILLAGE");
  call.session.message() << formatStatistics(meshStatistics(*data->mesh), mesh ? mesh->name : "");
  return Value();
}

} // namespace

STELLA_OPERATOR("MACR_INFO_MAIL", runMacrInfoMail);

} // namespace stella
