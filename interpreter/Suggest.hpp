#pragma once
// "did you mean 'X'?" suggestions from the nearest names by edit distance.

#include <string>
#include <vector>

namespace stella {

// Levenshtein distance (byte-wise), stopping early above `limit`.
int editDistance(const std::string& a, const std::string& b, int limit);
// The candidate nearest to `name` when near enough (case differences count little), or "".
std::string nearestName(const std::string& name, const std::vector<std::string>& candidates);
// "did you mean 'X'?" or "" when nothing is near.
std::string suggestionNote(const std::string& name, const std::vector<std::string>& candidates);

} // namespace stella
