// String formatting with Python's rules: `'%8.3f' % x`, `'{:>10}'.format(s)`, f-string fields,
// and the int()/float() conversions.
#include "Runtime.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stella {

namespace {

bool isIntLike(const Value& v) {
  return v.isInt() || v.isBool();
}

std::string printfNumber(const std::string& spec, double value) {
  char buffer[512];
  int n = std::snprintf(buffer, sizeof buffer, spec.c_str(), value);
  if (n < 0) {
    return {};
  }
  if (static_cast<std::size_t>(n) < sizeof buffer) {
    return std::string(buffer, static_cast<std::size_t>(n));
  }
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), spec.c_str(), value);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

std::string printfInt(const std::string& spec, long long value) {
  char buffer[512];
  int n = std::snprintf(buffer, sizeof buffer, spec.c_str(), value);
  if (n < 0) {
    return {};
  }
  if (static_cast<std::size_t>(n) < sizeof buffer) {
    return std::string(buffer, static_cast<std::size_t>(n));
  }
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), spec.c_str(), value);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

constexpr int maxWidth = 10000; // a field wider than this is refused

void checkWidth(long width) {
  if (width > maxWidth) {
    langError("LANG_VALUE.5", {{"max_width", std::to_string(maxWidth)}});
  }
}

std::string pad(std::string body, long width, bool left, char fill = ' ') {
  if (static_cast<long>(body.size()) >= width) {
    return body;
  }
  std::string padding(static_cast<std::size_t>(width) - body.size(), fill);
  return left ? body + padding : padding + body;
}

} // namespace

std::string percentFormat(const std::string& format, const Value& args) {
  ValueList single;
  const ValueList* list = nullptr;
  const DictObject* mapping = nullptr;
  if (args.isTuple()) {
    list = &args.items();
  } else if (args.isDict()) {
    mapping = args.asDict().get();
    single.push_back(args);
    list = &single;
  } else {
    single.push_back(args);
    list = &single;
  }
  std::size_t next = 0;
  bool usedMapping = false;
  auto take = [&]() -> const Value& {
    if (next >= list->size()) {
      langError("LANG_VALUE.6", {});
    }
    return (*list)[next++];
  };
  std::string out;
  for (std::size_t i = 0; i < format.size(); ++i) {
    char c = format[i];
    if (c != '%') {
      out += c;
      continue;
    }
    if (++i >= format.size()) {
      langError("LANG_VALUE.7", {});
    }
    const Value* mapped = nullptr;
    if (format[i] == '(') {
      std::size_t close = format.find(')', i);
      if (close == std::string::npos || mapping == nullptr) {
        langError(mapping == nullptr ? "LANG_VALUE.mapping" : "LANG_VALUE.format_key");
      }
      std::string key = format.substr(i + 1, close - i - 1);
      mapped = dictFind(*mapping, Value(key));
      if (mapped == nullptr) {
        langError("LANG_KEY.2", {{"key", key}});
      }
      usedMapping = true;
      i = close + 1;
    }
    std::string flags;
    while (i < format.size() && std::string_view("-+ 0#").find(format[i]) != std::string_view::npos) {
      flags += format[i++];
    }
    std::string width;
    if (i < format.size() && format[i] == '*') {
      width = std::to_string(toIndex(take(), "* width"));
      ++i;
    }
    while (i < format.size() && format[i] >= '0' && format[i] <= '9') {
      width += format[i++];
    }
    std::string precision;
    bool hasPrecision = false;
    if (i < format.size() && format[i] == '.') {
      hasPrecision = true;
      ++i;
      if (i < format.size() && format[i] == '*') {
        precision = std::to_string(toIndex(take(), "* precision"));
        ++i;
      }
      while (i < format.size() && format[i] >= '0' && format[i] <= '9') {
        precision += format[i++];
      }
    }
    while (i < format.size() && (format[i] == 'l' || format[i] == 'h' || format[i] == 'L')) {
      ++i;
    }
    if (i >= format.size()) {
      langError("LANG_VALUE.8", {});
    }
    if (width.size() > 6 || precision.size() > 6) {
      checkWidth(maxWidth + 1);
    }
    checkWidth(width.empty() ? 0 : std::stol(width));
    checkWidth(precision.empty() ? 0 : std::stol(precision));
    char type = format[i];
    if (type == '%') {
      out += '%';
      continue;
    }
    const Value& v = mapped != nullptr ? *mapped : take();
    std::string spec =
        "%" + flags + width + (hasPrecision ? "." + (precision.empty() ? "0" : precision) : "");
    switch (type) {
    case 'd':
    case 'i':
    case 'u': {
      if (!v.isNumber()) {
        langError("LANG_TYPE.13", {{"type", type}, {"type_name", v.typeName()}});
      }
      long long n = isIntLike(v) ? v.asInt() : static_cast<long long>(toInt(v).asInt());
      out += printfInt(spec + "lld", n);
      break;
    }
    case 'x':
    case 'X':
    case 'o':
      if (!isIntLike(v)) {
        langError("LANG_TYPE.14", {{"type", type}, {"type_name", v.typeName()}});
      }
      out += printfInt(spec + "ll" + type, v.asInt());
      break;
    case 'e':
    case 'E':
    case 'f':
    case 'F':
    case 'g':
    case 'G':
      if (!v.isNumber()) {
        langError("LANG_TYPE.15", {{"type", type}, {"type_name", v.typeName()}});
      }
      out += printfNumber(spec + type, v.asReal());
      break;
    case 's':
    case 'r':
    case 'a': {
      std::string text = type == 's' ? v.str() : v.repr();
      if (hasPrecision && !precision.empty() && std::stoul(precision) < text.size()) {
        text.resize(std::stoul(precision));
      }
      out += pad(text, width.empty() ? 0 : std::stol(width), flags.find('-') != std::string::npos);
      break;
    }
    case 'c':
      if (v.isString() && v.asString().size() == 1) {
        out += v.asString();
      } else if (isIntLike(v) && v.asInt() >= 0 && v.asInt() < 128) {
        out += static_cast<char>(v.asInt());
      } else {
        langError("LANG_TYPE.16", {});
      }
      break;
    default:
      langError("LANG_VALUE.9", {{"type", type}});
    }
  }
  if (!usedMapping && mapping == nullptr && next < list->size()) {
    langError("LANG_VALUE.10", {});
  }
  return out;
}

