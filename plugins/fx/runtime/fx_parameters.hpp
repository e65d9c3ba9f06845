#pragma once
// FX uniforms as pfx parameters: a uniform without a `source` annotation is something the user
// sets, so it becomes a typed parameter (float, int, bool, enum from ui_items, colour, vectors)
// with its ui_label, ui_tooltip, ui_category, ui_units, range and step. What a parameter writes
// into the uniform's components is kept beside it.
#include <string>
#include <vector>

#include <pfx/cpp/identifier.hpp>
#include <pfx/params.h>

#include "model/effect_model.hpp"

namespace pfx_fx {

struct ParamBinding {
  std::string uniform_name;  // qualified: instances find it in their own compile of the file
  int uniform = -1;     // index into the catalog's model's uniforms
  int first = 0;        // first component of the uniform this parameter writes
  int count = 1;        // components written
  bool whole = false;   // an integer uniform: round the value
};

// Strings and items the descriptors point to; owned beside them, never moved once built.
struct ParamTable {
  std::vector<pfx_param_desc> descs;
  std::vector<ParamBinding> bindings;
  std::vector<std::vector<pfx_enum_item>> items;
  std::vector<std::unique_ptr<std::string>> strings;
  // The FX names ("fUISharpness", and "fUIColor.a" for a float4's last component), for presets.
  std::vector<std::string> fx_names;

  const char* keep(const std::string& text);
};

// Builds the parameters of the uniforms the technique's passes may read (every uniform of the
// file without a source). `warnings` collects uniforms that cannot be parameters (matrices,
// arrays) and keep their initial value.
void build_params(const pfx::fx::EffectModel& model, ParamTable& table, std::vector<std::string>& warnings);

using pfx::identifier_from;  // ids of effects, parameters and items (pfx/cpp/identifier.hpp)

}  // namespace pfx_fx
