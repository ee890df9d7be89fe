// Source encodings of command files (PEP 263): declaration, decoding of 8-bit encodings, UTF-8
// validation.
#include "SourceEncoding.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>

namespace stella {

namespace {

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == '.';
}

std::optional<EncodingDeclaration> declarationOnLine(std::string_view line, int number) {
  std::size_t i = line.find_first_not_of(" \t\f");
  if (i == std::string_view::npos || line[i] != '#') {
    return std::nullopt;
  }
  for (std::size_t at = line.find("coding", i); at != std::string_view::npos;
       at = line.find("coding", at + 1)) {
    std::size_t j = at + 6;
    if (j >= line.size() || (line[j] != ':' && line[j] != '=')) {
      continue;
    }
    ++j;
    while (j < line.size() && (line[j] == ' ' || line[j] == '\t')) {
      ++j;
    }
    std::size_t end = j;
    while (end < line.size() && isNameChar(line[end])) {
      ++end;
    }
    if (end > j) {
      return EncodingDeclaration{std::string(line.substr(j, end - j)), number, j + 1};
    }
  }
  return std::nullopt;
}

std::string normalisedName(const std::string& name) {
  std::string out;
  for (char c : name) {
    out += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

// Windows-1252 0x80..0x9F (0 where the code page leaves the byte undefined: kept as U+0080+n).
constexpr std::array<std::uint16_t, 32> windows1252High = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

std::uint32_t codePoint(unsigned char byte, SourceEncoding encoding) {
  if (encoding == SourceEncoding::Windows1252 && byte >= 0x80 && byte < 0xA0) {
    const std::uint16_t mapped = windows1252High[byte - 0x80];
    return mapped != 0 ? mapped : byte;
  }
  if (encoding == SourceEncoding::Latin9) { // ISO-8859-15: eight differences from Latin-1
    switch (byte) {
    case 0xA4:
      return 0x20AC;
    case 0xA6:
      return 0x0160;
    case 0xA8:
      return 0x0161;
    case 0xB4:
      return 0x017D;
    case 0xB8:
      return 0x017E;
    case 0xBC:
      return 0x0152;
    case 0xBD:
      return 0x0153;
    case 0xBE:
      return 0x0178;
    default:
      break;
    }
  }
  return byte;
}

} // namespace

std::optional<EncodingDeclaration> declaredEncoding(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") {
    text.remove_prefix(3);
  }
  std::size_t end = text.find('\n');
  std::string_view first = text.substr(0, end);
  if (auto d = declarationOnLine(first, 1)) {
    return d;
  }
  // PEP 263: line 2 counts only when line 1 is a comment or blank
  const std::size_t i = first.find_first_not_of(" \t\f\r");
  if (end == std::string_view::npos || (i != std::string_view::npos && first[i] != '#')) {
    return std::nullopt;
  }
  std::string_view rest = text.substr(end + 1);
  return declarationOnLine(rest.substr(0, rest.find('\n')), 2);
}

SourceEncoding encodingNamed(const std::string& name) {
  const std::string n = normalisedName(name);
  if (n == "utf-8" || n == "utf8" || n.rfind("utf-8-", 0) == 0) {
    return SourceEncoding::Utf8;
  }
  if (n == "latin-1" || n == "latin1" || n == "iso-8859-1" || n == "iso8859-1" || n == "l1" || n == "cp819" ||
      n == "iso-latin-1") {
    return SourceEncoding::Latin1;
  }
  if (n == "iso-8859-15" || n == "iso8859-15" || n == "latin-9" || n == "latin9") {
    return SourceEncoding::Latin9;
  }
  if (n == "cp1252" || n == "windows-1252") {
    return SourceEncoding::Windows1252;
  }
  return SourceEncoding::Unknown;
}

std::string decodeSource(std::string text) {
  auto declaration = declaredEncoding(text);
  if (!declaration) {
    return text;
  }
  const SourceEncoding encoding = encodingNamed(declaration->name);
  if (encoding == SourceEncoding::Utf8 || encoding == SourceEncoding::Unknown) {
    return text;
  }
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    appendUtf8(out, codePoint(static_cast<unsigned char>(c), encoding));
  }
  return out;
}

std::optional<std::size_t> invalidUtf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    std::uint32_t minimum = 0;
    if (c < 0x80) {
      ++i;
      continue;
    }
    if (c >= 0xC2 && c <= 0xDF) {
      length = 2;
      minimum = 0x80;
    } else if (c >= 0xE0 && c <= 0xEF) {
      length = 3;
      minimum = 0x800;
    } else if (c >= 0xF0 && c <= 0xF4) {
      length = 4;
      minimum = 0x10000;
    } else {
      return i;
    }
    if (i + length > text.size()) {
      return i;
    }
    std::uint32_t code = c & (0xFF >> (length + 1));
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0) != 0x80) {
        return i;
      }
      code = (code << 6) | (next & 0x3F);
    }
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
      return i;
    }
    i += length;
  }
  return std::nullopt;
}

} // namespace stella
