// Methods of the built-in types: str (upper, split, join, format...), list (append, pop...),
// dict (keys, items, get...) and tuple (index, count).
#include "Evaluator.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace stella {

namespace {

constexpr std::array<std::string_view, 24> stringMethods = {
    "upper",      "lower",      "strip", "lstrip",  "rstrip",  "split", "join",       "replace",
    "startswith", "endswith",   "find",  "count",   "format",  "ljust", "rjust",      "center",
    "zfill",      "capitalize", "title", "isdigit", "isalpha", "index", "splitlines", "rfind"};
constexpr std::array<std::string_view, 10> listMethods = {"append", "extend", "index",   "count", "pop",
                                                          "insert", "remove", "reverse", "sort",  "copy"};
constexpr std::array<std::string_view, 9> dictMethods = {"keys",   "values",     "items", "get",  "pop",
                                                         "update", "setdefault", "copy",  "clear"};
constexpr std::array<std::string_view, 2> tupleMethods = {"index", "count"};

template <std::size_t N> bool among(const std::array<std::string_view, N>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void arity(const CallArguments& a, const std::string& name, std::size_t min, std::size_t max) {
  if (a.positional.size() < min || a.positional.size() > max) {
    std::string expected =
        min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
    langError(
        "LANG_ARGS.11",
        {{"name", name}, {"expected", expected}, {"positional_count", std::to_string(a.positional.size())}});
  }
}

void noKeywords(const CallArguments& a, const std::string& name) {
  if (!a.keywords.empty()) {
    langError("LANG_ARGS.6", {{"name", name}, {"name_2", a.keywords[0].name}});
  }
}

const std::string& stringArg(const CallArguments& a, std::size_t i, const std::string& name) {
  if (!a.positional[i].isString()) {
    langError("LANG_TYPE.26", {{"name", name}, {"type_name", a.positional[i].typeName()}});
  }
  return a.positional[i].asString();
}

bool isSpace(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

std::string stripChars(const std::string& s, const CallArguments& a, const std::string& name, bool left,
                       bool right) {
  arity(a, name, 0, 1);
  bool custom = !a.positional.empty() && !a.positional[0].isNone();
  std::string chars = custom ? stringArg(a, 0, name) : std::string();
  auto strip = [&](char c) { return custom ? chars.find(c) != std::string::npos : isSpace(c); };
  std::size_t b = 0;
  std::size_t e = s.size();
  while (left && b < e && strip(s[b])) {
    ++b;
  }
  while (right && e > b && strip(s[e - 1])) {
    --e;
  }
  return s.substr(b, e - b);
}

Value split(const std::string& s, const CallArguments& a) {
  arity(a, "split", 0, 2);
  ValueList out;
  std::int64_t maxSplit = a.positional.size() == 2 ? toIndex(a.positional[1], "maxsplit") : -1;
  if (a.positional.empty() || a.positional[0].isNone()) {
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && isSpace(s[i])) {
        ++i;
      }
      if (i >= s.size()) {
        break;
      }
      if (maxSplit >= 0 && static_cast<std::int64_t>(out.size()) == maxSplit) {
        std::size_t e = s.size();
        while (e > i && isSpace(s[e - 1])) {
          --e;
        }
        out.emplace_back(s.substr(i, e - i));
        break;
      }
      std::size_t j = i;
      while (j < s.size() && !isSpace(s[j])) {
        ++j;
      }
      out.emplace_back(s.substr(i, j - i));
      i = j;
    }
    return Value::list(std::move(out));
  }
  const std::string& sep = stringArg(a, 0, "split");
  if (sep.empty()) {
    langError("LANG_VALUE.30", {});
  }
  std::size_t start = 0;
  for (;;) {
    std::size_t at = s.find(sep, start);
    if (at == std::string::npos || (maxSplit >= 0 && static_cast<std::int64_t>(out.size()) == maxSplit)) {
      out.emplace_back(s.substr(start));
      break;
    }
    out.emplace_back(s.substr(start, at - start));
    start = at + sep.size();
  }
  return Value::list(std::move(out));
}

Value join(Evaluator& ev, const std::string& sep, const CallArguments& a) {
  arity(a, "join", 1, 1);
  std::string out;
  bool first = true;
  for (const Value& item : iterableItems(a.positional[0], ev.options().limits)) {
    if (!item.isString()) {
      langError("LANG_TYPE.27", {{"type_name", item.typeName()}});
    }
    if (!first) {
      out += sep;
    }
    first = false;
    out += item.asString();
    if (static_cast<std::int64_t>(out.size()) > ev.options().limits.maxStringLength) {
      langError("LANG_SIZE.4", {});
    }
  }
  chargeAllocation(static_cast<std::int64_t>(out.size()));
  return Value(std::move(out));
}

std::string justify(const std::string& s, const CallArguments& a, const std::string& name, char how,
                    const RuntimeLimits& limits) {
  arity(a, name, 1, 2);
  std::int64_t width = toIndex(a.positional[0], "width");
  if (width > limits.maxStringLength) {
    langError("LANG_SIZE.4", {});
  }
  char fill = ' ';
  if (a.positional.size() == 2) {
    const std::string& f = stringArg(a, 1, name);
    if (f.size() != 1) {
      langError("LANG_TYPE.28", {{"name", name}});
    }
    fill = f[0];
  }
  auto n = static_cast<std::int64_t>(s.size());
  if (width <= n) {
    return s;
  }
  auto padding = static_cast<std::size_t>(width - n);
  if (how == '<') {
    return s + std::string(padding, fill);
  }
  if (how == '>') {
    return std::string(padding, fill) + s;
  }
  if (how == '0') {
    bool sign = !s.empty() && (s[0] == '-' || s[0] == '+');
    return sign ? s.substr(0, 1) + std::string(padding, '0') + s.substr(1) : std::string(padding, '0') + s;
  }
  std::size_t left = padding / 2 + (padding & static_cast<std::size_t>(width) & 1);
  return std::string(left, fill) + s + std::string(padding - left, fill);
}

std::int64_t countOf(const std::string& s, const std::string& sub) {
  if (sub.empty()) {
    return static_cast<std::int64_t>(s.size()) + 1;
  }
  std::int64_t n = 0;
  for (std::size_t at = s.find(sub); at != std::string::npos; at = s.find(sub, at + sub.size())) {
    ++n;
  }
  return n;
}

Value affixTest(const std::string& s, const CallArguments& a, const std::string& name, bool prefix) {
  arity(a, name, 1, 1);
  auto test = [&](const std::string& x) {
    return x.size() <= s.size() &&
           (prefix ? s.compare(0, x.size(), x) == 0 : s.compare(s.size() - x.size(), x.size(), x) == 0);
  };
  if (a.positional[0].isTuple()) {
    for (const Value& v : a.positional[0].items()) {
      if (v.isString() && test(v.asString())) {
        return Value(true);
      }
    }
    return Value(false);
  }
  return Value(test(stringArg(a, 0, name)));
}

Value stringMethod(Evaluator& ev, const std::string& s, const std::string& name, const CallArguments& a) {
  if (name != "format") {
    noKeywords(a, name);
  }
  auto mapChars = [&](int (*f)(int)) {
    arity(a, name, 0, 0);
    std::string out = s;
    for (char& c : out) {
      c = static_cast<char>(f(static_cast<unsigned char>(c)));
    }
    return Value(std::move(out));
  };
  if (name == "upper") {
    return mapChars([](int c) { return std::toupper(c); });
  }
  if (name == "lower") {
    return mapChars([](int c) { return std::tolower(c); });
  }
  if (name == "strip" || name == "lstrip" || name == "rstrip") {
    return Value(stripChars(s, a, name, name != "rstrip", name != "lstrip"));
  }
  if (name == "split") {
    return split(s, a);
  }
  if (name == "splitlines") {
    arity(a, name, 0, 0);
    ValueList out;
    std::size_t start = 0;
    while (start < s.size()) {
      std::size_t at = s.find('\n', start);
      if (at == std::string::npos) {
        out.emplace_back(s.substr(start));
        break;
      }
      out.emplace_back(s.substr(start, at - start));
      start = at + 1;
    }
    return Value::list(std::move(out));
  }
  if (name == "join") {
    return join(ev, s, a);
  }
  if (name == "replace") {
    arity(a, name, 2, 3);
    const std::string& from = stringArg(a, 0, name);
    const std::string& to = stringArg(a, 1, name);
    std::int64_t limit = a.positional.size() == 3 ? toIndex(a.positional[2], "count") : -1;
    if (from.empty()) {
      return Value(s);
    }
    std::string out;
    std::size_t start = 0;
    std::int64_t done = 0;
    for (std::size_t at = s.find(from); at != std::string::npos && (limit < 0 || done < limit);
         at = s.find(from, start)) {
      out.append(s, start, at - start);
      out += to;
      start = at + from.size();
      ++done;
      if (static_cast<std::int64_t>(out.size()) > ev.options().limits.maxStringLength) {
        langError("LANG_SIZE.4", {});
      }
    }
    out.append(s, start);
    return Value(std::move(out));
  }
  if (name == "startswith" || name == "endswith") {
    return affixTest(s, a, name, name == "startswith");
  }
  if (name == "find" || name == "rfind" || name == "index") {
    arity(a, name, 1, 1);
    const std::string& sub = stringArg(a, 0, name);
    std::size_t at = name == "rfind" ? s.rfind(sub) : s.find(sub);
    if (at == std::string::npos) {
      if (name == "index") {
        langError("LANG_VALUE.31", {{"repr", Value(sub).repr()}});
      }
      return Value(std::int64_t{-1});
    }
    return Value(static_cast<std::int64_t>(at));
  }
  if (name == "count") {
    arity(a, name, 1, 1);
    return Value(countOf(s, stringArg(a, 0, name)));
  }
  if (name == "format") {
    return Value(braceFormat(s, a.positional, a.keywords));
  }
  if (name == "ljust" || name == "rjust" || name == "center") {
    return Value(
        justify(s, a, name, name == "ljust" ? '<' : (name == "rjust" ? '>' : '^'), ev.options().limits));
  }
  if (name == "zfill") {
    return Value(justify(s, a, name, '0', ev.options().limits));
  }
  if (name == "capitalize" || name == "title") {
    arity(a, name, 0, 0);
    std::string out = s;
    bool startOfWord = true;
    for (std::size_t i = 0; i < out.size(); ++i) {
      auto c = static_cast<unsigned char>(out[i]);
      bool upper = name == "title" ? startOfWord : i == 0;
      out[i] = static_cast<char>(upper ? std::toupper(c) : std::tolower(c));
      startOfWord = !std::isalpha(c);
    }
    return Value(std::move(out));
  }
  if (name == "isdigit" || name == "isalpha") {
    arity(a, name, 0, 0);
    bool digit = name == "isdigit";
    bool ok = !s.empty() && std::all_of(s.begin(), s.end(), [&](char c) {
      auto u = static_cast<unsigned char>(c);
      return digit ? std::isdigit(u) != 0 : std::isalpha(u) != 0;
    });
    return Value(ok);
  }
  langError("LANG_ATTR", {{"name", name}});
}

std::size_t indexOf(const ValueList& items, const Value& x, const char* type) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].equals(x)) {
      return i;
    }
  }
  langError("LANG_VALUE.32", {{"repr", x.repr()}, {"type", type}});
}

