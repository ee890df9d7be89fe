#pragma once
// Token reader for the text mesh formats (Gmsh .msh ASCII, ASTER .mail): whitespace-separated
// tokens with line numbers, optional comment character, double-quoted strings as one token, and
// typed reads that raise MESHFILE_2 naming the file and line on any malformed number.
// Formats that mix text and binary blocks (Gmsh binary .msh) read raw little-endian values with
// the binary* functions after startBinary().

#include "messages/Messages.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace stella {

class TextScanner {
public:
  TextScanner(std::filesystem::path file, std::string text, char comment = '\0');

  // Next token (empty at end of file). Quoted tokens are returned without their quotes.
  std::string_view next();
  // Next token, MESHFILE_2 "unexpected end of file, expected <what>" at end.
  std::string_view expect(const char* what);
  std::string_view peek();
  bool atEnd();
  // Line of the last token returned.
  int line() const { return tokenLine_; }
  // Whether another token follows on the line of the last token returned.
  bool moreOnLine();
  // Skips the rest of the current line (after the last token).
  void skipLine();

  std::int64_t integer(const char* what);
  double real(const char* what); // finite values only
  // A count that cannot exceed what the file could hold (guards allocations on damaged files).
  std::int64_t count(const char* what, std::int64_t bytesPerItem = 2);

  // Binary blocks: startBinary() steps over the line end that follows the last token (binary
  // data starts on the next byte); the binary* reads then consume raw little-endian values,
  // failing with MESHFILE_2 at the end of the file. Tokens may be read again afterwards.
  void startBinary();
  // Moves past the next occurrence of `marker` preceded by a line end (binary blocks of unknown
  // layout); false when the file has none.
  bool skipPastLine(std::string_view marker);
  std::int64_t binaryInteger(int bytes, const char* what); // signed, 4 or 8 bytes
  double binaryReal(const char* what);                     // 8 bytes, finite values only
  // A binary count (8 bytes) that cannot exceed what the file could hold, as count().
  std::int64_t binaryCount(const char* what, std::int64_t bytesPerItem);

  // Throws catalogue entry `key` (MESHFILE_2 syntax, MESHFILE_3 content) at the current line.
  [[noreturn]] void fail(std::string_view key, msg::Args args = {}) const;
  [[noreturn]] void failContent(std::string_view key, msg::Args args = {}) const;
  const std::filesystem::path& file() const { return file_; }
  std::size_t size() const { return text_.size(); }

private:
  void skipSpace();

  std::filesystem::path file_;
  std::string text_;
  char comment_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int tokenLine_ = 0;
};

} // namespace stella
