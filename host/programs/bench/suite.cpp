#include "suite.hpp"

#include <sstream>

#include "default_suite.inc"  // kDefaultSuite, generated from default_suite.txt

namespace pfx::bench {

std::string SuiteRow::label() const {
  if (settings.empty()) return "defaults";
  std::string text;
  for (const auto& s : settings) text += (text.empty() ? "" : " ") + s;
  return text;
}

bool parse_suite(const std::string& text, std::vector<SuiteRow>* rows, std::string* error) {
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  std::vector<SuiteRow> result;
  while (std::getline(lines, line)) {
    ++number;
    size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    SuiteRow row;
    if (!(words >> row.effect)) continue;
    std::string word;
    while (words >> word) {
      if (word.find('=') == std::string::npos || word.front() == '=') {
        *error = "suite line " + std::to_string(number) + ": '" + word + "' is not param=value";
        return false;
      }
      row.settings.push_back(word);
    }
    result.push_back(row);
  }
  *rows = std::move(result);
  return true;
}

const std::string& default_suite_text() {
  static const std::string text = kDefaultSuite;
  return text;
}

}  // namespace pfx::bench
