#pragma once
// Copying one result file back, without giving up the run on a failure: the reason (the OS's,
// with the path) is returned, so that the other files still come back and the message file
// names the one that did not.

#include <filesystem>
#include <optional>
#include <string>

namespace stella {

// Copies `from` to `to` (its folders made as needed), byte by byte through write(2) so that a
// full disk, a file-size limit, a folder or a device in the way gives the OS's reason. Returns
// nothing on success, the reason otherwise; a partly written regular file is removed.
std::optional<std::string> copyResultFile(const std::filesystem::path& from, const std::filesystem::path& to);

} // namespace stella
