#pragma once
// Every libretro preset the plugin offers, found once per process (on the first call of the effect
// factory, never in init): each `*.slangp` and `*.glslp` under the folders of PFX_LIBRETRO_PATH (':'-separated,
// searched with their sub-folders) and the folder installed beside the plugin
// (<plugin folder>/libretro/shaders). Listing reads the presets and their shaders' `#pragma
// parameter` lines only; the passes are compiled when an instance is made, so a collection of
// thousands of presets lists quickly. Each preset becomes an effect "libretro_<path>", the preset's
// path under its search folder without the extension made into an id (crt/crt-geom.slangp:
// libretro_crt_crt_geom; a .glslp adds "_glsl": libretro_crt_crt_geom_glsl), with its shaders'
// parameters; a preset that cannot be read is kept with
// its error and stops nothing else.
#include <memory>
#include <string>
#include <vector>

#include <pfx/effect.h>

#include "lr_parameters.hpp"
#include "preset.hpp"

namespace pfx_libretro {

struct LrEffectEntry {
  std::string id, label, description;
  std::string file;  // the preset loaded
  pfx::libretro::Preset preset;
  LrParameters params;
  // What the preset's reader and the parameters let pass with a default (an unknown wrap mode, a
  // parameter declared twice differently): logged when an instance is made.
  std::vector<std::string> warnings;
  pfx_effect_desc desc{};
};

struct LrLoadError {
  std::string file;
  std::string message;  // "file:line: error: why"
};

struct LrCatalog {
  std::vector<std::unique_ptr<LrEffectEntry>> effects;
  std::vector<LrLoadError> errors;
};

// The catalog, built on the first call (thread-safe).
const LrCatalog& catalog();
// The catalog's effect of that id, or null (null for a null id).
const LrEffectEntry* find_effect(const char* effect_id);

// The folders searched: PFX_LIBRETRO_PATH's, then the installed one when it exists.
std::vector<std::string> search_folders();

}  // namespace pfx_libretro
