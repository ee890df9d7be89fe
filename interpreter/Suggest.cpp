// Nearest-name suggestions for unknown names and keywords.
#include "Suggest.hpp"

#include "messages/Messages.hpp"

#include <algorithm>
#include <cctype>

namespace stella {

int editDistance(const std::string& a, const std::string& b, int limit) {
  // optimal string alignment: insertions, deletions, substitutions and adjacent transpositions
  if (std::abs(static_cast<int>(a.size()) - static_cast<int>(b.size())) > limit) {
    return limit + 1;
  }
  std::size_t n = b.size();
  std::vector<int> before(n + 1);
  std::vector<int> previous(n + 1);
  std::vector<int> row(n + 1);
  for (std::size_t j = 0; j <= n; ++j) {
    previous[j] = static_cast<int>(j);
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = static_cast<int>(i);
    int best = row[0];
    for (std::size_t j = 1; j <= n; ++j) {
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        row[j] = std::min(row[j], before[j - 2] + 1);
      }
      best = std::min(best, row[j]);
    }
    if (best > limit) {
      return limit + 1;
    }
    before.swap(previous);
    previous.swap(row);
  }
  return previous[n];
}

namespace {
std::string upper(const std::string& s) {
  std::string out = s;
  for (char& c : out) {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}
} // namespace

std::string nearestName(const std::string& name, const std::vector<std::string>& candidates) {
  if (name.size() > 200) {
    return {};
  }
  int limit = std::max(1, static_cast<int>(name.size()) / 3);
  std::string best;
  int bestScore = 1 << 20;
  std::string key = upper(name);
  for (const auto& c : candidates) {
    if (c == name || c.size() > 200) {
      continue;
    }
    // scores in half steps: a case-only difference costs 1, each edit 2
    int score = 0;
    std::string cu = upper(c);
    if (cu == key) {
      score = 1;
    } else {
      int d = editDistance(key, cu, limit);
      if (d > limit) {
        continue;
      }
      score = 2 * d + (c.size() == name.size() ? 0 : 0);
    }
    if (score < bestScore || (score == bestScore && c < best)) {
      bestScore = score;
      best = c;
    }
  }
  return best;
}

std::string suggestionNote(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best = nearestName(name, candidates);
  return best.empty() ? std::string() : msg::text("SUGGEST.n_mean", {{"name", best}});
}

} // namespace stella
