// The results file of an external series (`NAME: ! command` in [series], doc/sweep.md).

#include "MessReport.hpp"
#include "SweepSpec.hpp"

#include <cstdlib>
#include <sstream>

namespace stella::sweep {

namespace {

bool readNumber(std::istringstream& in, double& value) {
  std::string word;
  if (!(in >> word)) {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size();
}

} // namespace

MessReport parseExternalResult(const std::string& text) {
  MessReport r;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string content = trim(line);
    if (content.empty() || content.front() == '#') {
      continue;
    }
    std::istringstream words(content);
    ReferenceTest test;
    std::string name;
    if (!readNumber(words, test.computed) || !readNumber(words, test.reference) ||
        !std::getline(words, name) || trim(name).empty()) {
      throw SweepError("line " + std::to_string(number) + ": expected 'COMPUTED REFERENCE NAME', got '" +
                       content + "'");
    }
    test.name = trim(name);
    test.error = relativeError(test.computed, test.reference);
    r.tests.push_back(test);
  }
  return r;
}

} // namespace stella::sweep
