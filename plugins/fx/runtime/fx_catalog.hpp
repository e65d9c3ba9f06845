#pragma once
// Every FX technique the plugin offers, found once per process (on the first call of the effect
// factory, never in init): each `*.fx` file under the folders of PFX_FX_PATH (':'-separated,
// searched with their sub-folders) and the folder installed beside the plugin, compiled up to its
// model at a nominal frame size. Each technique becomes an effect "fx_<technique>" with its
// uniforms as parameters; a file that fails is kept with its error and stops nothing else.
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <pfx/effect.h>

#include "front_end.hpp"
#include "fx_parameters.hpp"

namespace pfx_fx {

struct FxEffectEntry {
  std::string id, label, description;
  std::string file;       // the .fx file
  std::string technique;  // the technique's name in it
  int technique_index = 0;
  ParamTable params;  // as at 1920x1080
  std::string vulkan_unsupported;  // why the Vulkan runtime cannot run it, "" when it can
  pfx_effect_desc desc{};
  // params_at's tables, per frame size asked for (kept until the plugin goes: hosts hold them).
  mutable std::mutex sized_mutex;
  mutable std::map<std::pair<int, int>, std::unique_ptr<ParamTable>> sized;
};

struct FxLoadError {
  std::string file;
  std::string message;  // "file:line:column: error: ..." lines
};

struct FxCatalog {
  std::vector<std::unique_ptr<FxEffectEntry>> effects;
  std::vector<FxLoadError> errors;
};

// The catalog, built on the first call (thread-safe).
const FxCatalog& catalog();
// The catalog's effect of that id, or null (null for a null id).
const FxEffectEntry* find_effect(const char* effect_id);

// The entry's parameters as they are at a frame of width x height (compiled once per size), or
// null for a size outside 1..16384, a file that does not compile there, or parameters that do not
// follow the frame size (fx_frame_params.hpp).
const ParamTable* params_at(const FxEffectEntry& entry, int width, int height);

// The preprocessor options every compile uses at this frame size: the shader folders (a
// collection's own ReShade.fxh) and then pfx's own headers as include folders.
pfx::fx::FrontEndOptions compile_options(int width, int height);
// The folders an environment variable names, ':'-separated like PATH (empty entries skipped).
std::vector<std::string> folders_in_variable(const char* name);
// The folders searched for effects: PFX_FX_PATH's, then the installed one.
std::vector<std::string> search_folders();

// Where the plugin library lies (its folder); the built-in headers are in <folder>/fx/include and
// the installed effects in <folder>/fx/shaders.
std::string plugin_folder();

}  // namespace pfx_fx
