// The evaluator's imports: `import math`, the sandboxed `os.path`, the code_aster namespaces
// accepted as no-ops (with code_aster's error classes; `import aster` for `aster.error`), and the
// refusal of any other module.
#include "EvaluatorParts.hpp"

#include "Exceptions.hpp"
#include "Suggest.hpp"

#include <algorithm>

namespace stella {

namespace {

// A module made by `import math` (or the code_aster namespace): attributes are its names.
// A sandboxed module (`os`, `os.path`) refuses every other name of the real module clearly.
class ModuleObject : public NativeObject {
public:
  ModuleObject(std::string name, const std::unordered_map<std::string, Value>* names, bool sandboxed = false)
      : name_(std::move(name)), names_(names), sandboxed_(sandboxed) {}
  std::string typeName() const override { return "module " + name_; }
  std::shared_ptr<const Value> attribute(const std::string& name) const override {
    auto it = names_->find(name);
    if (it == names_->end() && names_ != &exceptionNames() && exceptionNames().contains(name) &&
        !sandboxed_) {
      return std::make_shared<const Value>(exceptionNames().at(name)); // code_aster.AsterError
    }
    if (it == names_->end()) {
      if (sandboxed_) {
        refuseSandboxed(name_, name, *names_);
      }
      return nullptr;
    }
    return std::make_shared<const Value>(it->second);
  }

  [[noreturn]] static void refuseSandboxed(const std::string& module, const std::string& name,
                                           const std::unordered_map<std::string, Value>& names) {
    std::vector<std::string> offered;
    for (const auto& [n, v] : names) {
      offered.push_back(n);
    }
    std::sort(offered.begin(), offered.end());
    std::string list;
    for (const auto& n : offered) {
      list += (list.empty() ? "" : ", ") + n;
    }
    langError("LANG_IMPORT", {{"module", module}, {"name", name}, {"list", list}});
  }

private:
  std::string name_;
  const std::unordered_map<std::string, Value>* names_;
  bool sandboxed_;
};

Value osPathModule() {
  return Value(
      std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>("os.path", &osPathNames(), true)));
}

// `os`: its `path` and `sep` only.
const std::unordered_map<std::string, Value>& osNames() {
  static const std::unordered_map<std::string, Value> names = {{"path", osPathModule()}, {"sep", Value("/")}};
  return names;
}

// Older code_aster files: `import aster` for its error classes (`except aster.error:`).
const std::unordered_map<std::string, Value>& asterNames() {
  static const std::unordered_map<std::string, Value> names = {
      {"error", exceptionNames().at("AsterError")},
      {"NonConvergenceError", exceptionNames().at("ConvergenceError")},
  };
  return names;
}

Value osModule() {
  return Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>("os", &osNames(), true)));
}

const char* const importNote =
    "command files are a sandbox: they may import only the code_aster command namespace, 'math' and "
    "'os.path' (path names only)";

bool isCodeAsterModule(const std::string& module) {
  return module == "code_aster" || module.rfind("code_aster.", 0) == 0 || module == "__future__" ||
         module == "Accas" || module == "Cata" || module.rfind("Cata.", 0) == 0;
}

} // namespace

void Evaluator::execImport(const Stmt& s) {
  for (const auto& in : s.imports) {
    std::string bound = in.alias.empty() ? in.name.substr(0, in.name.find('.')) : in.alias;
    if (in.name == "os" || in.name == "os.path") {
      bindName(bound, in.name == "os.path" && !in.alias.empty() ? osPathModule() : osModule());
    } else if (in.name == "math") {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>("math", &mathNames()))));
    } else if (in.name == "aster") {
      bindName(bound, Value(std::shared_ptr<NativeObject>(
                          std::make_shared<ModuleObject>("aster", &asterNames(), true))));
    } else if (isCodeAsterModule(in.name)) {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>(in.name, &globals_))));
    } else {
      raise(in.pos, "LANG_IMPORT.2", {{"name", in.name}}, importNote);
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
  if (s.name != "math" && s.name != "os" && s.name != "os.path") {
    raise(modulePos, "LANG_IMPORT.3", {{"name", s.name}}, importNote);
  }
  const auto& names = s.name == "math" ? mathNames() : (s.name == "os" ? osNames() : osPathNames());
  for (std::size_t i = 1; i < s.imports.size(); ++i) {
    const auto& in = s.imports[i];
    if (in.name == "*") {
      for (const auto& [name, value] : names) {
        bindName(name, value);
      }
      continue;
    }
    auto it = names.find(in.name);
    if (it == names.end() && s.name != "math") {
      try {
        ModuleObject::refuseSandboxed(s.name, in.name, names);
      } catch (const LangError& e) {
        raise(in.pos, e);
      }
    }
    if (it == names.end()) {
      std::vector<std::string> candidates;
      for (const auto& [name, value] : names) {
        candidates.push_back(name);
      }
      raise(in.pos, "LANG_IMPORT.4", {{"name", in.name}}, suggestionNote(in.name, candidates));
    }
    bindName(in.alias.empty() ? in.name : in.alias, it->second);
  }
}

} // namespace stella
