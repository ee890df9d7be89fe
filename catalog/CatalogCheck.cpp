// The load-time checks of the whole catalogue (see CatalogLoader.hpp, checkCatalog): defaults
// that fit their keyword, duplicate or shadowed keywords, rules naming unknown keywords.
#include "CatalogLoader.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace stella {

namespace {

void allNames(const Level& level, std::set<std::string>& names) {
  for (const Entry& e : level.entries) {
    if (e.block) {
      allNames(e.block->body, names);
    } else {
      names.insert(e.name);
    }
  }
}

struct Checker {
  const LoadedCatalog& catalog;
  const CommandSpec& command;
  std::vector<std::string>& problems;

  void problem(const std::string& path, const std::string& what) {
    problems.push_back(command.file + ": " + path + ": " + what);
  }

  bool fitsType(const SimpleSpec& s, const Value& v) {
    for (const auto& t : s.types) {
      if ((t == "R" && (v.isReal() || v.isInt())) || (t == "I" && v.isInt()) || (t == "C" && v.isNumber()) ||
          ((t == "TXM" || t == "grma" || t == "grno") && v.isString())) {
        return true;
      }
    }
    return false;
  }

  void checkSimple(const std::string& path, const SimpleSpec& s) {
    if (s.description.empty()) {
      problem(path, "no description (fr=, or an entry in common/GLOSSAIRE.cata)");
    }
    for (const auto& t : s.types) {
      static const std::set<std::string> plain{"TXM", "R", "I", "C", "grma", "grno", "ma", "no"};
      if (!plain.count(t) && !catalog.types.known(t)) {
        problem(path, "unknown type '" + t + "' (declare it in common/TYPES.cata)");
      }
    }
    if (s.defaultValue) {
      for (const Value& v : *s.defaultValue) {
        if (!fitsType(s, v)) {
          problem(path, "default " + v.repr() + " does not match the keyword's type");
        }
        if (!s.into.empty() &&
            std::none_of(s.into.begin(), s.into.end(), [&](const Value& a) { return a.equals(v); })) {
          problem(path, "default " + v.repr() + " is not one of the allowed values");
        }
      }
      if (s.presence == Presence::Mandatory) {
        problem(path, "a mandatory keyword cannot have a default");
      }
    }
    for (const Value& v : s.into) {
      if (!fitsType(s, v)) {
        problem(path, "allowed value " + v.repr() + " does not match the keyword's type");
      }
    }
    if (s.max != kUnbounded && s.max < s.min) {
      problem(path, "max < min");
    }
  }

  std::set<std::string> outOfScope; // keywords declared outside the scope, here or above

  void checkLevel(const std::string& path, const Level& level, const std::set<std::string>& inherited) {
    std::set<std::string> names = inherited;
    outOfScope.insert(level.outOfScope.begin(), level.outOfScope.end());
    allNames(level, names);
    checkRules(path, level, names);
    checkShadowing(path, level);
    for (const Entry& e : level.entries) {
      std::string p = path + "/" + e.name;
      if (e.simple) {
        checkSimple(p, *e.simple);
      } else if (e.factor) {
        if (e.factor->description.empty()) {
          problem(p, "no description (fr=, or an entry in common/GLOSSAIRE.cata)");
        }
        checkLevel(p, e.factor->body, {});
      } else if (e.block) {
        checkLevel(path, e.block->body, names);
      }
    }
  }

  // A keyword defined unconditionally at a level and again inside one of its blocks: the block's
  // definition could never be used (the first active definition wins).
  void checkShadowing(const std::string& path, const Level& level) {
    std::set<std::string> direct;
    for (const Entry& e : level.entries) {
      if (!e.block) {
        direct.insert(e.name);
      }
    }
    for (const Entry& e : level.entries) {
      if (e.block) {
        std::set<std::string> inBlock;
        allNames(e.block->body, inBlock);
        for (const auto& n : inBlock) {
          if (direct.count(n)) {
            problem(path + "/" + n, "defined both unconditionally and in block " + e.name);
          }
        }
      }
    }
  }

  void checkRules(const std::string& path, const Level& level, const std::set<std::string>& names) {
    for (const Rule& r : level.rules) {
      for (const auto& n : r.names) {
        bool removed = std::find(command.removedKeywords.begin(), command.removedKeywords.end(), n) !=
                           command.removedKeywords.end() ||
                       outOfScope.count(n) > 0;
        if (!names.count(n) && !removed) {
          problem(path, "rule " + r.text() + " names the unknown keyword " + n +
                            " (declare it in supprimes= if it was removed)");
        }
      }
      for (const auto& d : r.defaults) {
        if (!names.count(d.first)) {
          problem(path, "rule " + r.text() + " gives a default to the unknown keyword " + d.first);
        }
      }
    }
  }
};

} // namespace

std::vector<std::string> checkCatalog(const LoadedCatalog& catalog) {
  std::vector<std::string> problems;
  for (const auto& [name, command] : catalog.commands) {
    Checker c{catalog, *command, problems, {}};
    if (command->description.empty()) {
      c.problem(name, "no description (fr=)");
    }
    c.checkLevel(name, command->body, {});
  }
  return problems;
}

} // namespace stella
