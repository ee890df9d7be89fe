#include "MeshMethods.hpp"

#include "interpreter/Diagnostics.hpp"
#include "interpreter/SequenceObject.hpp"
#include "interpreter/Suggest.hpp"
#include "messages/Messages.hpp"
#include "solver/database/MeshConcept.hpp"
#include "solver/mesh/MeshEdges.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

const Mesh& meshOf(const Concept& object, const char* method) {
  const auto* data = dynamic_cast<const MeshConcept*>(object.data.get());
  if (data == nullptr || data->mesh == nullptr) {
    throw UserError(msg::make("CONCEPT_3", {{"name", object.name}, {"method", method}}));
  }
  return *data->mesh;
}

void checkArity(const Concept& object, const char* method, const CallArguments& args, std::size_t most) {
  const std::size_t given = args.positional.size() + args.keywords.size();
  if (given > most) {
    throw UserError(msg::make("LANG_ARGS.2",
                              {{"name", object.name}, {"method", method}, {"most", most}, {"given", given}}));
  }
}

// `local` (code_aster's parallel meshes: the groups of this process) is the whole mesh here.
void checkLocal(const Concept& object, const char* method, const CallArguments& args) {
  checkArity(object, method, args, 1);
  const Value* local = !args.positional.empty() ? &args.positional[0] : nullptr;
  for (const auto& k : args.keywords) {
    if (k.name != "local") {
      throw UserError(
          msg::make("LANG_ARGS.3", {{"name", object.name}, {"method", method}, {"name_2", k.name}}));
    }
    local = k.value.get();
  }
  if (local != nullptr && !local->isBool()) {
    throw UserError(msg::make("LANG_TYPE",
                              {{"name", object.name}, {"method", method}, {"type_name", local->typeName()}}));
  }
}

Value getNumberOfNodes(const Concept& object, const CallArguments& args) {
  checkArity(object, "getNumberOfNodes", args, 0);
  return Value(static_cast<std::int64_t>(meshOf(object, "getNumberOfNodes").nodeCount()));
}

Value getNumberOfCells(const Concept& object, const CallArguments& args) {
  checkArity(object, "getNumberOfCells", args, 0);
  return Value(static_cast<std::int64_t>(meshOf(object, "getNumberOfCells").cellCount()));
}

template <class Groups> Value groupNames(const Groups& groups) {
  ValueList names;
  for (const auto& [name, members] : groups) {
    names.emplace_back(name);
  }
  return Value::list(std::move(names));
}

Value getGroupsOfNodes(const Concept& object, const CallArguments& args) {
  checkLocal(object, "getGroupsOfNodes", args);
  return groupNames(meshOf(object, "getGroupsOfNodes").nodeGroups());
}

Value getGroupsOfCells(const Concept& object, const CallArguments& args) {
  checkLocal(object, "getGroupsOfCells", args);
  return groupNames(meshOf(object, "getGroupsOfCells").cellGroups());
}

// code_aster's MeshCoordinatesField: x, y, z of every node in turn (z = 0 in 2D), read by index
// or as a list with getValues().
class CoordinatesField : public SequenceObject {
public:
  explicit CoordinatesField(std::vector<double> values) : values_(std::move(values)) {}
  std::string typeName() const override { return "MeshCoordinatesField"; }
  std::int64_t length() const override { return static_cast<std::int64_t>(values_.size()); }
  Value item(std::int64_t index) const override { return Value(values_[static_cast<std::size_t>(index)]); }
  std::shared_ptr<const Value> attribute(const std::string& name) const override {
    if (name != "getValues") {
      return nullptr;
    }
    std::vector<double> values = values_;
    return std::make_shared<const Value>(makeNativeFunction("getValues", [values](const CallArguments& a) {
      if (!a.positional.empty() || !a.keywords.empty()) {
        throw UserError(msg::make("LANG_ARGS.4"));
      }
      ValueList list;
      list.reserve(values.size());
      for (double v : values) {
        list.emplace_back(v);
      }
      return Value::list(std::move(list));
    }));
  }

private:
  std::vector<double> values_;
};

Value getCoordinates(const Concept& object, const CallArguments& args) {
  checkArity(object, "getCoordinates", args, 0);
  return Value(std::shared_ptr<NativeObject>(
      std::make_shared<CoordinatesField>(meshOf(object, "getCoordinates").coordinates())));
}

// code_aster: getMinMaxEdgeSizes(group of cells) -> (shortest, longest) edge.
Value getMinMaxEdgeSizes(const Concept& object, const CallArguments& args) {
  if (args.positional.size() != 1 || !args.keywords.empty() || !args.positional[0].isString()) {
    throw UserError(msg::make("LANG_ARGS.5", {{"name", object.name}}));
  }
  const Mesh& mesh = meshOf(object, "getMinMaxEdgeSizes");
  const std::string& group = args.positional[0].asString();
  const std::vector<CellId>* cells = mesh.cellGroup(group);
  if (cells == nullptr) {
    std::vector<std::string> names;
    for (const auto& [name, members] : mesh.cellGroups()) {
      names.push_back(name);
    }
    Diagnostic d = msg::make("GROUP_1.3", {{"name", object.name}, {"group", group}});
    const std::string note = names.empty() ? "the mesh has no cell group" : suggestionNote(group, names);
    if (!note.empty()) {
      d.withNote(note);
    }
    throw UserError(std::move(d));
  }
  if (cells->empty()) {
    throw UserError(msg::make("GROUP_1.4", {{"group", group}, {"name", object.name}}));
  }
  const auto [shortest, longest] = minMaxEdgeLengths(mesh, *cells);
  return Value::tuple({Value(shortest), Value(longest)});
}

} // namespace

const std::map<std::string, ConceptMethod>& meshMethods() {
  static const std::map<std::string, ConceptMethod> methods = {
      {"getNumberOfNodes", getNumberOfNodes}, {"getNumberOfCells", getNumberOfCells},
      {"getGroupsOfNodes", getGroupsOfNodes}, {"getGroupsOfCells", getGroupsOfCells},
      {"getCoordinates", getCoordinates},     {"getMinMaxEdgeSizes", getMinMaxEdgeSizes},
  };
  return methods;
}

} // namespace stella
