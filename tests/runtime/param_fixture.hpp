// Hand-written descriptors for the parameter store tests: no plugin, no GL.
#pragma once

#include <limits>

#include <pfx/host/param_store.hpp>

namespace pfx::test {

inline pfx_param_desc make_param(const char* id, pfx_param_type type, double lo, double hi, double def) {
  pfx_param_desc p{};
  p.struct_size = sizeof p;
  p.id = id;
  p.label = id;
  p.tooltip = "";
  p.unit = "";
  p.group = "";
  p.type = type;
  p.hard_min = lo;
  p.hard_max = hi;
  p.display_min = lo;
  p.display_max = hi;
  p.step = 1;
  for (double& v : p.default_value.v) v = 0;
  p.default_value.v[0] = def;
  return p;
}

inline const pfx_enum_item kModes[] = {{"chain", "Chain"}, {"chain13", "13-tap chain"}, {"gaussian", "Gaussian"}};

// A "bloom" with one parameter of every type (levels refuses out-of-range values, focus reaches
// infinity), registered in a store of its own.
struct ParamFixture {
  pfx_param_desc params[6];
  pfx_effect_desc effect{};
  pfx::host::ParamStore store;
  ParamFixture() {
    params[0] = make_param("threshold", PFX_PARAM_FLOAT, 0, 100, 1);
    params[1] = make_param("levels", PFX_PARAM_INT, 0, 16, 6);
    params[1].flags = PFX_PARAM_REJECT_OUT_OF_RANGE;
    params[2] = make_param("mode", PFX_PARAM_ENUM, 0, 2, 0);
    params[2].items = kModes;
    params[2].item_count = 3;
    params[3] = make_param("tint", PFX_PARAM_COLOR, 0, 1000, 1);
    params[3].default_value.v[1] = params[3].default_value.v[2] = 1;
    params[4] = make_param("karis", PFX_PARAM_BOOL, 0, 1, 1);
    params[5] = make_param("focus", PFX_PARAM_FLOAT, 0.01, std::numeric_limits<double>::infinity(), 10);
    effect.struct_size = sizeof effect;
    effect.id = "bloom";
    effect.params = params;
    effect.param_count = 6;
    store.add_effect(&effect);
  }
};

}  // namespace pfx::test
