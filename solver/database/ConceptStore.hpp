#pragma once
// The concepts of a study (meshes, models, results, tables...), beside the result database they
// hold: the store of the concepts made so far by name, and the typed access to a concept's data
// that operators, inputs readers and post-processing use. The session fills the store; nothing
// here depends on the session.

#include "interpreter/Value.hpp"

#include <map>
#include <memory>
#include <string>

namespace stella {

// Data of a concept, typed: the concept's data as T, or null when the concept holds no such data
// (e.g. the placeholder concept that `stella check` makes for a command it does not run).
template <class T> std::shared_ptr<T> conceptData(const std::shared_ptr<Concept>& c) {
  return std::dynamic_pointer_cast<T>(c->data);
}

// Every concept made so far, by name: a later concept of a name replaces the earlier one (the
// command file assigned the name again).
class ConceptStore {
public:
  void put(const std::string& name, std::shared_ptr<Concept> c) { byName_[name] = std::move(c); }
  // The concept named `name`, null when none.
  std::shared_ptr<Concept> find(const std::string& name) const {
    const auto it = byName_.find(name);
    return it == byName_.end() ? nullptr : it->second;
  }
  // Its data as T, null when there is no such concept or its data is not a T.
  template <class T> std::shared_ptr<T> findData(const std::string& name) const {
    const auto c = find(name);
    return c ? conceptData<T>(c) : nullptr;
  }
  const std::map<std::string, std::shared_ptr<Concept>>& byName() const { return byName_; }

private:
  std::map<std::string, std::shared_ptr<Concept>> byName_;
};

} // namespace stella
