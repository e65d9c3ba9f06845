// pfx-validate's output: per plugin a table of check x effect with a line per problem below it,
// or one JSON object with the same content.
#pragma once

#include <string>
#include <vector>

#include "validation.hpp"

namespace pfx::validate {

std::string report_text(const std::vector<PluginResult>& results, const ValidationSettings& settings);
std::string report_json(const std::vector<PluginResult>& results, const ValidationSettings& settings);

}  // namespace pfx::validate
