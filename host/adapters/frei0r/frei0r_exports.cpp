// The frei0r entry points (frei0r.h, version 1.2) of pfx_chain.so and every pfx_<effect>.so.
// What each does inside the host is in frei0r_library.hpp and frei0r_instance.hpp; nothing here
// may throw into the host, whose code is C.
#include <exception>
#include <new>

#include "frei0r_api.hpp"

#include "frei0r_instance.hpp"
#include "frei0r_library.hpp"

#define PFX_FREI0R_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

using pfx::frei0r::Instance;
using pfx::frei0r::library;

// The largest frame an instance accepts: GL textures of 4.5 contexts reach 16384 on every side.
constexpr unsigned kMaxSide = 16384;

// A string parameter's value arrives as a pointer to the char* (frei0r.h: f0r_param_string),
// which is what ffmpeg, MLT and GStreamer 1.22's frei0r bridge pass.
const char* string_argument(const void* param) { return *static_cast<const char* const*>(param); }

}  // namespace

PFX_FREI0R_EXPORT int f0r_init(void) {
  try {
    library();
    return 1;
  } catch (const std::exception&) {
    return 0;
  }
}

// The description stays until the library is unloaded: hosts keep pointers into it, and MLT calls
// this while its instances are still alive.
PFX_FREI0R_EXPORT void f0r_deinit(void) {}

PFX_FREI0R_EXPORT void f0r_get_plugin_info(f0r_plugin_info_t* info) {
  const auto& lib = *library();
  info->name = lib.name.c_str();
  info->author = "pfx";
  info->plugin_type = F0R_PLUGIN_TYPE_FILTER;
  info->color_model = F0R_COLOR_MODEL_RGBA8888;
  info->frei0r_version = FREI0R_MAJOR_VERSION;
  info->major_version = 0;
  info->minor_version = 1;
  info->num_params = static_cast<int>(lib.params.size());
  info->explanation = lib.explanation.c_str();
}

PFX_FREI0R_EXPORT void f0r_get_param_info(f0r_param_info_t* info, int param_index) {
  const auto& lib = *library();
  if (param_index < 0 || static_cast<size_t>(param_index) >= lib.params.size()) return;
  const auto& slot = lib.params[param_index];
  info->name = slot.name.c_str();
  info->type = slot.type;
  info->explanation = slot.explanation.c_str();
}

PFX_FREI0R_EXPORT f0r_instance_t f0r_construct(unsigned int width, unsigned int height) {
  if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide) return nullptr;
  try {
    return new Instance(library(), width, height);
  } catch (const std::exception&) {
    return nullptr;
  }
}

PFX_FREI0R_EXPORT void f0r_destruct(f0r_instance_t instance) { delete static_cast<Instance*>(instance); }

PFX_FREI0R_EXPORT void f0r_set_param_value(f0r_instance_t instance, f0r_param_t param, int param_index) {
  if (!instance || !param) return;
  try {
    const auto& lib = *library();
    const bool is_string = param_index >= 0 && static_cast<size_t>(param_index) < lib.params.size() &&
                           lib.params[param_index].type == F0R_PARAM_STRING;
    const char* text = is_string ? string_argument(param) : nullptr;
    static_cast<Instance*>(instance)->set_param(param_index, param, text);
  } catch (const std::exception&) {
  }
}

PFX_FREI0R_EXPORT void f0r_get_param_value(f0r_instance_t instance, f0r_param_t param, int param_index) {
  if (!instance || !param) return;
  try {
    static_cast<Instance*>(instance)->get_param(param_index, param);
  } catch (const std::exception&) {
  }
}

PFX_FREI0R_EXPORT void f0r_update(f0r_instance_t instance, double time, const uint32_t* inframe,
                                  uint32_t* outframe) {
  if (!instance || !inframe || !outframe) return;
  try {
    static_cast<Instance*>(instance)->update(time, inframe, outframe);
  } catch (const std::exception&) {
  }
}
