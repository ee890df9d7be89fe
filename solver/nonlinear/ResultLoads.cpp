// ResultLoads: registries from live results to their excitations and element characteristics.

#include "solver/nonlinear/ResultLoads.hpp"

#include <algorithm>
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

struct CaraEntry {
  std::weak_ptr<Result> result;
  std::shared_ptr<const ElementCharacteristics> cara;
};

std::map<const Result*, CaraEntry>& caraRegistry() {
  static std::map<const Result*, CaraEntry> r;
  return r;
}

struct StrainEntry {
  std::weak_ptr<Result> result;
  std::vector<fem::StrainMeasure> strains;
};

std::map<const Result*, StrainEntry>& strainRegistry() {
  static std::map<const Result*, StrainEntry> r;
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

void rememberCharacteristics(const std::shared_ptr<Result>& result,
                             std::shared_ptr<const ElementCharacteristics> cara) {
  caraRegistry()[result.get()] = CaraEntry{result, std::move(cara)};
}

std::shared_ptr<const ElementCharacteristics> rememberedCharacteristics(const Result& result) {
  auto it = caraRegistry().find(&result);
  if (it == caraRegistry().end() || it->second.result.expired()) {
    return nullptr;
  }
  return it->second.cara;
}

void rememberStrainMeasures(const std::shared_ptr<Result>& result, std::vector<fem::StrainMeasure> strains) {
  if (std::find(strains.begin(), strains.end(), fem::StrainMeasure::GreenLagrange) == strains.end()) {
    strainRegistry().erase(result.get());
    return;
  }
  strainRegistry()[result.get()] = StrainEntry{result, std::move(strains)};
}

const std::vector<fem::StrainMeasure>* rememberedStrainMeasures(const Result& result) {
  auto it = strainRegistry().find(&result);
  if (it == strainRegistry().end() || it->second.result.expired()) {
    return nullptr;
  }
  return &it->second.strains;
}

} // namespace stella
