// A list of preprocessor definitions as pfx.sources/1's set_definitions and pfx.vulkan_effects/1's
// create_with_definitions take it ("NAME=VALUE,NAME2=VALUE2,FLAG", a ReShade preset's
// PreprocessorDefinitions= line), read one way by whoever takes the list and whoever checks it
// before handing it on: the FX plugin compiles with it, and the Vulkan bridge refuses a malformed
// one when a preset is set, as the GL path does.
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace pfx {

using Definitions = std::vector<std::pair<std::string, std::string>>;  // name, replacement text

namespace detail {
inline std::string trimmed_definition_text(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}
}  // namespace detail

// The list's entries in order. White space around an entry, its name and its value is dropped and
// empty entries are skipped; a name without a value ("FLAG" or "FLAG=") is defined as 1, as
// ReShade does. False with *error naming the first entry whose name is not an identifier (*out
// unchanged).
inline bool parse_definitions(const std::string& list, Definitions* out, std::string* error) {
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  Definitions definitions;
  for (std::size_t start = 0; start <= list.size();) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    const std::string entry = detail::trimmed_definition_text(list.substr(start, end - start));
    start = end + 1;
    if (entry.empty()) continue;
    const std::size_t equals = entry.find('=');
    const std::string name = detail::trimmed_definition_text(entry.substr(0, equals));
    const std::string value = equals == std::string::npos ? ""
                                                          : detail::trimmed_definition_text(entry.substr(equals + 1));
    const bool identifier = !name.empty() && letter(name[0]) && std::all_of(name.begin(), name.end(), [&](char c) {
      return letter(c) || (c >= '0' && c <= '9');
    });
    if (!identifier) {
      *error = "'" + entry + "': '" + name + "' is not a macro name (letters, digits and _, not starting with a digit)";
      return false;
    }
    definitions.emplace_back(name, value.empty() ? "1" : value);
  }
  *out = std::move(definitions);
  return true;
}

}  // namespace pfx
