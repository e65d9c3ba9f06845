#pragma once
// Preprocessor definitions a host gives an instance ("pfx.sources/1"'s set_definitions): the
// "NAME=VALUE,NAME2=VALUE2,FLAG" list of a ReShade preset's PreprocessorDefinitions= line, read
// the way ReShade reads it.
#include <string>
#include <utility>
#include <vector>

namespace pfx_fx {

using Definitions = std::vector<std::pair<std::string, std::string>>;  // name, replacement text

// The list's entries in order. White space around an entry, its name and its value is dropped and
// empty entries are skipped; a name without a value ("FLAG" or "FLAG=") is defined as 1, as
// ReShade does. False with *error naming the first entry whose name is not an identifier.
bool parse_definitions(const std::string& list, Definitions* out, std::string* error);

// Removes the definitions of names pfx defines itself (`own`: compile_options' defines, the
// RESHADE_DEPTH_* settings that match the depth pfx hands FX effects) and returns their names.
std::vector<std::string> remove_own_definitions(const Definitions& own, Definitions* definitions);

}  // namespace pfx_fx
