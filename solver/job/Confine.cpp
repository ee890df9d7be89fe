// `stella run --confine` (Confine.hpp): paths resolved (symbolic links followed, `..` removed)
// and compared with the folder, component by component.
#include "Confine.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>

namespace stella {

namespace fs = std::filesystem;

namespace {

bool inside(const fs::path& path, const fs::path& folder) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(path, ec);
  if (ec) {
    return false;
  }
  auto [f, p] = std::mismatch(folder.begin(), folder.end(), resolved.begin(), resolved.end());
  return f == folder.end();
}

fs::path folderOf(const fs::path& file) {
  return fs::weakly_canonical(fs::absolute(file).parent_path());
}

[[noreturn]] void refuse(const std::string& what, const std::string& written, const fs::path& folder,
                         const SourceLocation& at) {
  throw UserError(
      msg::make("CONFINE_1", {{"what", what}, {"written", written}, {"folder", folder.string()}}, at));
}

} // namespace

void confineExport(const Export& study, const fs::path& outputDirectory) {
  const fs::path folder = folderOf(study.file);
  std::shared_ptr<const SourceFile> source = SourceFile::load(study.file.string());
  if (!outputDirectory.empty() && !inside(fs::absolute(outputDirectory), folder)) {
    refuse(msg::text("CONFINE_1.f1"), outputDirectory.string(), folder, {});
  }
  const fs::path outputBase = outputDirectory.empty() ? folder : fs::absolute(outputDirectory);
  for (const ExportEntry& e : study.entries) {
    SourceLocation at{source, e.line, 1, static_cast<int>(source->line(e.line).size())};
    if (e.data && !inside(e.path, folder)) {
      refuse(msg::text("CONFINE_1.f2"), e.pathAsWritten, folder, at);
    }
    if (e.result) {
      const fs::path written(e.pathAsWritten);
      const fs::path destination = written.is_absolute() ? written : outputBase / written;
      if (!inside(destination, folder)) {
        refuse(msg::text("CONFINE_1.f3"), e.pathAsWritten, folder, at);
      }
    }
  }
}

void confineCommandFile(const fs::path& commandFile, const std::map<int, fs::path>& units,
                        const fs::path& outputDirectory) {
  const fs::path folder = folderOf(commandFile);
  if (!outputDirectory.empty() && !inside(fs::absolute(outputDirectory), folder)) {
    refuse(msg::text("CONFINE_1.f1"), outputDirectory.string(), folder, {});
  }
  for (const auto& [unit, path] : units) {
    if (!inside(fs::absolute(path), folder)) {
      refuse(msg::text("CONFINE_1.f4", {{"unit", std::to_string(unit)}}), path.string(), folder, {});
    }
  }
}

} // namespace stella
