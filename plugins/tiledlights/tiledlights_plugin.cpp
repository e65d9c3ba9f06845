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

constexpr pfx_reference_factory kReferenceFactory = {sizeof(pfx_reference_factory), has_reference, evaluate};
constexpr const pfx_effect_desc* kEffects[] = {&kTiledLightsEffect};

// The reference logs through the host it was loaded by.
pfx_status remember_host(const pfx_host* host) {
  g_host = host;
  return PFX_OK;
}
void forget_host() { g_host = nullptr; }

constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.tiledlights")
                             .name("pfx tiled lights")
                             .version("0.1.0")
                             .effects(kEffects)
                             .references(&kReferenceFactory)
                             .on_init(remember_host)
                             .on_deinit(forget_host);

}  // namespace
}  // namespace pfx_tiledlights

PFX_PLUGIN_ENTRY(pfx_tiledlights::kPlugin)
