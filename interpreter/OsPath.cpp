// The sandboxed part of Python's `os` module that command files may import: `os.sep` and the
// pure string functions of `os.path` (POSIX rules, as Python's posixpath). Nothing here reaches
// the file system, the environment or a process.
#include "Evaluator.hpp"
#include "Runtime.hpp"

namespace stella {

namespace {

const std::string& stringArgument(const CallArguments& a, std::size_t i, const char* function) {
  if (i >= a.positional.size() || !a.positional[i].isString()) {
    langError("LANG_TYPE.8",
              {{"function", function},
               {"value", (i < a.positional.size() ? ", found '" + a.positional[i].typeName() + "'" : "")}});
  }
  return a.positional[i].asString();
}

void exactly(const CallArguments& a, std::size_t n, const char* function) {
  if (a.positional.size() != n || !a.keywords.empty()) {
    langError("LANG_ARGS.7", {{"function", function},
                              {"n", std::to_string(n)},
                              {"value", (n == 1 ? "" : "s")},
                              {"positional_count", std::to_string(a.positional.size() + a.keywords.size())}});
  }
}

// posixpath.split: the head keeps its trailing slashes only when it is made of slashes alone.
std::pair<std::string, std::string> splitPath(const std::string& p) {
  std::size_t i = p.rfind('/') == std::string::npos ? 0 : p.rfind('/') + 1;
  std::string head = p.substr(0, i);
  std::string tail = p.substr(i);
  if (!head.empty() && head.find_first_not_of('/') != std::string::npos) {
    head.erase(head.find_last_not_of('/') + 1);
  }
  return {head, tail};
}

// posixpath.splitext: the extension starts at the last dot of the last component, unless that
// component is only leading dots before it ('.bashrc' has no extension).
std::pair<std::string, std::string> splitExtension(const std::string& p) {
  std::size_t sep = p.rfind('/');
  std::size_t dot = p.rfind('.');
  std::size_t start = sep == std::string::npos ? 0 : sep + 1;
  if (dot == std::string::npos || (sep != std::string::npos && dot < sep)) {
    return {p, ""};
  }
  for (std::size_t i = start; i < dot; ++i) {
    if (p[i] != '.') {
      return {p.substr(0, dot), p.substr(dot)};
    }
  }
  return {p, ""};
}

Value join(const CallArguments& a) {
  if (a.positional.empty() || !a.keywords.empty()) {
    langError("LANG_ARGS.8", {});
  }
  std::string path = stringArgument(a, 0, "join");
  for (std::size_t i = 1; i < a.positional.size(); ++i) {
    const std::string& b = stringArgument(a, i, "join");
    if (!b.empty() && b[0] == '/') {
      path = b;
    } else if (path.empty() || path.back() == '/') {
      path += b;
    } else {
      path += "/" + b;
    }
  }
  return Value(path);
}

} // namespace

const std::unordered_map<std::string, Value>& osPathNames() {
  static const std::unordered_map<std::string, Value> names = [] {
    std::unordered_map<std::string, Value> n;
    n.emplace("sep", Value("/"));
    n.emplace("join", makeNativeFunction("join", join));
    n.emplace("basename", makeNativeFunction("basename", [](const CallArguments& a) {
                exactly(a, 1, "basename");
                return Value(splitPath(stringArgument(a, 0, "basename")).second);
              }));
    n.emplace("dirname", makeNativeFunction("dirname", [](const CallArguments& a) {
                exactly(a, 1, "dirname");
                return Value(splitPath(stringArgument(a, 0, "dirname")).first);
              }));
    n.emplace("split", makeNativeFunction("split", [](const CallArguments& a) {
                exactly(a, 1, "split");
                auto [head, tail] = splitPath(stringArgument(a, 0, "split"));
                return Value::tuple({Value(head), Value(tail)});
              }));
    n.emplace("splitext", makeNativeFunction("splitext", [](const CallArguments& a) {
                exactly(a, 1, "splitext");
                auto [root, ext] = splitExtension(stringArgument(a, 0, "splitext"));
                return Value::tuple({Value(root), Value(ext)});
              }));
    n.emplace("isabs", makeNativeFunction("isabs", [](const CallArguments& a) {
                exactly(a, 1, "isabs");
                const std::string& p = stringArgument(a, 0, "isabs");
                return Value(!p.empty() && p[0] == '/');
              }));
    return n;
  }();
  return names;
}

} // namespace stella
