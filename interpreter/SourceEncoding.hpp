#pragma once
// Python's source-encoding rules (PEP 263) for command files: a comment on line 1 or 2 matching
// `coding[:=] NAME` declares the file's encoding; without one the file is UTF-8. Files in a
// declared 8-bit encoding are decoded to UTF-8 when read; the lexer reports an unknown encoding
// and bytes that are not UTF-8.

#include <optional>
#include <string>
#include <string_view>

namespace stella {

struct EncodingDeclaration {
  std::string name;       // as written, e.g. "latin-1"
  int line = 0;           // 1 or 2
  std::size_t column = 0; // 1-based, of the name
};

// The declaration of the text's encoding, if any (PEP 263: `^[ \t\f]*#.*?coding[:=][ \t]*([-\w.]+)`).
std::optional<EncodingDeclaration> declaredEncoding(std::string_view text);

enum class SourceEncoding { Utf8, Latin1, Latin9, Windows1252, Unknown };
SourceEncoding encodingNamed(const std::string& name);

// The text decoded to UTF-8 when its declared encoding is an 8-bit one; unchanged otherwise.
std::string decodeSource(std::string text);

// The offset of the first byte that does not belong to a valid UTF-8 sequence, if any.
std::optional<std::size_t> invalidUtf8(std::string_view text);

} // namespace stella
