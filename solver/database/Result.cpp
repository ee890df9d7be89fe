#include "Result.hpp"

#include <cmath>
#include <set>

namespace stella {

const Field* ResultStep::field(const std::string& name) const {
  auto it = fields.find(name);
  return it == fields.end() ? nullptr : it->second.get();
}

ResultStep& Result::addStep(double time, int first) {
  ResultStep s;
  s.number = steps.empty() ? first : steps.back().number + 1;
  s.time = time;
  steps.push_back(std::move(s));
  return steps.back();
}

const ResultStep* Result::stepAtTime(double time, double precision, bool absolute) const {
  for (const auto& s : steps) {
    double tolerance = absolute ? precision : precision * std::max(std::fabs(time), 1.0e-300);
    if (std::fabs(s.time - time) <= tolerance || s.time == time) {
      return &s;
    }
  }
  return nullptr;
}

const ResultStep* Result::stepNumber(int number) const {
  for (const auto& s : steps) {
    if (s.number == number) {
      return &s;
    }
  }
  return nullptr;
}

ResultStep* Result::stepNumber(int number) {
  for (auto& s : steps) {
    if (s.number == number) {
      return &s;
    }
  }
  return nullptr;
}

std::vector<std::string> Result::fieldNames() const {
  std::set<std::string> names;
  for (const auto& s : steps) {
    for (const auto& [name, f] : s.fields) {
      names.insert(name);
    }
  }
  return {names.begin(), names.end()};
}

} // namespace stella
