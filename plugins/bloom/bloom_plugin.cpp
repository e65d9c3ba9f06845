// The bloom plugin's entry point: its two effects and the CPU reference factory. Everything here
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

constexpr pfx_reference_factory kReferenceFactory = {sizeof(pfx_reference_factory), has_reference, evaluate};
constexpr const pfx_effect_desc* kEffects[] = {&kBloomEffect, &kGlareEffect};

// No GL and no state: the kit's init (the host's check) is all it needs.
constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.bloom")
                             .name("pfx bloom")
                             .version("0.1.0")
                             .effects(kEffects)
                             .references(&kReferenceFactory);

}  // namespace
}  // namespace pfx_bloom

PFX_PLUGIN_ENTRY(pfx_bloom::kPlugin)
