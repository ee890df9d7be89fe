// Decoding of the backslash escapes of string literals (Python's rules).
#include "Lexer.hpp"
#include "LexerTables.hpp"

namespace stella {

using namespace lexing;

namespace {

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | ((code >> 18) & 0x07));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

} // namespace

// Decodes the escapes of a (non-raw) string body, Python's rules; unknown escapes are kept.
std::string decodeEscapes(std::string_view body) {
  std::string out;
  out.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    char c = body[i];
    if (c != '\\' || i + 1 >= body.size()) {
      out += c;
      continue;
    }
    char e = body[++i];
    switch (e) {
    case '\n':
      break;
    case '\r':
      if (i + 1 < body.size() && body[i + 1] == '\n') {
        ++i;
      }
      break;
    case '\\':
    case '\'':
    case '"':
      out += e;
      break;
    case 'n':
      out += '\n';
      break;
    case 't':
      out += '\t';
      break;
    case 'r':
      out += '\r';
      break;
    case 'a':
      out += '\a';
      break;
    case 'b':
      out += '\b';
      break;
    case 'f':
      out += '\f';
      break;
    case 'v':
      out += '\v';
      break;
    case 'x':
    case 'u':
    case 'U': {
      std::size_t digits = e == 'x' ? 2 : (e == 'u' ? 4 : 8);
      std::uint32_t code = 0;
      std::size_t k = 0;
      for (; k < digits && i + 1 + k < body.size() && hexDigit(body[i + 1 + k]) >= 0; ++k) {
        code = code * 16 + static_cast<std::uint32_t>(hexDigit(body[i + 1 + k]));
      }
      if (k == digits && code <= 0x10FFFF) {
        appendUtf8(out, code);
        i += digits;
      } else {
        out += '\\';
        out += e;
      }
      break;
    }
    default:
      if (e >= '0' && e <= '7') {
        std::uint32_t code = 0;
        std::size_t k = 0;
        for (; k < 3 && i + k < body.size() && body[i + k] >= '0' && body[i + k] <= '7'; ++k) {
          code = code * 8 + static_cast<std::uint32_t>(body[i + k] - '0');
        }
        appendUtf8(out, code);
        i += k - 1;
      } else {
        out += '\\';
        out += e;
      }
    }
  }
  return out;
}

} // namespace stella
