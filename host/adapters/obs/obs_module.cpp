// pfx-obs.so: the OBS Studio module (docs/hosts.md). At load, on OBS's graphics context (OpenGL
// 4.5 only): the pfx plugins beside the module, one filter per effect that needs only colour,
// and the "pfx chain" filter.
#include <memory>
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <obs-module.h>
#include <pfx/host/gl_state_guard.hpp>

#include "adapter_plugins.hpp"
#include "colour_only.hpp"
#include "frame_chain.hpp"
#include "obs_filter.hpp"
#include "texture_filter.hpp"

OBS_DECLARE_MODULE()
OBS_MODULE_AUTHOR("The pfx developers")

namespace {

std::shared_ptr<pfx::host::PluginRegistry> g_registry;
std::vector<std::unique_ptr<pfx::obs::FilterKind>> g_kinds;

// Plugin messages of WARNING and above go to OBS's log.
void log_to_obs(pfx_log_level level, const std::string& source, const std::string& message) {
  if (level < PFX_LOG_WARNING) return;
  blog(level >= PFX_LOG_ERROR ? LOG_ERROR : LOG_WARNING, "[pfx-obs] [%s] %s", source.c_str(), message.c_str());
}

pfx_gl_proc load_gl(const char* name) { return reinterpret_cast<pfx_gl_proc>(eglGetProcAddress(name)); }

// With OBS's context current: the plugins and the effects that run on colour alone.
bool load_effects(std::vector<std::string>* colour_only, std::string* error) {
  if (!gs_get_context()) {
    *error = "OBS's video is not set up yet: the module must load after obs_reset_video";
    return false;
  }
  if (gs_get_device_type() != GS_DEVICE_OPENGL) {
    *error = "OBS renders with Direct3D: pfx needs its OpenGL renderer";
    return false;
  }
  if (!pfx::adapters::load_host_gl(load_gl, error)) return false;
  g_registry = std::make_shared<pfx::host::PluginRegistry>(load_gl, log_to_obs, "pfx-obs (OBS Studio)");
  const std::string library = pfx::adapters::library_path_of(reinterpret_cast<const void*>(&load_effects));
  for (const auto& message : pfx::adapters::load_adapter_plugins(*g_registry, {library, {PFX_OBS_TO_PLUGINS, "../../plugins", PFX_OBS_INSTALLED_PLUGINS}}))
    blog(LOG_WARNING, "[pfx-obs] %s", message.c_str());
  // Telling the effects apart makes instances: OBS's GL state is put back afterwards.
  std::vector<std::string> notes;
  auto empty = pfx::adapters::FrameChain::build(*g_registry, {}, "set", &notes, error);
  if (!empty) return false;
  pfx::host::GlStateGuard guard(empty->chain());
  for (const auto& effect : pfx::adapters::classify_effects(*g_registry))
    if (effect.colour_only) colour_only->push_back(effect.id);
  return true;
}

}  // namespace

bool obs_module_load(void) {
  std::vector<std::string> colour_only;
  std::string error;
  obs_enter_graphics();
  const bool loaded = load_effects(&colour_only, &error);
  obs_leave_graphics();
  if (!loaded) {
    blog(LOG_ERROR, "[pfx-obs] %s; no pfx filters", error.c_str());
    return false;
  }
  g_kinds.push_back(std::make_unique<pfx::obs::FilterKind>(pfx::obs::FilterKind{"pfx_chain_filter", "pfx chain", nullptr}));
  for (const auto& id : colour_only)
    for (const auto& effect : g_registry->effects())
      if (id == effect.desc->id)
        g_kinds.push_back(std::make_unique<pfx::obs::FilterKind>(
            pfx::obs::FilterKind{"pfx_" + id + "_filter", std::string("pfx ") + effect.desc->label, effect.desc, effect.plugin}));
  pfx::obs::set_filter_registry(g_registry);
  for (const auto& kind : g_kinds) {
    obs_source_info info = pfx::obs::filter_info(*kind);
    obs_register_source(&info);
  }
  blog(LOG_INFO, "[pfx-obs] %zu filters (%zu effects need colour alone)", g_kinds.size(), colour_only.size());
  return true;
}

void obs_module_unload(void) {
  // Filters are gone by now; the plugins' deinit may touch GL.
  pfx::obs::set_filter_registry(nullptr);
  obs_enter_graphics();
  g_registry.reset();
  obs_leave_graphics();
}

const char* obs_module_name(void) { return "pfx"; }
// OBS asks a module for no licence; its description carries it (the text is pfx's LICENSE).
const char* obs_module_description(void) {
  return "pfx post effects (bloom, glare, ...) as video filters. MIT licence.";
}
