// Escaping of strings written between quotes (see StringEscape.hpp).
#include "StringEscape.hpp"

#include <fmt/format.h>

namespace stella {

void appendEscaped(std::string& out, std::string_view text, char quote, EscapeStyle style) {
  for (char c : text) {
    switch (c) {
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    case '\r':
      out += "\\r";
      break;
    case '{':
    case '}':
      out += c;
      if (style == EscapeStyle::FStringBody) {
        out += c;
      }
      break;
    default:
      if (c == quote) {
        out += '\\';
        out += c;
      } else if (style == EscapeStyle::Json && static_cast<unsigned char>(c) < 0x20) {
        out += fmt::format("\\u{:04x}", static_cast<int>(c));
      } else {
        out += c;
      }
    }
  }
}

std::string quoted(std::string_view text, char quote, EscapeStyle style) {
  std::string out(1, quote);
  appendEscaped(out, text, quote, style);
  out += quote;
  return out;
}

} // namespace stella
