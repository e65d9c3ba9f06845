#include "known_headers.hpp"

#include <algorithm>
#include <cctype>

namespace pfx::fx {
namespace {

struct KnownHeader {
  const char* name;        // lower case
  const char* collection;  // where users get it
};

// What the public collections share, from their repositories. ReShade.fxh and ReShadeUI.fxh are
// not here: pfx ships its own.
constexpr KnownHeader kKnownHeaders[] = {
    {"drawtext.fxh", "crosire/reshade-shaders (its Shaders folder, with Textures/FontAtlas.png)"},
    {"macros.fxh", "crosire/reshade-shaders (its Shaders folder)"},
    {"blending.fxh", "crosire/reshade-shaders (its Shaders folder)"},
    {"tridither.fxh", "crosire/reshade-shaders (its Shaders folder)"},
    {"quint_common.fxh", "martymcmodding/qUINT (its Shaders folder)"},
    {"fxaa.fxh", "CeeJayDK/SweetFX (Shaders/SweetFX)"},
    {"smaa.fxh", "CeeJayDK/SweetFX (Shaders/SweetFX)"},
};

}  // namespace

std::string collection_of_header(const std::string& include_name) {
  std::string name = include_name.substr(include_name.find_last_of('/') == std::string::npos ? 0 : include_name.find_last_of('/') + 1);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const KnownHeader& header : kKnownHeaders)
    if (name == header.name) return header.collection;
  return {};
}

}  // namespace pfx::fx
