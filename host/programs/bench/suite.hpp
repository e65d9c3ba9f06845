// A bench suite: rows "EFFECT [param=value ...]", one per line, '#' comments.
#pragma once

#include <string>
#include <vector>

namespace pfx::bench {

struct SuiteRow {
  std::string effect;
  std::vector<std::string> settings;  // "param=value", applied as effect.param=value
  std::string label() const;          // "mode=chain levels=6", or "defaults"
};

// False with *error naming the line for a malformed row.
bool parse_suite(const std::string& text, std::vector<SuiteRow>* rows, std::string* error);
// The built-in suite (host/programs/bench/default_suite.txt, compiled in).
const std::string& default_suite_text();

}  // namespace pfx::bench
