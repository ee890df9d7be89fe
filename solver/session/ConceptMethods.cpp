#include "ConceptMethods.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/session/MeshMethods.hpp"

#include <map>

namespace stella {

namespace {

Value getName(const Concept& object, const CallArguments& args) {
  if (!args.positional.empty() || !args.keywords.empty()) {
    throw UserError(msg::make("LANG_ARGS", {{"name", object.name}}));
  }
  return Value(object.name);
}

// Methods of every concept.
const std::map<std::string, ConceptMethod>& commonMethods() {
  static const std::map<std::string, ConceptMethod> methods = {{"getName", getName}};
  return methods;
}

const std::map<std::string, ConceptMethod>* typeMethods(const std::string& type) {
  if (type == "maillage") {
    return &meshMethods();
  }
  return nullptr;
}

} // namespace

ConceptMethod findConceptMethod(const std::string& type, const std::string& name) {
  if (const auto* methods = typeMethods(type)) {
    if (auto it = methods->find(name); it != methods->end()) {
      return it->second;
    }
  }
  auto it = commonMethods().find(name);
  return it == commonMethods().end() ? nullptr : it->second;
}

std::vector<std::string> conceptMethodNames(const std::string& type) {
  std::map<std::string, ConceptMethod> all = commonMethods();
  if (const auto* methods = typeMethods(type)) {
    all.insert(methods->begin(), methods->end());
  }
  std::vector<std::string> names;
  for (const auto& [name, method] : all) {
    names.push_back(name);
  }
  return names;
}

} // namespace stella
