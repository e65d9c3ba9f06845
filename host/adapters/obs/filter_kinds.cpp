#include "filter_kinds.hpp"

#include <pfx/host/param_store.hpp>

#include "plugin_listing.hpp"

namespace pfx::obs {
namespace {

int components(pfx_param_type type) {
  switch (type) {
    case PFX_PARAM_COLOR:
    case PFX_PARAM_VEC3: return 3;
    case PFX_PARAM_VEC2: return 2;
    default: return 1;
  }
}

// A vector's components are separate numbers in OBS: "tint.0", "tint.1", "tint.2".
std::string component_key(const pfx_param_desc& param, int component) {
  return components(param.type) == 1 ? param.id : std::string(param.id) + "." + std::to_string(component);
}

std::string label_of(const pfx_param_desc& param, int component) {
  static const char* const rgb[] = {"red", "green", "blue"};
  static const char* const xyz[] = {"x", "y", "z"};
  std::string label = param.label;
  if (components(param.type) > 1)
    label += std::string(" (") + (param.type == PFX_PARAM_COLOR ? rgb : xyz)[component] + ")";
  if (param.unit && *param.unit) label += std::string(" [") + param.unit + "]";
  return label;
}

// `param` as listed; `shown` the same at the source's frame size (its slider range).
void add_parameter(obs_properties_t* props, const pfx_param_desc& param, const pfx_param_desc& shown,
                   const std::string& size) {
  for (int c = 0; c < components(param.type); ++c) {
    const std::string key = component_key(param, c);
    const std::string label = label_of(param, c);
    obs_property_t* property = nullptr;
    switch (param.type) {
      case PFX_PARAM_BOOL: property = obs_properties_add_bool(props, key.c_str(), label.c_str()); break;
      case PFX_PARAM_INT:
        property = obs_properties_add_int_slider(props, key.c_str(), label.c_str(), static_cast<int>(shown.display_min),
                                                 static_cast<int>(shown.display_max),
                                                 param.step >= 1 ? static_cast<int>(param.step) : 1);
        break;
      case PFX_PARAM_ENUM:
        property = obs_properties_add_list(props, key.c_str(), label.c_str(), OBS_COMBO_TYPE_LIST,
                                           OBS_COMBO_FORMAT_STRING);
        for (uint32_t i = 0; i < param.item_count; ++i)
          obs_property_list_add_string(property, param.items[i].label, param.items[i].id);
        break;
      default:
        property = obs_properties_add_float_slider(props, key.c_str(), label.c_str(), shown.display_min,
                                                   shown.display_max, param.step > 0 ? param.step : 0.001);
        break;
    }
    std::string explanation = param.tooltip ? param.tooltip : "";
    if (param.flags & PFX_PARAM_FOLLOWS_FRAME_SIZE)
      explanation += std::string(explanation.empty() ? "" : " ") + "Its default and range follow the frame size (" +
                     (size.empty() ? "" : app::value_text(shown, shown.default_value) + " at " + size + "; ") +
                     "the listed default " + app::value_text(param, param.default_value) + " means the frame's own).";
    if (!explanation.empty()) obs_property_set_long_description(property, explanation.c_str());
  }
}

}  // namespace

obs_properties_t* kind_properties(const FilterKind& kind, uint32_t width, uint32_t height) {
  obs_properties_t* props = obs_properties_create();
  if (kind.effect) {
    std::vector<pfx_param_desc> at_size;
    if (width > 0 && height > 0 && kind.plugin)
      at_size = host::params_at_frame_size(host::EffectInfo{kind.effect, kind.plugin}, width, height);
    const std::string size = at_size.empty() ? "" : std::to_string(width) + "x" + std::to_string(height);
    for (uint32_t i = 0; i < kind.effect->param_count; ++i)
      add_parameter(props, kind.effect->params[i], at_size.empty() ? kind.effect->params[i] : at_size[i], size);
    return props;
  }
  obs_property_t* chain = obs_properties_add_text(props, "chain", "Chain", OBS_TEXT_DEFAULT);
  obs_property_set_long_description(chain, "pfx effects to run, in order, separated by ',' (e.g. bloom,glare); none: "
                                           "no effect; empty: the preset's chain. Effects see colour alone (no depth)");
  obs_property_t* set = obs_properties_add_text(props, "set", "Values", OBS_TEXT_MULTILINE);
  obs_property_set_long_description(set, "effect.param=value items separated by ';' (bloom.threshold=0.5; "
                                         "bloom.strength=2), applied after the preset");
  obs_property_t* transfer = obs_properties_add_list(props, "transfer", "Transfer", OBS_COMBO_TYPE_LIST,
                                                     OBS_COMBO_FORMAT_STRING);
  obs_property_list_add_string(transfer, "sRGB (what almost all video holds)", "srgb");
  obs_property_list_add_string(transfer, "linear", "linear");
  obs_properties_add_path(props, "preset", "Preset (pfx-view's .json or ReShade's .ini)", OBS_PATH_FILE,
                          "Presets (*.json *.ini);;All files (*)", nullptr);
  return props;
}

void kind_defaults(const FilterKind& kind, obs_data_t* settings) {
  if (!kind.effect) {
    const adapters::ChainSettings defaults;
    obs_data_set_default_string(settings, "chain", defaults.chain.c_str());
    obs_data_set_default_string(settings, "set", defaults.set.c_str());
    obs_data_set_default_string(settings, "transfer", defaults.transfer.c_str());
    obs_data_set_default_string(settings, "preset", defaults.preset.c_str());
    return;
  }
  for (uint32_t i = 0; i < kind.effect->param_count; ++i) {
    const pfx_param_desc& param = kind.effect->params[i];
    const pfx_value value = host::default_for(param, host::DefaultSet::DISPLAY_REFERRED);
    for (int c = 0; c < components(param.type); ++c) {
      const std::string key = component_key(param, c);
      switch (param.type) {
        case PFX_PARAM_BOOL: obs_data_set_default_bool(settings, key.c_str(), value.v[0] != 0); break;
        case PFX_PARAM_INT: obs_data_set_default_int(settings, key.c_str(), static_cast<long long>(value.v[0])); break;
        case PFX_PARAM_ENUM: obs_data_set_default_string(settings, key.c_str(), app::value_text(param, value).c_str()); break;
        default: obs_data_set_default_double(settings, key.c_str(), value.v[c]); break;
      }
    }
  }
}

adapters::ChainSettings kind_chain_settings(const FilterKind& kind, obs_data_t* settings) {
  adapters::ChainSettings chain;
  if (!kind.effect) {
    chain.chain = obs_data_get_string(settings, "chain");
    chain.set = obs_data_get_string(settings, "set");
    chain.transfer = obs_data_get_string(settings, "transfer");
    chain.preset = obs_data_get_string(settings, "preset");
    return chain;
  }
  chain.chain = kind.effect->id;
  for (uint32_t i = 0; i < kind.effect->param_count; ++i) {
    const pfx_param_desc& param = kind.effect->params[i];
    pfx_value value{};
    for (int c = 0; c < components(param.type); ++c) {
      const std::string key = component_key(param, c);
      switch (param.type) {
        case PFX_PARAM_BOOL: value.v[0] = obs_data_get_bool(settings, key.c_str()) ? 1 : 0; break;
        case PFX_PARAM_INT: value.v[0] = static_cast<double>(obs_data_get_int(settings, key.c_str())); break;
        case PFX_PARAM_ENUM: {
          const std::string id = obs_data_get_string(settings, key.c_str());
          for (uint32_t item = 0; item < param.item_count; ++item)
            if (id == param.items[item].id) value.v[0] = item;
          break;
        }
        default: value.v[c] = obs_data_get_double(settings, key.c_str()); break;
      }
    }
    chain.set += std::string(kind.effect->id) + "." + param.id + "=" + app::value_text(param, value) + ";";
  }
  return chain;
}

}  // namespace pfx::obs
