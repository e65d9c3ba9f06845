#include "lr_effect.hpp"

#include <pfx/cpp/create_functions.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "lr_instance.hpp"

namespace pfx_libretro {
namespace {

pfx_status create_effect(std::size_t index, const pfx_host* host, void** out_instance) {
  if (!out_instance || !pfx::plugin::usable_host(host)) return PFX_INVALID_ARGUMENT;
  const LrCatalog& c = catalog();
  if (index >= c.effects.size()) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&]() -> pfx_status {
    auto instance = std::make_unique<LrInstance>(*c.effects[index], host);
    const pfx_status status = instance->create();
    if (status != PFX_OK) return status;
    *out_instance = instance.release();
    return PFX_OK;
  });
}

constexpr auto kCreate = pfx::plugin::create_functions<kMaxEffects, create_effect>();

void destroy(void* instance) {
  try {
    delete static_cast<LrInstance*>(instance);
  } catch (...) {  // nothing may unwind through the C ABI
  }
}

pfx_status declare(void* instance, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  if (!instance || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions(
      [&] { return static_cast<LrInstance*>(instance)->declare(frame, params, out); });
}

pfx_status run_pass(void* instance, const pfx_pass_context* context) {
  if (!instance || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&] { return static_cast<LrInstance*>(instance)->run_pass(context); });
}

const char* report_json(void* instance) {
  try {
    return instance ? static_cast<LrInstance*>(instance)->report_json() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

void fill_effect_desc(LrEffectEntry& entry, std::size_t index) {
  pfx_effect_desc& d = entry.desc;
  d = {};
  d.struct_size = sizeof(pfx_effect_desc);
  d.id = entry.id.c_str();
  d.label = entry.label.c_str();
  d.description = entry.description.c_str();
  d.params = entry.params.descs.empty() ? nullptr : entry.params.descs.data();
  d.param_count = static_cast<uint32_t>(entry.params.descs.size());
  d.create = index < kMaxEffects ? kCreate[index] : nullptr;
  d.destroy = destroy;
  d.declare = declare;
  d.run_pass = run_pass;
  d.report_json = report_json;
  // Every pass reads the frame's colour and its own pictures: hosts of video frames need not make
  // an instance (which compiles every pass) to learn it.
  d.flags = PFX_EFFECT_COLOR_ONLY;
}

}  // namespace pfx_libretro
