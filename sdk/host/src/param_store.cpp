#include "pfx/host/param_store.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>

#include <nlohmann/json.hpp>

#include "descriptor_check.hpp"
#include "param_text.hpp"

namespace pfx::host {

void ParamStore::add_effect(const pfx_effect_desc* desc) {
  EffectParams fresh;
  fresh.desc = desc;
  for (uint32_t i = 0; i < desc->param_count; ++i) fresh.values.push_back(desc->params[i].default_value);
  auto existing = effects_.find(desc->id);
  if (existing == effects_.end()) {
    order_.push_back(desc->id);
  } else {
    // Carry values over by id and type: a reload that adds, removes or retypes a parameter keeps
    // the rest of the user's settings.
    const EffectParams& old = existing->second;
    for (uint32_t i = 0; i < desc->param_count; ++i)
      for (uint32_t j = 0; j < old.desc->param_count; ++j)
        if (std::strcmp(desc->params[i].id, old.desc->params[j].id) == 0 &&
            desc->params[i].type == old.desc->params[j].type) {
          pfx_value value = old.values[j];
          std::string ignored;
          if (validate_param_value(desc->params[i], &value, &ignored, nullptr)) fresh.values[i] = value;
        }
    fresh.revision = old.revision + 1;
  }
  effects_[desc->id] = std::move(fresh);
}

void ParamStore::remove_effect(const std::string& effect) {
  effects_.erase(effect);
  order_.erase(std::remove(order_.begin(), order_.end(), effect), order_.end());
}

const pfx_effect_desc* ParamStore::effect_descriptor(const std::string& effect) const {
  auto it = effects_.find(effect);
  return it == effects_.end() ? nullptr : it->second.desc;
}

bool ParamStore::find(const std::string& key, EffectParams** effect, uint32_t* index, std::string* error) {
  size_t dot = key.find('.');
  if (dot == std::string::npos) {
    *error = "'" + key + "' is not of the form effect.param";
    return false;
  }
  std::string effect_id = key.substr(0, dot), param_id = key.substr(dot + 1);
  auto it = effects_.find(effect_id);
  if (it == effects_.end()) {
    *error = "unknown effect '" + effect_id + "' in '" + key + "'";
    return false;
  }
  const pfx_effect_desc* desc = it->second.desc;
  for (uint32_t i = 0; i < desc->param_count; ++i)
    if (param_id == desc->params[i].id) {
      *effect = &it->second;
      *index = i;
      return true;
    }
  std::string known;
  for (uint32_t i = 0; i < desc->param_count; ++i) known += (i ? ", " : "") + std::string(desc->params[i].id);
  *error = "effect '" + effect_id + "' has no parameter '" + param_id + "'" +
           (known.empty() ? " (it has none)" : " (it has: " + known + ")");
  return false;
}

bool ParamStore::set(const std::string& key, const std::string& text, std::string* error, std::string* note) {
  std::string message;
  EffectParams* effect = nullptr;
  uint32_t index = 0;
  if (!find(key, &effect, &index, &message)) {
    if (error) *error = message;
    return false;
  }
  const pfx_param_desc& desc = effect->desc->params[index];
  pfx_value value{};
  if (!parse_param_text(desc, text, &value, &message) || !validate_param_value(desc, &value, &message, note)) {
    if (error) *error = key + ": " + message;
    return false;
  }
  effect->values[index] = value;
  ++effect->revision;
  return true;
}

bool ParamStore::set_assignment(const std::string& assignment, std::string* error, std::string* note) {
  size_t equals = assignment.find('=');
  if (equals == std::string::npos) {
    if (error) *error = "'" + assignment + "' is not of the form effect.param=value";
    return false;
  }
  std::string key = assignment.substr(0, equals);
  key.erase(std::remove_if(key.begin(), key.end(), [](char c) { return c == ' ' || c == '\t'; }), key.end());
  return set(key, assignment.substr(equals + 1), error, note);
}

bool ParamStore::set_value(const std::string& effect_id, const std::string& param, const pfx_value& input,
                           std::string* error, std::string* note) {
  std::string message;
  EffectParams* effect = nullptr;
  uint32_t index = 0;
  std::string key = effect_id + "." + param;
  if (!find(key, &effect, &index, &message)) {
    if (error) *error = message;
    return false;
  }
  pfx_value value = input;
  if (!validate_param_value(effect->desc->params[index], &value, &message, note)) {
    if (error) *error = key + ": " + message;
    return false;
  }
  effect->values[index] = value;
  ++effect->revision;
  return true;
}

void ParamStore::reset(const std::string& effect_id, const std::string& param) {
  EffectParams* effect = nullptr;
  uint32_t index = 0;
  std::string ignored;
  if (!find(effect_id + "." + param, &effect, &index, &ignored)) return;
  effect->values[index] = effect->desc->params[index].default_value;
  ++effect->revision;
}

const pfx_value* ParamStore::values(const std::string& effect) const {
  auto it = effects_.find(effect);
  if (it == effects_.end()) return nullptr;
  // An effect without parameters still gets a valid (never dereferenced) pointer.
  static const pfx_value none{};
  return it->second.values.empty() ? &none : it->second.values.data();
}

const pfx_param_desc* ParamStore::descriptor(const std::string& effect, const std::string& param) const {
  auto it = effects_.find(effect);
  if (it == effects_.end()) return nullptr;
  for (uint32_t i = 0; i < it->second.desc->param_count; ++i)
    if (param == it->second.desc->params[i].id) return &it->second.desc->params[i];
  return nullptr;
}

uint64_t ParamStore::revision(const std::string& effect) const {
  auto it = effects_.find(effect);
  return it == effects_.end() ? 0 : it->second.revision;
}

std::string ParamStore::get_text(const std::string& key) const {
  size_t dot = key.find('.');
  if (dot == std::string::npos) return "";
  auto it = effects_.find(key.substr(0, dot));
  if (it == effects_.end()) return "";
  const pfx_effect_desc* desc = it->second.desc;
  for (uint32_t i = 0; i < desc->param_count; ++i)
    if (key.compare(dot + 1, std::string::npos, desc->params[i].id) == 0)
      return format_param_text(desc->params[i], it->second.values[i]);
  return "";
}

std::string ParamStore::to_text() const {
  std::string text;
  for (const auto& id : order_) {
    const EffectParams& effect = effects_.at(id);
    for (uint32_t i = 0; i < effect.desc->param_count; ++i)
      text += id + "." + effect.desc->params[i].id + "=" + format_param_text(effect.desc->params[i], effect.values[i]) + "\n";
  }
  return text;
}

bool ParamStore::from_text(const std::string& text, std::string* error) {
  // Work on a copy so a bad line leaves the store untouched.
  ParamStore copy = *this;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::string message;
    if (!copy.set_assignment(line.substr(first), &message)) {
      if (error) *error = "line " + std::to_string(number) + ": " + message;
      return false;
    }
  }
  *this = std::move(copy);
  return true;
}

