// Rules, presence letters, the concept type hierarchy and type wording of the catalogue model.
#include "CommandSpec.hpp"

#include <algorithm>

namespace stella {

char presenceLetter(Presence p) {
  switch (p) {
  case Presence::Mandatory:
    return 'o';
  case Presence::Optional:
    return 'f';
  case Presence::Hidden:
    return 'c';
  case Presence::Defaulted:
    return 'd';
  }
  return '?';
}

std::string Rule::keyword() const {
  switch (kind) {
  case Kind::UnParmi:
    return "UN_PARMI";
  case Kind::AuMoinsUn:
    return "AU_MOINS_UN";
  case Kind::Exclus:
    return "EXCLUS";
  case Kind::Ensemble:
    return "ENSEMBLE";
  case Kind::PresentPresent:
    return "PRESENT_PRESENT";
  case Kind::PresentAbsent:
    return "PRESENT_ABSENT";
  case Kind::NonVide:
    return "NON_VIDE";
  }
  return "?";
}

namespace {
std::string join(const std::vector<std::string>& names, std::size_t from = 0) {
  std::string out;
  for (std::size_t i = from; i < names.size(); ++i) {
    out += (i > from ? ", " : "") + names[i];
  }
  return out;
}
} // namespace

std::string Rule::text() const {
  std::string out = keyword() + "(" + join(names);
  if (!defaults.empty()) {
    out += "; default ";
    for (std::size_t i = 0; i < defaults.size(); ++i) {
      out += (i ? ", " : "") + defaults[i].first + "=" + defaults[i].second.repr();
    }
  }
  return out + ")";
}

std::string Rule::explanation() const {
  switch (kind) {
  case Kind::UnParmi:
    return "exactly one of " + join(names) + " must be given";
  case Kind::AuMoinsUn:
    return "at least one of " + join(names) + " must be given";
  case Kind::Exclus:
    return "at most one of " + join(names) + " may be given";
  case Kind::Ensemble:
    return join(names) + " must be given together or not at all";
  case Kind::PresentPresent:
    return "when " + names.front() + " is given, " + join(names, 1) + " must be given too";
  case Kind::PresentAbsent:
    return "when " + names.front() + " is given, " + join(names, 1) + " must not be given";
  case Kind::NonVide:
    return "at least one keyword must be given";
  }
  return "";
}

bool Rule::holds(const std::vector<std::string>& present) const {
  auto has = [&](const std::string& n) {
    return std::find(present.begin(), present.end(), n) != present.end();
  };
  auto count = static_cast<std::size_t>(std::count_if(names.begin(), names.end(), has));
  switch (kind) {
  case Kind::UnParmi:
    return count == 1;
  case Kind::AuMoinsUn:
    return count >= 1;
  case Kind::Exclus:
    return count <= 1;
  case Kind::Ensemble:
    return count == 0 || count == names.size();
  case Kind::PresentPresent:
    return names.empty() || !has(names.front()) || std::all_of(names.begin() + 1, names.end(), has);
  case Kind::PresentAbsent:
    return names.empty() || !has(names.front()) || std::none_of(names.begin() + 1, names.end(), has);
  case Kind::NonVide:
    return names.empty() ? !present.empty() : count >= 1;
  }
  return true;
}

bool SimpleSpec::isConceptType() const {
  static const std::vector<std::string> plain{"TXM", "R", "I", "C", "grma", "grno", "ma", "no"};
  return std::any_of(types.begin(), types.end(), [](const std::string& t) {
    return std::find(plain.begin(), plain.end(), t) == plain.end();
  });
}

void ConceptTypes::addParent(const std::string& child, const std::string& parent) {
  known_[child].push_back(parent);
  known_[parent];
}

bool ConceptTypes::isA(const std::string& type, const std::string& wanted) const {
  if (type == wanted) {
    return true;
  }
  auto it = known_.find(type);
  if (it == known_.end()) {
    return false;
  }
  return std::any_of(it->second.begin(), it->second.end(),
                     [&](const std::string& p) { return isA(p, wanted); });
}

bool ConceptTypes::known(const std::string& type) const {
  return known_.count(type) > 0;
}

std::string typeDescription(const std::string& type) {
  if (type == "R") {
    return "a real";
  }
  if (type == "I") {
    return "an integer";
  }
  if (type == "C") {
    return "a complex";
  }
  if (type == "TXM") {
    return "a text";
  }
  if (type == "grma") {
    return "a cell group name";
  }
  if (type == "grno") {
    return "a node group name";
  }
  if (type == "ma") {
    return "a cell name";
  }
  if (type == "no") {
    return "a node name";
  }
  return "a " + type;
}

} // namespace stella
