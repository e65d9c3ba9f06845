// Named descriptions of a plugin's parameters and effects. C++17 has no designated initialisers,
// so each field is given by a setter of its own name, in any order, and a field left out takes its
// default: zero, or what zero stands for (written beside each setter). The result converts to the
// ABI's struct with struct_size set, so a table reads
//
//   const pfx_param_desc kParams[] = {
//       pfx::desc::param("strength").label("Strength").tooltip("How much light is added.")
//           .float_range(0, 100).display_range(0, 4).step(0.05).default_value(1.0),
//   };
//
// and no two numbers of a descriptor can trade places unseen.
#pragma once

#include <cstddef>
#include <cstdint>

#include <pfx/effect.h>
#include <pfx/params.h>

namespace pfx::desc {

// One parameter (pfx_param_desc). The type and the hard range come together from one of
// float_range, int_range, boolean, items, color_range, vec2_range or vec3_range: without one the
// parameter is a float whose only value is 0, which pfx-validate reports.
class Param {
 public:
  constexpr explicit Param(const char* id) : d_() {
    d_.struct_size = sizeof(pfx_param_desc);
    d_.id = id;
  }

  // For a UI. Left out: the id.
  constexpr Param& label(const char* text) {
    d_.label = text;
    return *this;
  }
  // One or two sentences for a UI. Left out: "".
  constexpr Param& tooltip(const char* text) {
    d_.tooltip = text;
    return *this;
  }
  // "px", "m", "deg"... Left out: "" (no unit).
  constexpr Param& unit(const char* text) {
    d_.unit = text;
    return *this;
  }
  // The UI group. Left out: "" (none).
  constexpr Param& group(const char* text) {
    d_.group = text;
    return *this;
  }

  constexpr Param& float_range(double min, double max) { return typed(PFX_PARAM_FLOAT, min, max); }
  // A whole number in [min, max].
  constexpr Param& int_range(double min, double max) { return typed(PFX_PARAM_INT, min, max); }
  // Off (0) or on (1).
  constexpr Param& boolean() { return typed(PFX_PARAM_BOOL, 0, 1); }
  // Linear RGB, every channel in [min, max].
  constexpr Param& color_range(double min, double max) { return typed(PFX_PARAM_COLOR, min, max); }
  constexpr Param& vec2_range(double min, double max) { return typed(PFX_PARAM_VEC2, min, max); }
  constexpr Param& vec3_range(double min, double max) { return typed(PFX_PARAM_VEC3, min, max); }
  // An enum of these items, its value the item's index. The descriptor keeps the pointer: give the
  // items static storage.
  template <std::size_t N>
  constexpr Param& items(const pfx_enum_item (&list)[N]) {
    return items(list, static_cast<uint32_t>(N));
  }
  constexpr Param& items(const pfx_enum_item* list, uint32_t count) {
    d_.items = list;
    d_.item_count = count;
    return typed(PFX_PARAM_ENUM, 0, count > 0 ? count - 1.0 : 0.0);
  }

  // A UI slider's range, inside the hard range. Left out (or 0, 0): the hard range.
  constexpr Param& display_range(double min, double max) {
    d_.display_min = min;
    d_.display_max = max;
    return *this;
  }
  // A UI's increment. Left out (or 0): 1 for int, bool and enum; a hundredth of the display range
  // for the others.
  constexpr Param& step(double increment) {
    d_.step = increment;
    return *this;
  }

  // The value a new instance starts from, one number per component. Left out: 0.
  constexpr Param& default_value(double x, double y = 0, double z = 0) {
    d_.default_value = value(x, y, z);
    return *this;
  }
  // The start for display-referred frames (nothing above 1.0: 8-bit video, an application's back
  // buffer) where it differs from default_value (ABI 1.4, PFX_PARAM_HAS_DISPLAY_DEFAULT). Left
  // out: default_value serves every frame.
  constexpr Param& display_default(double x, double y = 0, double z = 0) {
    d_.flags |= PFX_PARAM_HAS_DISPLAY_DEFAULT;
    d_.display_default = value(x, y, z);
    return *this;
  }

