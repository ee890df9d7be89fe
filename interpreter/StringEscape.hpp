#pragma once
// The one place where a string is escaped to be written between quotes: Python's repr() of a
// string, the string parts of f-strings printed by the formatter, and JSON strings written by
// the catalogue.

#include <string>
#include <string_view>

namespace stella {

enum class EscapeStyle {
  Python,      // \\ \n \r \t and the quote character; other characters as they are
  FStringBody, // as Python, and { } doubled (literal braces of an f-string)
  Json         // \\ \n \r \t \" and the other control characters as \u00XX
};

// Appends `text` to `out`, escaped for a literal delimited by `quote` (the quotes not included).
void appendEscaped(std::string& out, std::string_view text, char quote, EscapeStyle style);

// `text` between `quote` characters, escaped.
std::string quoted(std::string_view text, char quote, EscapeStyle style);

} // namespace stella