std::string ParamStore::to_json() const {
  nlohmann::ordered_json root = nlohmann::ordered_json::object();
  for (const auto& id : order_) {
    const EffectParams& effect = effects_.at(id);
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (uint32_t i = 0; i < effect.desc->param_count; ++i) {
      const pfx_param_desc& desc = effect.desc->params[i];
      const pfx_value& value = effect.values[i];
      switch (desc.type) {
        case PFX_PARAM_BOOL: params[desc.id] = value.v[0] != 0; break;
        case PFX_PARAM_ENUM: params[desc.id] = format_param_text(desc, value); break;
        case PFX_PARAM_INT: params[desc.id] = static_cast<long long>(value.v[0]); break;
        case PFX_PARAM_FLOAT: params[desc.id] = value.v[0]; break;
        default: {
          auto array = nlohmann::ordered_json::array();
          for (int c = 0; c < param_component_count(desc.type); ++c) array.push_back(value.v[c]);
          params[desc.id] = array;
        }
      }
    }
    root[id] = params;
  }
  return root.dump(2);
}

bool ParamStore::from_json(const std::string& json, std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(json);
  } catch (const nlohmann::json::exception& e) {
    return fail(std::string("not valid JSON: ") + e.what());
  }
  if (!root.is_object()) return fail("parameters JSON must be an object of effects");
  ParamStore copy = *this;
  for (const auto& [effect_id, params] : root.items()) {
    if (!params.is_object()) return fail("'" + effect_id + "' must map to an object of parameters");
    for (const auto& [param_id, value] : params.items()) {
      std::string key = effect_id + "." + param_id;
      std::string text;
      // Reuse the text path so JSON and --set accept exactly the same values.
      if (value.is_string()) text = value.get<std::string>();
      else if (value.is_boolean()) text = value.get<bool>() ? "true" : "false";
      else if (value.is_number()) text = format_number(value.get<double>());
      else if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i) {
          if (!value[i].is_number()) return fail(key + ": array items must be numbers");
          text += (i ? "," : "") + format_number(value[i].get<double>());
        }
      } else {
        return fail(key + ": unsupported JSON value " + value.dump());
      }
      std::string message;
      if (!copy.set(key, text, &message)) return fail(message);
    }
  }
  *this = std::move(copy);
  return true;
}

}  // namespace pfx::host
