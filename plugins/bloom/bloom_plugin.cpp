// The bloom plugin's entry point: the effect factory and the CPU reference factory. Everything here
// is static data; GL is loaded only when an instance is created.
#include <cstring>

#include <pfx/cpp/plugin_entry.hpp>
#include <pfx/pfx.h>
#include <pfx/reference.h>

#include "bloom_effect.hpp"
#include "bloom_params.hpp"
#include "glare_effect.hpp"
#include "reference/bloom_model.hpp"
#include "reference/glare_model.hpp"
#include "reference/ideal.hpp"

namespace pfx_bloom {
namespace {

const pfx_effect_desc* const kEffects[] = {&kBloomEffect, &kGlareEffect};

uint32_t effect_count() { return 2; }
const pfx_effect_desc* get_effect(uint32_t index) { return index < 2 ? kEffects[index] : nullptr; }

const pfx_effect_factory kEffectFactory = {sizeof(pfx_effect_factory), effect_count, get_effect};

bool is_bloom(const char* effect_id) { return effect_id && std::strcmp(effect_id, "bloom") == 0; }
bool is_glare(const char* effect_id) { return effect_id && std::strcmp(effect_id, "glare") == 0; }

// bloom: the model of each mode and its ideal; glare: its model.
int has_reference(const char* effect_id, pfx_reference_kind kind) {
  return (is_bloom(effect_id) && (kind == PFX_REFERENCE_MODEL || kind == PFX_REFERENCE_IDEAL)) ||
         (is_glare(effect_id) && kind == PFX_REFERENCE_MODEL);
}

pfx_status evaluate(const pfx_reference_request* request) {
  if (!pfx::plugin::usable_reference_request(request)) return PFX_INVALID_ARGUMENT;
  if (!has_reference(request->effect_id, request->kind)) return PFX_UNSUPPORTED;
  const uint32_t w = request->frame->width, h = request->frame->height;
  return pfx::plugin::without_exceptions([&] {
    if (is_glare(request->effect_id))
      evaluate_glare_model(glare_settings_from(request->params), w, h, request->color, request->output);
    else if (request->kind == PFX_REFERENCE_IDEAL)
      evaluate_ideal(settings_from(request->params), w, h, request->color, request->output);
    else
      evaluate_model(settings_from(request->params), w, h, request->color, request->output);
    return PFX_OK;
  });
}

const pfx_reference_factory kReferenceFactory = {sizeof(pfx_reference_factory), has_reference, evaluate};

// No GL and no state: init is trivially idempotent.
pfx_status plugin_init(const pfx_host* host) {
  return pfx::plugin::usable_host(host) ? PFX_OK : PFX_INVALID_ARGUMENT;
}

void plugin_deinit() {}

const void* plugin_get_factory(const char* factory_id) {
  return pfx::plugin::factory_for(factory_id, &kEffectFactory, &kReferenceFactory);
}

const pfx_entry kEntry = {sizeof(pfx_entry), PFX_ABI_MAJOR,  PFX_ABI_MINOR,      "org.pfx.bloom",
                          "pfx bloom",       "0.1.0",        plugin_init,        plugin_deinit,
                          plugin_get_factory};

}  // namespace
}  // namespace pfx_bloom

extern "C" PFX_EXPORT const pfx_entry* pfx_get_entry(void) { return &pfx_bloom::kEntry; }
