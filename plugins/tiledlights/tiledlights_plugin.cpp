// The tiledlights plugin's entry point: the effect factory and the CPU reference factory (model:
// the windowed sum every mode computes; ideal: the un-windowed sum). Static data only; GL is
// loaded when an instance is created.
#include <cstring>
#include <string>

#include <pfx/cpp/plugin_entry.hpp>
#include <pfx/pfx.h>

#include "reference/light_shading.hpp"
#include "tiledlights_effect.hpp"
#include "tiledlights_params.hpp"

namespace pfx_tiledlights {
namespace {

const pfx_host* g_host = nullptr;

uint32_t effect_count() { return 1; }
const pfx_effect_desc* get_effect(uint32_t index) { return index == 0 ? &kTiledLightsEffect : nullptr; }

const pfx_effect_factory kEffectFactory = {sizeof(pfx_effect_factory), effect_count, get_effect};

int has_reference(const char* effect_id, pfx_reference_kind kind) {
  return effect_id && std::strcmp(effect_id, "tiledlights") == 0 &&
         (kind == PFX_REFERENCE_MODEL || kind == PFX_REFERENCE_IDEAL);
}

pfx_status evaluate(const pfx_reference_request* request) {
  if (!pfx::plugin::usable_reference_request(request)) return PFX_INVALID_ARGUMENT;
  if (!has_reference(request->effect_id, request->kind)) return PFX_UNSUPPORTED;
  const Settings settings = settings_from(request->params);
  // The heat view shows how the GPU's lists came out, which only the GPU knows.
  if (settings.show != SHOW_LIGHT) return PFX_UNSUPPORTED;
  // The G-buffer fields arrived in ABI 1.1: only read them when the request is that large.
  if (!pfx::plugin::has_gbuffer_fields(*request) || !request->depth || !request->normal || !request->albedo ||
      (settings.base == BASE_EMISSIVE && !request->emissive))
    return PFX_MISSING_INPUT;
  GBufferImages images;
  images.color = request->color;
  images.depth = request->depth;
  images.normal = request->normal;
  images.albedo = request->albedo;
  images.emissive = request->emissive;
  return pfx::plugin::without_exceptions([&] {
    std::string error;
    if (!shade_reference(*request->frame, settings, images, request->kind == PFX_REFERENCE_MODEL, request->output,
                         &error)) {
      if (g_host) g_host->log(g_host->host_data, PFX_LOG_ERROR, ("tiledlights reference: " + error).c_str());
      return PFX_INVALID_ARGUMENT;
    }
    return PFX_OK;
  });
}

const pfx_reference_factory kReferenceFactory = {sizeof(pfx_reference_factory), has_reference, evaluate};

pfx_status plugin_init(const pfx_host* host) {
  if (!pfx::plugin::usable_host(host)) return PFX_INVALID_ARGUMENT;
  g_host = host;
  return PFX_OK;
}

void plugin_deinit() { g_host = nullptr; }

const void* plugin_get_factory(const char* factory_id) {
  return pfx::plugin::factory_for(factory_id, &kEffectFactory, &kReferenceFactory);
}

const pfx_entry kEntry = {sizeof(pfx_entry), PFX_ABI_MAJOR,      PFX_ABI_MINOR,  "org.pfx.tiledlights",
                          "pfx tiled lights", "0.1.0",           plugin_init,    plugin_deinit,
                          plugin_get_factory};

}  // namespace
}  // namespace pfx_tiledlights

extern "C" PFX_EXPORT const pfx_entry* pfx_get_entry(void) { return &pfx_tiledlights::kEntry; }