namespace {

struct FormatSpec {
  char fill = ' ';
  char align = 0;
  char sign = '-';
  bool alternate = false;
  long width = 0;
  char grouping = 0;
  long precision = -1;
  char type = 0;
};

FormatSpec parseSpec(const std::string& spec) {
  FormatSpec f;
  std::size_t i = 0;
  auto isAlign = [](char c) { return c == '<' || c == '>' || c == '=' || c == '^'; };
  if (spec.size() >= 2 && isAlign(spec[1])) {
    f.fill = spec[0];
    f.align = spec[1];
    i = 2;
  } else if (!spec.empty() && isAlign(spec[0])) {
    f.align = spec[0];
    i = 1;
  }
  if (i < spec.size() && (spec[i] == '+' || spec[i] == '-' || spec[i] == ' ')) {
    f.sign = spec[i++];
  }
  if (i < spec.size() && spec[i] == '#') {
    f.alternate = true;
    ++i;
  }
  if (i < spec.size() && spec[i] == '0') {
    if (f.align == 0) {
      f.fill = '0';
      f.align = '=';
    }
    ++i;
  }
  std::string digits;
  while (i < spec.size() && spec[i] >= '0' && spec[i] <= '9') {
    digits += spec[i++];
  }
  if (digits.size() > 6) {
    checkWidth(maxWidth + 1);
  }
  f.width = digits.empty() ? 0 : std::stol(digits);
  checkWidth(f.width);
  if (i < spec.size() && (spec[i] == ',' || spec[i] == '_')) {
    f.grouping = spec[i++];
  }
  if (i < spec.size() && spec[i] == '.') {
    ++i;
    digits.clear();
    while (i < spec.size() && spec[i] >= '0' && spec[i] <= '9') {
      digits += spec[i++];
    }
    if (digits.empty() || digits.size() > 6) {
      langError("LANG_VALUE.11", {{"spec", spec}});
    }
    f.precision = std::stol(digits);
    checkWidth(f.precision);
  }
  if (i < spec.size()) {
    f.type = spec[i++];
  }
  if (i != spec.size()) {
    langError("LANG_VALUE.12", {{"spec", spec}});
  }
  return f;
}

std::string group(const std::string& digits, char sep) {
  std::string out;
  int count = 0;
  for (auto it = digits.rbegin(); it != digits.rend(); ++it) {
    if (count > 0 && count % 3 == 0) {
      out += sep;
    }
    out += *it;
    ++count;
  }
  return std::string(out.rbegin(), out.rend());
}

std::string align(const FormatSpec& f, const std::string& sign, const std::string& body, char defaultAlign) {
  char a = f.align == 0 ? defaultAlign : f.align;
  long total = static_cast<long>(sign.size() + body.size());
  if (total >= f.width) {
    return sign + body;
  }
  std::size_t padding = static_cast<std::size_t>(f.width - total);
  switch (a) {
  case '<':
    return sign + body + std::string(padding, f.fill);
  case '^':
    return std::string(padding / 2, f.fill) + sign + body + std::string(padding - padding / 2, f.fill);
  case '=':
    return sign + std::string(padding, f.fill) + body;
  default:
    return std::string(padding, f.fill) + sign + body;
  }
}

std::string formatReal(const FormatSpec& f, double x) {
  std::string sign =
      std::signbit(x) && !std::isnan(x) ? "-" : (f.sign == '+' ? "+" : (f.sign == ' ' ? " " : ""));
  double a = std::fabs(x);
  std::string body;
  char type = f.type;
  if (type == '%') {
    body = printfNumber("%." + std::to_string(f.precision < 0 ? 6 : f.precision) + "f", a * 100.0) + "%";
  } else if (type == 0 && f.precision < 0) {
    body = Value(a).repr();
  } else {
    if (type == 0) {
      type = 'g';
    }
    body = printfNumber(std::string("%") + (f.alternate ? "#" : "") + "." +
                            std::to_string(f.precision < 0 ? 6 : f.precision) + type,
                        a);
  }
  if (f.grouping != 0) {
    std::size_t end = body.find_first_not_of("0123456789");
    if (end == std::string::npos) {
      end = body.size();
    }
    body = group(body.substr(0, end), f.grouping) + body.substr(end);
  }
  return align(f, sign, body, '>');
}

std::string formatInt(const FormatSpec& f, std::int64_t n) {
  std::string sign = n < 0 ? "-" : (f.sign == '+' ? "+" : (f.sign == ' ' ? " " : ""));
  auto magnitude = n < 0 ? static_cast<std::uint64_t>(-(n + 1)) + 1 : static_cast<std::uint64_t>(n);
  std::string body;
  switch (f.type) {
  case 0:
  case 'd':
  case 'n':
    body = std::to_string(magnitude);
    break;
  case 'x':
  case 'X':
  case 'o':
  case 'b': {
    int base = f.type == 'o' ? 8 : (f.type == 'b' ? 2 : 16);
    const char* digits = f.type == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
    do {
      body.insert(body.begin(), digits[magnitude % static_cast<unsigned>(base)]);
      magnitude /= static_cast<unsigned>(base);
    } while (magnitude > 0);
    if (f.alternate) {
      body = std::string("0") + (f.type == 'o' ? "o" : (f.type == 'b' ? "b" : (f.type == 'X' ? "X" : "x"))) +
             body;
    }
    break;
  }
  case 'c':
    body = std::string(1, static_cast<char>(n));
    sign.clear();
    break;
  default:
    langError("LANG_VALUE.13", {{"type", f.type}});
  }
  if (f.grouping != 0) {
    body = group(body, f.grouping);
  }
  return align(f, sign, body, '>');
}

} // namespace

