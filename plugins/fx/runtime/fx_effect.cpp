#include "fx_effect.hpp"

#include <mutex>
#include <set>

#include <pfx/cpp/create_functions.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "fx_instance.hpp"

namespace pfx_fx {
namespace {

std::mutex live_mutex;
std::set<const void*> live;  // the instances made and not destroyed

pfx_status create_effect(std::size_t index, const pfx_host* host, void** out_instance) {
  if (!out_instance || !pfx::plugin::usable_host(host)) return PFX_INVALID_ARGUMENT;
  const FxCatalog& c = catalog();
  if (index >= c.effects.size()) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&] {
    auto instance = std::make_unique<FxInstance>(*c.effects[index], host);
    if (!instance->create_gl()) return PFX_GL_ERROR;
    std::lock_guard<std::mutex> lock(live_mutex);
    live.insert(instance.get());
    *out_instance = instance.release();
    return PFX_OK;
  });
}

constexpr auto kCreate = pfx::plugin::create_functions<kMaxEffects, create_effect>();

void destroy(void* instance) {
  try {
    {
      std::lock_guard<std::mutex> lock(live_mutex);
      live.erase(instance);
    }
    delete static_cast<FxInstance*>(instance);
  } catch (...) {  // nothing may unwind through the C ABI
  }
}

pfx_status declare(void* instance, const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  if (!instance || !pfx::plugin::usable_declare_arguments(frame, params, out)) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions(
      [&] { return static_cast<FxInstance*>(instance)->declare(frame, params, out); });
}

pfx_status run_pass(void* instance, const pfx_pass_context* context) {
  if (!instance || !context || context->struct_size < PFX_PASS_CONTEXT_MIN_SIZE) return PFX_INVALID_ARGUMENT;
  return pfx::plugin::without_exceptions([&] { return static_cast<FxInstance*>(instance)->run_pass(context); });
}

const char* report_json(void* instance) {
  try {
    return instance ? static_cast<FxInstance*>(instance)->report_json() : nullptr;
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

FxInstance* live_instance(void* instance) {
  std::lock_guard<std::mutex> lock(live_mutex);
  return live.count(instance) ? static_cast<FxInstance*>(instance) : nullptr;
}

void fill_effect_desc(FxEffectEntry& entry, std::size_t index) {
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
  // A technique reads depth only where the frame has it (the far plane otherwise): hosts of video
  // frames need not make an instance (which compiles the file) to learn that it runs on colour.
  d.flags = PFX_EFFECT_COLOR_ONLY;
}

}  // namespace pfx_fx