Value listMethod(Evaluator& ev, const Value& self, const std::string& name, const CallArguments& a,
                 const Pos& at) {
  auto& items = self.asList()->items;
  ev.noteMutated(self);
  const auto maxLength = static_cast<std::size_t>(ev.options().limits.maxSequenceLength);
  if (name != "sort") {
    noKeywords(a, name);
  }
  if (name == "append") {
    arity(a, name, 1, 1);
    if (items.size() >= maxLength) {
      langError("LANG_SIZE.6", {});
    }
    if (items.size() == items.capacity()) { // the list's storage is about to double
      chargeAllocation(static_cast<std::int64_t>(items.capacity() * sizeof(Value)));
    }
    items.push_back(a.positional[0]);
    return Value();
  }
  if (name == "extend") {
    arity(a, name, 1, 1);
    ValueList more = iterableItems(a.positional[0], ev.options().limits);
    if (items.size() + more.size() > maxLength) {
      langError("LANG_SIZE.6", {});
    }
    items.insert(items.end(), more.begin(), more.end());
    return Value();
  }
  if (name == "index") {
    arity(a, name, 1, 1);
    return Value(static_cast<std::int64_t>(indexOf(items, a.positional[0], "list")));
  }
  if (name == "count") {
    arity(a, name, 1, 1);
    return Value(static_cast<std::int64_t>(std::count_if(
        items.begin(), items.end(), [&](const Value& v) { return v.equals(a.positional[0]); })));
  }
  if (name == "pop") {
    arity(a, name, 0, 1);
    if (items.empty()) {
      langError("LANG_INDEX.2", {});
    }
    std::size_t i = a.positional.empty()
                        ? items.size() - 1
                        : normalizeIndex(toIndex(a.positional[0], "pop index"), items.size(), "list");
    Value v = items[i];
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(i));
    return v;
  }
  if (name == "insert") {
    arity(a, name, 2, 2);
    if (items.size() >= maxLength) {
      langError("LANG_SIZE.6", {});
    }
    std::int64_t i = toIndex(a.positional[0], "insert index");
    auto n = static_cast<std::int64_t>(items.size());
    i = i < 0 ? std::max<std::int64_t>(0, i + n) : std::min(i, n);
    items.insert(items.begin() + i, a.positional[1]);
    return Value();
  }
  if (name == "remove") {
    arity(a, name, 1, 1);
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(indexOf(items, a.positional[0], "list")));
    return Value();
  }
  if (name == "reverse") {
    arity(a, name, 0, 0);
    std::reverse(items.begin(), items.end());
    return Value();
  }
  if (name == "copy") {
    arity(a, name, 0, 0);
    return Value::list(items);
  }
  // sort(key=None, reverse=False): through sorted()
  arity(a, name, 0, 0);
  CallArguments args = a;
  args.positional = {self};
  Value sortedList = callBuiltin(ev, Builtin(Builtin::Id::Sorted, "sort"), args, at);
  items = sortedList.items();
  return Value();
}

