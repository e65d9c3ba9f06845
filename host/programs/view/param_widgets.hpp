// Dear ImGui widgets for an effect's parameters, made from the descriptors alone (no code here
// knows any plugin): sliders over the display range with the unit, drag fields for vectors, combos
// for enums, colour pickers, check boxes; tooltips; the descriptors' groups as tree nodes; a reset
// button where a value differs from its default. Every change goes through the ParamStore, which
// validates and clamps it.
#pragma once

#include <string>
#include <vector>

#include <pfx/host/param_store.hpp>

namespace pfx::app {

// The effect's parameters at the frame size being rendered (pfx::host::params_at_frame_size),
// for those flagged PFX_PARAM_FOLLOWS_FRAME_SIZE; empty when it has none.
struct FrameSizeParams {
  std::vector<pfx_param_desc> params;
  std::string size;  // "640x360"
};

// The values of one instance of the effect ("bloom", "bloom#2": ParamStore's names). Returns true
// when a value changed. A refused change leaves *problem set (else it is cleared).
bool draw_effect_parameters(const pfx_effect_desc& effect, const std::string& instance, pfx::host::ParamStore& params,
                            std::string* problem, const FrameSizeParams& at_frame = {});

// The ImGui format for a number with its unit: "%.3f px" (a '%' in the unit doubled).
std::string number_format(const pfx_param_desc& param, bool integer);

}  // namespace pfx::app