std::string formatWithSpec(const Value& value, const std::string& spec) {
  if (spec.empty()) {
    return value.str();
  }
  FormatSpec f = parseSpec(spec);
  if (isIntLike(value) && std::string_view("eEfFgG%").find(f.type) == std::string_view::npos) {
    return formatInt(f, value.asInt());
  }
  if (value.isNumber()) {
    if (f.type != 0 && std::string_view("eEfFgG%").find(f.type) == std::string_view::npos) {
      langError("LANG_VALUE.14", {{"type", f.type}});
    }
    return formatReal(f, value.asReal());
  }
  if (f.type != 0 && f.type != 's') {
    langError("LANG_VALUE.15", {{"type", f.type}, {"type_name", value.typeName()}});
  }
  std::string text = value.str();
  if (f.precision >= 0 && static_cast<std::size_t>(f.precision) < text.size()) {
    text.resize(static_cast<std::size_t>(f.precision));
  }
  return align(f, "", text, '<');
}

std::string braceFormat(const std::string& format, const ValueList& positional,
                        const std::vector<KeywordArgument>& keywords) {
  std::string out;
  std::size_t autoIndex = 0;
  for (std::size_t i = 0; i < format.size(); ++i) {
    char c = format[i];
    if (c == '}') {
      if (i + 1 < format.size() && format[i + 1] == '}') {
        ++i;
        out += '}';
        continue;
      }
      langError("LANG_VALUE.16", {});
    }
    if (c != '{') {
      out += c;
      continue;
    }
    if (i + 1 < format.size() && format[i + 1] == '{') {
      ++i;
      out += '{';
      continue;
    }
    std::size_t close = format.find('}', i);
    if (close == std::string::npos) {
      langError("LANG_VALUE.17", {});
    }
    std::string field = format.substr(i + 1, close - i - 1);
    i = close;
    std::string spec;
    char conversion = 0;
    std::size_t colon = field.find(':');
    if (colon != std::string::npos) {
      spec = field.substr(colon + 1);
      field.resize(colon);
    }
    std::size_t bang = field.find('!');
    if (bang != std::string::npos) {
      conversion = bang + 1 < field.size() ? field[bang + 1] : '?';
      field.resize(bang);
    }
    const Value* v = nullptr;
    if (field.empty() || (field[0] >= '0' && field[0] <= '9')) {
      std::size_t index = autoIndex++;
      if (!field.empty()) {
        if (field.find_first_not_of("0123456789") != std::string::npos || field.size() > 6) {
          langError("LANG_VALUE.18", {{"field", field}});
        }
        index = std::stoul(field);
      }
      if (index >= positional.size()) {
        langError("LANG_INDEX", {{"field", field}, {"positional_count", std::to_string(positional.size())}});
      }
      v = &positional[index];
    } else {
      for (const auto& kw : keywords) {
        if (kw.name == field) {
          v = kw.value.get();
        }
      }
      if (v == nullptr) {
        langError("LANG_KEY.3", {{"field", field}});
      }
    }
    Value shown = *v;
    if (conversion == 'r' || conversion == 'a') {
      shown = Value(v->repr());
    } else if (conversion == 's') {
      shown = Value(v->str());
    } else if (conversion != 0) {
      langError("LANG_VALUE.19", {});
    }
    out += formatWithSpec(shown, spec);
  }
  return out;
}