Value dictMethod(Evaluator& ev, const Value& self, const std::string& name, const CallArguments& a) {
  auto& dict = *self.asDict();
  ev.noteMutated(self);
  noKeywords(a, name);
  if (name == "keys" || name == "values" || name == "items") {
    arity(a, name, 0, 0);
    ValueList out;
    for (const auto& [k, v] : dict.items) {
      out.push_back(name == "keys" ? k : (name == "values" ? v : Value::tuple({k, v})));
    }
    return Value::list(std::move(out));
  }
  if (name == "get") {
    arity(a, name, 1, 2);
    checkHashable(a.positional[0]);
    const Value* v = dictFind(dict, a.positional[0]);
    return v != nullptr ? *v : (a.positional.size() == 2 ? a.positional[1] : Value());
  }
  if (name == "pop") {
    arity(a, name, 1, 2);
    for (auto it = dict.items.begin(); it != dict.items.end(); ++it) {
      if (it->first.equals(a.positional[0])) {
        Value v = it->second;
        dict.items.erase(it);
        return v;
      }
    }
    if (a.positional.size() == 2) {
      return a.positional[1];
    }
    langError("LANG_KEY", {{"repr", a.positional[0].repr()}});
  }
  if (name == "update") {
    arity(a, name, 1, 1);
    if (!a.positional[0].isDict()) {
      langError("LANG_TYPE.29", {});
    }
    for (const auto& [k, v] : a.positional[0].asDict()->items) {
      dictSet(dict, k, v);
    }
    return Value();
  }
  if (name == "setdefault") {
    arity(a, name, 1, 2);
    if (const Value* v = dictFind(dict, a.positional[0])) {
      return *v;
    }
    Value d = a.positional.size() == 2 ? a.positional[1] : Value();
    dictSet(dict, a.positional[0], d);
    return d;
  }
  if (name == "clear") {
    arity(a, name, 0, 0);
    dict.items.clear();
    return Value();
  }
  arity(a, name, 0, 0); // copy
  auto copy = std::make_shared<DictObject>(dict);
  return Value(copy);
}

} // namespace

