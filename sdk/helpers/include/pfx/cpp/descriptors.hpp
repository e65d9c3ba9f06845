// Header-only C++ builders for the ABI's descriptor structs (DESIGN.md §2), so a plugin's
// parameter table and pass list read as one line each and struct_size is never forgotten.
#pragma once

#include <pfx/effect.h>
#include <pfx/params.h>

namespace pfx::desc {

inline pfx_param_desc param(const char* id, const char* label, const char* tooltip, const char* unit,
                            const char* group, pfx_param_type type, double hard_min, double hard_max,
                            double display_min, double display_max, double step, pfx_value default_value) {
  pfx_param_desc d{};
  d.struct_size = sizeof(pfx_param_desc);
  d.id = id;
  d.label = label;
  d.tooltip = tooltip;
  d.unit = unit;
  d.group = group;
  d.type = type;
  d.hard_min = hard_min;
  d.hard_max = hard_max;
  d.display_min = display_min;
  d.display_max = display_max;
  d.step = step;
  d.default_value = default_value;
  return d;
}

// An enum parameter's items (the descriptor keeps the pointer: give it static storage).
inline pfx_param_desc with_items(pfx_param_desc d, const pfx_enum_item* items, uint32_t count) {
  d.items = items;
  d.item_count = count;
  return d;
}

// A parameter whose default for display-referred frames (8-bit video, an application's back
// buffer: nothing above 1.0) differs from its scene-linear one.
inline pfx_param_desc with_display_default(pfx_param_desc d, pfx_value display_default) {
  d.flags |= PFX_PARAM_HAS_DISPLAY_DEFAULT;
  d.display_default = display_default;
  return d;
}

// A target of a fixed size (the effect computes it in declare from the frame's size).
inline pfx_target_desc fixed_target(const char* name, pfx_format format, int width, int height) {
  pfx_target_desc t{};
  t.struct_size = sizeof t;
  t.name = name;
  t.format = format;
  t.size_mode = PFX_SIZE_FIXED;
  t.width = static_cast<uint32_t>(width);
  t.height = static_cast<uint32_t>(height);
  return t;
}

inline pfx_pass_desc fullscreen_pass(const char* name, const char* output, const pfx_pass_input* inputs,
                                     uint32_t input_count, pfx_blend blend, pfx_load load, uint32_t user_tag) {
  pfx_pass_desc pass{};
  pass.struct_size = sizeof pass;
  pass.name = name;
  pass.kind = PFX_PASS_FULLSCREEN;
  pass.output = output;
  pass.inputs = inputs;
  pass.input_count = input_count;
  pass.blend = blend;
  pass.load = load;
  pass.user_tag = user_tag;
  return pass;
}

}  // namespace pfx::desc
