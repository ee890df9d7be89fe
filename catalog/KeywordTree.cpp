#include "KeywordTree.hpp"

#include "interpreter/Diagnostics.hpp"

#include <sstream>

namespace stella {

void KeywordTree::addSimple(SimpleKeyword k) {
  simples_.push_back(std::move(k));
}
void KeywordTree::addFactor(FactorKeyword k) {
  factors_.push_back(std::move(k));
}

bool KeywordTree::has(const std::string& name) const {
  return simple(name) != nullptr || factor(name) != nullptr;
}

const SimpleKeyword* KeywordTree::simple(const std::string& name) const {
  for (const auto& k : simples_) {
    if (k.name == name) {
      return &k;
    }
  }
  return nullptr;
}

const FactorKeyword* KeywordTree::factor(const std::string& name) const {
  for (const auto& k : factors_) {
    if (k.name == name) {
      return &k;
    }
  }
  return nullptr;
}

namespace {
const SimpleKeyword& require(const KeywordTree& tree, const std::string& name) {
  const SimpleKeyword* k = tree.simple(name);
  STELLA_ASSERT(k != nullptr, "keyword " + name + " is absent");
  STELLA_ASSERT(!k->values.empty(), "keyword " + name + " has no value");
  return *k;
}
} // namespace

const Value& KeywordTree::value(const std::string& name) const {
  return require(*this, name).values.front();
}

std::string KeywordTree::text(const std::string& name) const {
  const Value& v = value(name);
  STELLA_ASSERT(v.isString(), "keyword " + name + " is not a text");
  return v.asString();
}

double KeywordTree::real(const std::string& name) const {
  const Value& v = value(name);
  STELLA_ASSERT(v.isNumber(), "keyword " + name + " is not a number");
  return v.asReal();
}

std::int64_t KeywordTree::integer(const std::string& name) const {
  const Value& v = value(name);
  STELLA_ASSERT(v.isInt() || v.isBool(), "keyword " + name + " is not an integer");
  return v.asInt();
}

std::vector<std::string> KeywordTree::texts(const std::string& name) const {
  std::vector<std::string> out;
  if (const SimpleKeyword* k = simple(name)) {
    for (const auto& v : k->values) {
      STELLA_ASSERT(v.isString(), "keyword " + name + " is not a text");
      out.push_back(v.asString());
    }
  }
  return out;
}

std::vector<double> KeywordTree::reals(const std::string& name) const {
  std::vector<double> out;
  if (const SimpleKeyword* k = simple(name)) {
    for (const auto& v : k->values) {
      STELLA_ASSERT(v.isNumber(), "keyword " + name + " is not a number");
      out.push_back(v.asReal());
    }
  }
  return out;
}

std::vector<std::int64_t> KeywordTree::integers(const std::string& name) const {
  std::vector<std::int64_t> out;
  if (const SimpleKeyword* k = simple(name)) {
    for (const auto& v : k->values) {
      STELLA_ASSERT(v.isInt() || v.isBool(), "keyword " + name + " is not an integer");
      out.push_back(v.asInt());
    }
  }
  return out;
}

std::shared_ptr<Concept> KeywordTree::conceptValue(const std::string& name) const {
  const Value& v = value(name);
  STELLA_ASSERT(v.isConcept(), "keyword " + name + " is not a concept");
  return v.asConcept();
}

std::vector<std::shared_ptr<Concept>> KeywordTree::conceptValues(const std::string& name) const {
  std::vector<std::shared_ptr<Concept>> out;
  if (const SimpleKeyword* k = simple(name)) {
    for (const auto& v : k->values) {
      STELLA_ASSERT(v.isConcept(), "keyword " + name + " is not a concept");
      out.push_back(v.asConcept());
    }
  }
  return out;
}

std::string KeywordTree::textOr(const std::string& name, const std::string& fallback) const {
  return simple(name) ? text(name) : fallback;
}
double KeywordTree::realOr(const std::string& name, double fallback) const {
  return simple(name) ? real(name) : fallback;
}
std::int64_t KeywordTree::integerOr(const std::string& name, std::int64_t fallback) const {
  return simple(name) ? integer(name) : fallback;
}

const std::vector<KeywordTree>& KeywordTree::occurrences(const std::string& name) const {
  static const std::vector<KeywordTree> none;
  const FactorKeyword* f = factor(name);
  return f ? f->occurrences : none;
}

SourceLocation KeywordTree::locationOf(const std::string& name) const {
  if (const SimpleKeyword* k = simple(name); k && k->location.known()) {
    return k->location;
  }
  if (const FactorKeyword* f = factor(name); f && f->location.known()) {
    return f->location;
  }
  return location_;
}

namespace {
std::string formatValue(const Value& v) {
  if (v.isConcept()) {
    return v.asConcept()->name;
  }
  return v.repr();
}

std::string formatValues(const ValueList& values) {
  if (values.size() == 1) {
    return formatValue(values.front());
  }
  std::string out = "(";
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += (i ? ", " : "") + formatValue(values[i]);
  }
  return out + ")";
}
} // namespace

std::string KeywordTree::format(int indent) const {
  std::ostringstream out;
  std::string pad(static_cast<std::size_t>(indent), ' ');
  for (const auto& k : simples_) {
    out << pad << k.name << '=' << formatValues(k.values) << ",\n";
  }
  for (const auto& f : factors_) {
    // One occurrence: K=_F(...); several: K=(_F(...), _F(...)), as a user would write them.
    const bool several = f.occurrences.size() > 1;
    const std::string inner = several ? pad + "    " : pad;
    if (several) {
      out << pad << f.name << "=(\n";
    }
    for (const auto& occ : f.occurrences) {
      std::string keywords = occ.format(static_cast<int>(inner.size()) + 4);
      out << inner << (several ? "" : f.name + "=") << "_F(";
      if (!keywords.empty()) {
        out << "\n" << keywords << inner;
      }
      out << "),\n";
    }
    if (several) {
      out << pad << "),\n";
    }
  }
  return out.str();
}

} // namespace stella