bool hasMethod(const Value& object, const std::string& name) {
  if (object.isString()) {
    return among(stringMethods, name);
  }
  if (object.isList()) {
    return among(listMethods, name);
  }
  if (object.isDict()) {
    return among(dictMethods, name);
  }
  if (object.isTuple()) {
    return among(tupleMethods, name);
  }
  return false;
}

std::optional<Value> callMethod(Evaluator& ev, const Value& object, const std::string& name,
                                const CallArguments& args, const Pos& at) {
  try {
    if (object.isString()) {
      return stringMethod(ev, object.asString(), name, args);
    }
    if (object.isList()) {
      return listMethod(ev, object, name, args, at);
    }
    if (object.isDict()) {
      return dictMethod(ev, object, name, args);
    }
    if (object.isTuple()) {
      noKeywords(args, name);
      arity(args, name, 1, 1);
      const ValueList& items = object.items();
      if (name == "index") {
        return Value(static_cast<std::int64_t>(indexOf(items, args.positional[0], "tuple")));
      }
      return Value(static_cast<std::int64_t>(std::count_if(
          items.begin(), items.end(), [&](const Value& v) { return v.equals(args.positional[0]); })));
    }
  } catch (const LangError& e) {
    ev.raise(at, e);
  }
  return std::nullopt;
}

} // namespace stella
