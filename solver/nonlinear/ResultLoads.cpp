// ResultLoads: a registry from live results to their excitations.

#include "solver/nonlinear/ResultLoads.hpp"

#include <map>

namespace stella {

namespace {

struct Entry {
  std::weak_ptr<Result> result;
  std::vector<Excitation> excitations;
};

std::map<const Result*, Entry>& registry() {
  static std::map<const Result*, Entry> r;
  return r;
}

} // namespace

void rememberLoads(const std::shared_ptr<Result>& result, std::vector<Excitation> excitations) {
  registry()[result.get()] = Entry{result, std::move(excitations)};
}

const std::vector<Excitation>* rememberedLoads(const Result& result) {
  auto it = registry().find(&result);
  if (it == registry().end() || it->second.result.expired()) {
    return nullptr;
  }
  return &it->second.excitations;
}

} // namespace stella
