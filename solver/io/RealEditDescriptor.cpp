// Fortran edit descriptors of real values (see RealEditDescriptor.hpp).

#include "solver/io/RealEditDescriptor.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <regex>

namespace stella {

std::optional<RealEditDescriptor> parseRealEditDescriptor(const std::string& text) {
  std::string t;
  for (const char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c))) {
      t += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  static const std::regex form(R"(^(?:([-+]?\d+)P,?)?(ES|E|D|F)(\d+)\.(\d+)$)");
  std::smatch m;
  if (!std::regex_match(t, m, form)) {
    return std::nullopt;
  }
  RealEditDescriptor d;
  const std::string kind = m[2].str();
  d.kind = kind == "F" ? 'F' : 'E';
  d.exponentLetter = kind == "D" ? 'D' : 'E';
  d.scale = kind == "ES" ? 1 : (m[1].matched ? std::atoi(m[1].str().c_str()) : 0);
  d.width = std::atoi(m[3].str().c_str());
  d.digits = std::atoi(m[4].str().c_str());
  if (d.width < 1 || d.width > 60 || d.digits > 40 || (m[1].matched && (kind == "F" || kind == "ES")) ||
      (d.kind == 'E' && (d.scale < 0 || d.scale > d.digits + 1 || (d.scale == 0 && d.digits < 1)))) {
    return std::nullopt;
  }
  return d;
}

namespace {

// Ew.d with scale k: k digits before the point, d - k + 1 after it (k >= 1), or 0.d digits
// (k = 0); the exponent so that the value is unchanged.
std::string exponentForm(const RealEditDescriptor& d, double value) {
  if (!std::isfinite(value)) {
    return fmt::format("{}", value);
  }
  // Scientific notation with the significant digits the descriptor shows: d (k = 0) or d + 1.
  const int significant = d.scale == 0 ? d.digits : d.digits + 1;
  const std::string sci = fmt::format("{:.{}e}", std::abs(value), significant - 1);
  const auto e = sci.find('e');
  std::string mantissa = sci.substr(0, e);
  int exponent = std::atoi(sci.substr(e + 1).c_str());
  std::string digits;
  for (const char c : mantissa) {
    if (c != '.') {
      digits += c;
    }
  }
  std::string body;
  if (value == 0.0) {
    body = d.scale == 0 ? "0." + digits
                        : digits.substr(0, static_cast<std::size_t>(d.scale)) + "." +
                              digits.substr(static_cast<std::size_t>(d.scale));
    exponent = 0;
  } else if (d.scale == 0) {
    body = "0." + digits;
    exponent += 1;
  } else {
    body = digits.substr(0, static_cast<std::size_t>(d.scale)) + "." +
           digits.substr(static_cast<std::size_t>(d.scale));
    exponent -= d.scale - 1;
  }
  return fmt::format("{}{}{}{}{:02d}", std::signbit(value) && value != 0.0 ? "-" : "", body, d.exponentLetter,
                     exponent < 0 ? '-' : '+', std::abs(exponent));
}

} // namespace

std::string formatReal(const RealEditDescriptor& d, double value) {
  const std::string s = d.kind == 'F' ? fmt::format("{:.{}f}", value, d.digits) : exponentForm(d, value);
  return fmt::format("{:>{}}", s, d.width);
}

} // namespace stella
