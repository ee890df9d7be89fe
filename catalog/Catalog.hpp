#pragma once
// The keyword catalogue (DESIGN §4): one entry per command, loaded from the catalogue files in
// catalog/commands/ (embedded in the executable at build time), checked at load, used to
// validate every call and to generate doc/catalog/.

#include "KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "interpreter/Value.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {

struct CommandSpec; // one command's definition (catalog/CommandSpec.hpp)
class ConceptTypes;

// What validation of one call produced.
struct ValidatedCall {
  KeywordTree keywords;
  std::string resultType;          // "" for a PROC or a command returning nothing
  std::shared_ptr<Concept> reused; // the concept given by reuse=, if any
};

class Catalog {
public:
  // The catalogue built into stella (loaded and checked once; a broken catalogue is an
  // internal error naming the file and keyword).
  static const Catalog& builtin();

  std::vector<std::string> commandNames() const;
  const CommandSpec* find(const std::string& command) const;

  // Validates a call. On success returns the complete keyword tree; otherwise throws UserError
  // with every error of the call (each located at the offending keyword, with a message id).
  ValidatedCall validate(const std::string& command, const CallArguments& args) const;

  // Human-readable tree of one command (`stella catalog NAME`) and the whole catalogue as JSON.
  std::string describe(const std::string& command) const;
  std::string toJson() const;

  // A catalogue built from given files (path relative to catalog/commands, text), for tests and
  // tools; not checked (see problems()).
  static Catalog fromFiles(const std::vector<std::pair<std::string, std::string>>& files);
  // The load-time checks: one line per problem, "FILE: COMMAND/FACT/KEYWORD: what".
  std::vector<std::string> problems() const;
  const ConceptTypes& conceptTypes() const;

  ~Catalog();
  Catalog(Catalog&&) noexcept;

private:
  Catalog();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes doc/catalog/: one Markdown page per command (tree, defaults, allowed values, rules,
// descriptions) and an index (README.md). Implemented in CatalogDocs.cpp.
void writeCatalogDocs(const std::filesystem::path& dir);

// `tools/catalog-coverage`: which keywords and allowed values of the catalogue no command file
// among `commandFiles` uses (a Markdown report). Implemented in CatalogCoverage.cpp.
std::string catalogCoverage(const std::vector<std::filesystem::path>& commandFiles);

} // namespace stella
