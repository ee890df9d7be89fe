// The evaluator's imports: `import math`, the code_aster namespaces accepted as no-ops, and
// the refusal of any other module.
#include "EvaluatorParts.hpp"

#include "Suggest.hpp"

namespace stella {

namespace {

// A module made by `import math` (or the code_aster namespace): attributes are its names.
class ModuleObject : public NativeObject {
public:
  ModuleObject(std::string name, const std::unordered_map<std::string, Value>* names)
      : name_(std::move(name)), names_(names) {}
  std::string typeName() const override { return "module " + name_; }
  std::shared_ptr<const Value> attribute(const std::string& name) const override {
    auto it = names_->find(name);
    if (it == names_->end()) {
      return nullptr;
    }
    return std::make_shared<const Value>(it->second);
  }

private:
  std::string name_;
  const std::unordered_map<std::string, Value>* names_;
};

bool isCodeAsterModule(const std::string& module) {
  return module == "code_aster" || module.rfind("code_aster.", 0) == 0 || module == "__future__" ||
         module == "Accas" || module == "Cata" || module.rfind("Cata.", 0) == 0;
}

} // namespace

void Evaluator::execImport(const Stmt& s) {
  for (const auto& in : s.imports) {
    std::string bound = in.alias.empty() ? in.name.substr(0, in.name.find('.')) : in.alias;
    if (in.name == "math") {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>("math", &mathNames()))));
    } else if (isCodeAsterModule(in.name)) {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>(in.name, &globals_))));
    } else {
      raise(in.pos, "LANG_IMPORT", "import of module '" + in.name + "' is refused",
            "command files are a sandbox: they may import only the code_aster command namespace and 'math'");
    }
  }
}

void Evaluator::execFromImport(const Stmt& s) {
  const Pos& modulePos = s.imports[0].pos;
  if (isCodeAsterModule(s.name)) {
    for (std::size_t i = 1; i < s.imports.size(); ++i) {
      const auto& in = s.imports[i];
      if (in.name == "CA" || in.name == "Commands") {
        bindName(in.alias.empty() ? in.name : in.alias,
                 Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>(in.name, &globals_))));
      }
      // command names are already global: `from code_aster.Commands import *` is a no-op
    }
    return;
  }
  if (s.name != "math") {
    raise(modulePos, "LANG_IMPORT", "import from module '" + s.name + "' is refused",
          "command files are a sandbox: they may import only the code_aster command namespace and 'math'");
  }
  const auto& names = mathNames();
  for (std::size_t i = 1; i < s.imports.size(); ++i) {
    const auto& in = s.imports[i];
    if (in.name == "*") {
      for (const auto& [name, value] : names) {
        bindName(name, value);
      }
      continue;
    }
    auto it = names.find(in.name);
    if (it == names.end()) {
      std::vector<std::string> candidates;
      for (const auto& [name, value] : names) {
        candidates.push_back(name);
      }
      raise(in.pos, "LANG_IMPORT", "module 'math' has no name '" + in.name + "'",
            suggestionNote(in.name, candidates));
    }
    bindName(in.alias.empty() ? in.name : in.alias, it->second);
  }
}

} // namespace stella
