#pragma once
// A `.export` run file, as code_aster users write them (reference §4.1):
//   P <parameter> <value...>         e.g. P time_limit 120, P testlist verification, P expected_diag
//   NOOK_TEST_RESU A <args>                         extra arguments F|R <type> <path> <D|R|C...> <unit>   F
//   file, R directory; D data, R result, C compressed
// Paths are relative to the export's folder.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stella {

struct ExportEntry {
  bool directory = false;     // R line
  std::string type;           // comm, mmed, mail, msh, mess, resu, rmed, base, nom, ...
  std::filesystem::path path; // absolute
  std::string pathAsWritten;
  bool data = false;
  bool result = false;
  bool compressed = false; // results are written uncompressed; compressed data is refused
  int unit = 0;
  int line = 0; // in the export file
};

struct Export {
  std::filesystem::path file;
  std::map<std::string, std::vector<std::string>> parameters;
  std::vector<std::string> arguments;
  std::vector<ExportEntry> entries;

  // Parses an export; throws UserError (EXPORT_n) naming the line for an unknown line type, a
  // missing field, a bad unit, a reserved unit (6 and 15 for data), or a missing command file.
  static Export read(const std::filesystem::path& file);

  // The command files (type comm, data), in order.
  std::vector<const ExportEntry*> commandFiles() const;
  bool hasParameter(const std::string& name) const { return parameters.count(name) != 0; }
  std::vector<std::string> parameter(const std::string& name) const;
};

} // namespace stella
