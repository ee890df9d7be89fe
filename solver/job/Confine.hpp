#pragma once
// `stella run --confine`, for services that run studies they did not write: every data or
// result path of the export (or of the command line) must resolve inside the export's folder
// (or the .comm's): no `..` out of it, no absolute path elsewhere, no symbolic link leading out.
// A refused path is named with its export line; the file itself is never opened.

#include "Export.hpp"

#include <filesystem>
#include <map>

namespace stella {

// Throws UserError CONFINE_1 at the first export line whose path resolves outside the export's
// folder; result paths are taken relative to `outputDirectory` when it is given (itself checked).
void confineExport(const Export& study, const std::filesystem::path& outputDirectory);

// The quick run: the command file's folder holds the --unit files and the outputs.
void confineCommandFile(const std::filesystem::path& commandFile,
                        const std::map<int, std::filesystem::path>& units,
                        const std::filesystem::path& outputDirectory);

} // namespace stella