namespace {
std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) {
    s.remove_prefix(1);
  }
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) {
    s.remove_suffix(1);
  }
  return s;
}
} // namespace

Value toInt(const Value& v) {
  if (isIntLike(v)) {
    return Value(v.asInt());
  }
  if (v.isReal()) {
    double d = std::trunc(v.asReal());
    if (!std::isfinite(d) || d >= 9.2e18 || d <= -9.2e18) {
      langError("LANG_VALUE.20", {{"repr", v.repr()}});
    }
    return Value(static_cast<std::int64_t>(d));
  }
  if (v.isString()) {
    std::string_view s = trim(v.asString());
    std::string digits;
    for (char c : s) {
      if (c != '_') {
        digits += c;
      }
    }
    std::int64_t n = 0;
    const char* begin = digits.data();
    if (!digits.empty() && digits[0] == '+') {
      ++begin;
    }
    auto [ptr, ec] = std::from_chars(begin, digits.data() + digits.size(), n);
    if (ec != std::errc() || ptr != digits.data() + digits.size() || digits.empty()) {
      langError("LANG_VALUE.21", {{"repr", v.repr()}});
    }
    return Value(n);
  }
  langError("LANG_TYPE.17", {{"type_name", v.typeName()}});
}

Value toFloat(const Value& v) {
  if (v.isNumber()) {
    return Value(v.asReal());
  }
  if (v.isString()) {
    std::string s(trim(v.asString()));
    std::string lower;
    for (char c : s) {
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    std::string_view body = lower;
    bool negative = false;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
      negative = body[0] == '-';
      body.remove_prefix(1);
    }
    if (body == "inf" || body == "infinity") {
      return Value(negative ? -std::numeric_limits<double>::infinity()
                            : std::numeric_limits<double>::infinity());
    }
    if (body == "nan") {
      return Value(std::numeric_limits<double>::quiet_NaN());
    }
    double d = 0.0;
    auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), d);
    if (body.empty() || ptr != body.data() + body.size() ||
        (ec != std::errc() && ec != std::errc::result_out_of_range)) {
      langError("LANG_VALUE.22", {{"repr", v.repr()}});
    }
    if (ec == std::errc::result_out_of_range) { // Python: '1e400' is inf, '1e-400' is 0.0
      const std::size_t e = body.find_first_of("eE");
      const bool tiny = e != std::string::npos && e + 1 < body.size() && body[e + 1] == '-';
      d = tiny ? 0.0 : std::numeric_limits<double>::infinity();
    }
    return Value(negative ? -d : d);
  }
  langError("LANG_TYPE.18", {{"type_name", v.typeName()}});
}

double toReal(const Value& v, const char* what) {
  if (!v.isNumber()) {
    langError("LANG_TYPE.19", {{"what", std::string(what)}, {"type_name", v.typeName()}});
  }
  return v.asReal();
}

} // namespace stella
