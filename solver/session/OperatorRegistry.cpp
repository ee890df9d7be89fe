#include "OperatorRegistry.hpp"

#include "Session.hpp"

#include "interpreter/Diagnostics.hpp"

namespace stella {

OperatorRegistry& OperatorRegistry::instance() {
  static OperatorRegistry registry;
  return registry;
}

bool OperatorRegistry::add(const std::string& name, OperatorFunction fn, const char* file) {
  auto [it, inserted] = operators_.emplace(name, std::make_pair(fn, std::string(file)));
  if (!inserted) {
    throw InternalError("operator " + name + " registered twice: in " + it->second.second + " and " + file,
                        __FILE__, __LINE__);
  }
  return true;
}

OperatorFunction OperatorRegistry::find(const std::string& name) const {
  auto it = operators_.find(name);
  return it == operators_.end() ? nullptr : it->second.first;
}

std::vector<std::string> OperatorRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, entry] : operators_) {
    out.push_back(name);
  }
  return out;
}

Value OperatorCall::makeConcept(std::shared_ptr<ConceptData> data) const {
  if (reused) {
    reused->data = std::move(data);
    session.noteConceptInProgress(reused);
    return Value(reused);
  }
  auto c = std::make_shared<Concept>();
  c->name = resultName;
  c->type = resultType;
  c->data = std::move(data);
  c->definedAt = location;
  session.noteConceptInProgress(c);
  return Value(c);
}

TestReportSink& OperatorCall::testReport() const {
  return session;
}

} // namespace stella
