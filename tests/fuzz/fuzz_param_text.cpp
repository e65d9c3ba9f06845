// libFuzzer target for parameter text: what pfx-render --set, settings files (ParamStore::
// from_text) and JSON presets (from_json) accept. Whatever the input, a refused set changes
// nothing, an accepted one leaves every value valid for its descriptor (no NaN, inside the hard
// range, whole where it must be), and what the store writes out reads back to the same values.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/host/param_store.hpp>

namespace {

const pfx_enum_item kModes[] = {{"chain", "Chain"}, {"chain13", "13 taps"}, {"dual", "Dual"}};

// One parameter of every type, one of them refusing out-of-range values instead of clamping.
const pfx_param_desc kParams[] = {
    pfx::desc::param("threshold")
        .label("Threshold")
        .tooltip("t")
        .float_range(0, 65504)
        .display_range(0, 8)
        .step(0.1)
        .default_value(1),
    pfx::desc::param("strict").label("Strict").tooltip("s").float_range(-1, 1).step(0.1).default_value(0),
    pfx::desc::param("levels").label("Levels").tooltip("l").int_range(0, 12).default_value(6),
    pfx::desc::param("on").label("On").tooltip("o").boolean().default_value(1),
    pfx::desc::param("mode").label("Mode").tooltip("m").items(kModes, 3).default_value(0),
    pfx::desc::param("tint").label("Tint").tooltip("c").color_range(0, 16).display_range(0, 1).step(0.01).default_value(
        1, 1, 1),
    pfx::desc::param("offset")
        .label("Offset")
        .unit("px")
        .tooltip("v")
        .vec2_range(-100, 100)
        .display_range(-10, 10)
        .step(1)
        .default_value(0, 0),
    pfx::desc::param("axis").label("Axis").tooltip("a").vec3_range(-1, 1).step(0.1).default_value(0, 0, 1),
};

pfx_param_desc strict(pfx_param_desc d) {
  d.flags = PFX_PARAM_REJECT_OUT_OF_RANGE;
  return d;
}

pfx_effect_desc effect(const char* id, const pfx_param_desc* params, uint32_t count) {
  pfx_effect_desc e{};
  e.struct_size = sizeof e;
  e.id = id;
  e.label = id;
  e.description = id;
  e.params = params;
  e.param_count = count;
  return e;
}

void check_valid(const pfx::host::ParamStore& store, const pfx_effect_desc& e, size_t instance = 1) {
  const pfx_value* values = store.values(e.id, instance);
  if (!values) __builtin_trap();
  for (uint32_t i = 0; i < e.param_count; ++i) {
    const pfx_param_desc& d = e.params[i];
    for (int c = 0; c < 4; ++c) {
      const double v = values[i].v[c];
      if (std::isnan(v)) __builtin_trap();
      const bool used = c == 0 || (c < 2 && d.type == PFX_PARAM_VEC2) ||
                        (c < 3 && (d.type == PFX_PARAM_COLOR || d.type == PFX_PARAM_VEC3));
      if (!used) continue;
      if (v < d.hard_min || v > d.hard_max) __builtin_trap();
      if ((d.type == PFX_PARAM_INT || d.type == PFX_PARAM_BOOL || d.type == PFX_PARAM_ENUM) && v != std::floor(v))
        __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const pfx_param_desc kStrict[] = {strict(kParams[1])};
  static const pfx_effect_desc kEffect = effect("bloom", kParams, sizeof kParams / sizeof kParams[0]);
  static const pfx_effect_desc kStrictEffect = effect("strict", kStrict, 1);
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);

  // Two instances of bloom, as a chain "bloom,strict,bloom" holds them: "bloom#2" is reachable.
  pfx::host::ParamStore store;
  store.add_effect(&kEffect);
  store.add_effect(&kStrictEffect);
  store.set_instance_count("bloom", 2);
  const std::string before = store.to_text();
  std::string error, note;
  bool ok = false;
  switch (data[0] % 3) {
    case 0: ok = store.set_assignment(text, &error, &note); break;  // one --set value
    case 1: ok = store.from_text(text, &error); break;              // a settings file
    default: ok = store.from_json(text, &error); break;             // a JSON preset
  }
  if (!ok && (error.empty() || store.to_text() != before)) __builtin_trap();  // refused: unchanged, and said why
  check_valid(store, kEffect);
  check_valid(store, kEffect, 2);
  check_valid(store, kStrictEffect);

  // Both saved forms read back to exactly the same values.
  const std::string saved_text = store.to_text(), saved_json = store.to_json();
  pfx::host::ParamStore from_text, from_json;
  for (pfx::host::ParamStore* copy : {&from_text, &from_json}) {
    copy->add_effect(&kEffect);
    copy->add_effect(&kStrictEffect);
    copy->set_instance_count("bloom", 2);
  }
  if (!from_text.from_text(saved_text, &error) || from_text.to_text() != saved_text) __builtin_trap();
  if (!from_json.from_json(saved_json, &error) || from_json.to_text() != saved_text) __builtin_trap();
  return 0;
}
