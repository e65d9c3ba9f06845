#pragma once
// Preprocessor definitions a host gives an instance ("pfx.sources/1"'s set_definitions): the
// "NAME=VALUE,NAME2=VALUE2,FLAG" list of a ReShade preset's PreprocessorDefinitions= line, read
// the way ReShade reads it.
#include <string>
#include <vector>

#include <pfx/cpp/definitions_list.hpp>

namespace pfx_fx {

// The list is read by pfx::parse_definitions (pfx/cpp/definitions_list.hpp), which the Vulkan
// bridge uses too.
using pfx::Definitions;
using pfx::parse_definitions;

// Removes the definitions of names pfx defines itself (`own`: compile_options' defines, the
// RESHADE_DEPTH_* settings that match the depth pfx hands FX effects) and returns their names.
std::vector<std::string> remove_own_definitions(const Definitions& own, Definitions* definitions);

}  // namespace pfx_fx