  // A UI should use a logarithmic slider (the display range must then be above 0).
  constexpr Param& logarithmic() { return flag(PFX_PARAM_LOGARITHMIC); }
  // A value outside the hard range is refused with an error instead of clamped.
  constexpr Param& reject_out_of_range() { return flag(PFX_PARAM_REJECT_OUT_OF_RANGE); }

  // The descriptor, every default filled in.
  constexpr operator pfx_param_desc() const {
    pfx_param_desc d = d_;
    if (!d.label) d.label = d.id;
    if (!d.tooltip) d.tooltip = "";
    if (!d.unit) d.unit = "";
    if (!d.group) d.group = "";
    if (d.display_min == 0 && d.display_max == 0) {
      d.display_min = d.hard_min;
      d.display_max = d.hard_max;
    }
    if (d.step == 0) d.step = default_step(d);
    return d;
  }

 private:
  constexpr Param& typed(pfx_param_type type, double min, double max) {
    d_.type = type;
    d_.hard_min = min;
    d_.hard_max = max;
    return *this;
  }
  constexpr Param& flag(uint32_t bit) {
    d_.flags |= bit;
    return *this;
  }
  static constexpr pfx_value value(double x, double y, double z) {
    pfx_value v{};
    v.v[0] = x;
    v.v[1] = y;
    v.v[2] = z;
    return v;
  }
  static constexpr double default_step(const pfx_param_desc& d) {
    if (d.type == PFX_PARAM_INT || d.type == PFX_PARAM_BOOL || d.type == PFX_PARAM_ENUM) return 1;
    const double span = d.display_max - d.display_min;
    return span > 0 && span < 1e300 ? span / 100 : 0.01;  // an infinite display range: 0.01
  }

  pfx_param_desc d_;
};

constexpr Param param(const char* id) { return Param(id); }

// One effect (pfx_effect_desc): its id and callbacks by name. Left out: the label is the id, the
// description "", no parameters, no report_json, no promises; create, destroy, declare and run_pass are required.
class Effect {
 public:
  constexpr explicit Effect(const char* id) : d_() {
    d_.struct_size = sizeof(pfx_effect_desc);
    d_.id = id;
  }
  constexpr Effect& label(const char* text) {
    d_.label = text;
    return *this;
  }
  constexpr Effect& description(const char* text) {
    d_.description = text;
    return *this;
  }
  // The parameter table; values reach declare and run_pass in its order.
  template <std::size_t N>
  constexpr Effect& params(const pfx_param_desc (&table)[N]) {
    return params(table, static_cast<uint32_t>(N));
  }
  constexpr Effect& params(const pfx_param_desc* table, uint32_t count) {
    d_.params = table;
    d_.param_count = count;
    return *this;
  }
  constexpr Effect& create(pfx_status (*fn)(const pfx_host*, void**)) {
    d_.create = fn;
    return *this;
  }
  constexpr Effect& destroy(void (*fn)(void*)) {
    d_.destroy = fn;
    return *this;
  }
  constexpr Effect& declare(pfx_status (*fn)(void*, const pfx_frame*, const pfx_value*, pfx_declaration*)) {
    d_.declare = fn;
    return *this;
  }
  constexpr Effect& run_pass(pfx_status (*fn)(void*, const pfx_pass_context*)) {
    d_.run_pass = fn;
    return *this;
  }
  constexpr Effect& report_json(const char* (*fn)(void*)) {
    d_.report_json = fn;
    return *this;
  }
  // The promise that, offered a frame of colour alone, it asks for nothing more
  // (PFX_EFFECT_COLOR_ONLY): hosts of video frames then offer it without making an instance.
  constexpr Effect& color_only() {
    d_.flags |= PFX_EFFECT_COLOR_ONLY;
    return *this;
  }

  constexpr operator pfx_effect_desc() const {
    pfx_effect_desc d = d_;
    if (!d.label) d.label = d.id;
    if (!d.description) d.description = "";
    return d;
  }

 private:
  pfx_effect_desc d_;
};

constexpr Effect effect(const char* id) { return Effect(id); }

}  // namespace pfx::desc
