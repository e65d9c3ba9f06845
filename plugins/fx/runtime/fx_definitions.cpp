#include "fx_definitions.hpp"

#include <algorithm>

namespace pfx_fx {
namespace {

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

bool is_identifier(const std::string& name) {
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (name.empty() || !letter(name[0])) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

}  // namespace

bool parse_definitions(const std::string& list, Definitions* out, std::string* error) {
  Definitions definitions;
  for (std::size_t start = 0; start <= list.size();) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    const std::string entry = trimmed(list.substr(start, end - start));
    start = end + 1;
    if (entry.empty()) continue;
    const std::size_t equals = entry.find('=');
    const std::string name = trimmed(entry.substr(0, equals));
    const std::string value = equals == std::string::npos ? "" : trimmed(entry.substr(equals + 1));
    if (!is_identifier(name)) {
      *error = "'" + entry + "': '" + name + "' is not a macro name (letters, digits and _, not starting with a digit)";
      return false;
    }
    definitions.emplace_back(name, value.empty() ? "1" : value);
  }
  *out = std::move(definitions);
  return true;
}

std::vector<std::string> remove_own_definitions(const Definitions& own, Definitions* definitions) {
  std::vector<std::string> removed;
  Definitions kept;
  for (const auto& definition : *definitions) {
    const bool is_own = std::any_of(own.begin(), own.end(), [&](const auto& o) { return o.first == definition.first; });
    if (!is_own)
      kept.push_back(definition);
    else if (std::find(removed.begin(), removed.end(), definition.first) == removed.end())
      removed.push_back(definition.first);
  }
  *definitions = std::move(kept);
  return removed;
}

}  // namespace pfx_fx
