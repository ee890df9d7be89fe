#pragma once
// Wording shared by `stella catalog`, the JSON export and the generated reference pages: what a
// command returns and whether it reuses a concept.

#include "CommandSpec.hpp"

#include <string>

namespace stella {

std::string describeResult(const CommandSpec& c);
std::string describeReuse(const CommandSpec& c);
const char* commandKindName(CommandKind k);

} // namespace stella
