#include "pfx/host/param_store.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "descriptor_check.hpp"
#include "param_text.hpp"

namespace pfx::host {

namespace {

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

std::string count_text(size_t count) {
  return std::to_string(count) + (count == 1 ? " instance" : " instances");
}

nlohmann::ordered_json json_value(const pfx_param_desc& desc, const pfx_value& value) {
  switch (desc.type) {
    case PFX_PARAM_BOOL: return value.v[0] != 0;
    case PFX_PARAM_ENUM: return format_param_text(desc, value);
    case PFX_PARAM_INT: return static_cast<long long>(value.v[0]);
    case PFX_PARAM_FLOAT: return value.v[0];
    default: {
      auto array = nlohmann::ordered_json::array();
      for (int c = 0; c < param_component_count(desc.type); ++c) array.push_back(value.v[c]);
      return array;
    }
  }
}

}  // namespace

pfx_value default_for(const pfx_param_desc& desc, DefaultSet set) {
  const bool display = set == DefaultSet::DISPLAY_REFERRED && (desc.flags & PFX_PARAM_HAS_DISPLAY_DEFAULT) &&
                       PFX_STRUCT_HAS(&desc, pfx_param_desc, display_default);
  return display ? desc.display_default : desc.default_value;
}

ParamStore::ParamStore(const ParamStore& other)
    : effects_(other.effects_),
      order_(other.order_),
      last_revision_(other.last_revision_),
      default_set_(other.default_set_) {}

ParamStore::ParamStore(ParamStore&& other) noexcept
    : effects_(std::move(other.effects_)),
      order_(std::move(other.order_)),
      last_revision_(other.last_revision_),
      default_set_(other.default_set_) {}

ParamStore& ParamStore::operator=(const ParamStore& other) {
  if (this != &other) *this = ParamStore(other);
  return *this;
}

ParamStore& ParamStore::operator=(ParamStore&& other) {
  if (this == &other) return *this;
  const std::map<std::string, EffectParams> previous = std::move(effects_);
  effects_ = std::move(other.effects_);
  order_ = std::move(other.order_);
  last_revision_ = other.last_revision_;
  default_set_ = other.default_set_;
  keep_held(previous);
  return *this;
}

void ParamStore::keep_held(const std::map<std::string, EffectParams>& previous) {
  for (const auto& [effect, held] : held_) {
    auto it = effects_.find(effect);
    if (it == effects_.end()) {
      // Values without the effect at all: the chain keeps the ones it had.
      it = effects_.emplace(effect, previous.at(effect)).first;
      order_.push_back(effect);
    }
    std::vector<Block>& instances = it->second.instances;
    while (instances.size() < held) instances.push_back(defaults(it->second.desc));
  }
}

ParamStore::Block ParamStore::defaults(const pfx_effect_desc* desc) {
  Block block;
  for (uint32_t i = 0; i < desc->param_count; ++i) block.values.push_back(default_for(desc->params[i], default_set_));
  block.revision = ++last_revision_;
  return block;
}

void ParamStore::add_effect(const pfx_effect_desc* desc) {
  EffectParams fresh;
  fresh.desc = desc;
  auto existing = effects_.find(desc->id);
  if (existing == effects_.end()) {
    order_.push_back(desc->id);
    fresh.instances.push_back(defaults(desc));
  } else {
    // Carry values over by id and type, instance by instance: a reload that adds, removes or
    // retypes a parameter keeps the rest of the user's settings.
    const EffectParams& old = existing->second;
    for (const Block& old_block : old.instances) {
      Block block = defaults(desc);
      for (uint32_t i = 0; i < desc->param_count; ++i)
        for (uint32_t j = 0; j < old.desc->param_count; ++j)
          if (std::strcmp(desc->params[i].id, old.desc->params[j].id) == 0 &&
              desc->params[i].type == old.desc->params[j].type) {
            pfx_value value = old_block.values[j];
            std::string ignored;
            if (validate_param_value(desc->params[i], &value, &ignored, nullptr)) block.values[i] = value;
          }
      fresh.instances.push_back(std::move(block));
    }
  }
  effects_[desc->id] = std::move(fresh);
}

bool ParamStore::remove_effect(const std::string& effect) {
  if (held_.count(effect)) return false;
  effects_.erase(effect);
  order_.erase(std::remove(order_.begin(), order_.end(), effect), order_.end());
  return true;
}

const pfx_effect_desc* ParamStore::effect_descriptor(const std::string& effect) const {
  auto it = effects_.find(effect);
  return it == effects_.end() ? nullptr : it->second.desc;
}

size_t ParamStore::instance_count(const std::string& effect) const {
  auto it = effects_.find(effect);
  return it == effects_.end() ? 0 : it->second.instances.size();
}

bool ParamStore::set_instance_count(const std::string& effect, size_t count) {
  auto it = effects_.find(effect);
  if (it == effects_.end() || count == 0) return false;
  auto held = held_.find(effect);
  if (held != held_.end() && count < held->second) return false;
  std::vector<Block>& instances = it->second.instances;
  if (count < instances.size()) instances.resize(count);
  while (instances.size() < count) instances.push_back(defaults(it->second.desc));
  return true;
}

void ParamStore::hold_instance(const pfx_effect_desc* desc) {
  if (!has_effect(desc->id)) add_effect(desc);
  EffectParams& effect = effects_.at(desc->id);
  const size_t held = ++held_[desc->id];
  while (effect.instances.size() < held) effect.instances.push_back(defaults(effect.desc));
}

void ParamStore::release_instance(const std::string& effect) {
  auto held = held_.find(effect);
  if (held != held_.end() && --held->second == 0) held_.erase(held);
}

void ParamStore::drop_instance(const std::string& effect, size_t number) {
  release_instance(effect);
  auto it = effects_.find(effect);
  if (it == effects_.end()) return;
  std::vector<Block>& instances = it->second.instances;
  if (instances.size() < 2 || number < 1 || number > instances.size()) return;
  instances.erase(instances.begin() + static_cast<long>(number - 1));
  // The numbers from `number` on now hold other values.
  for (size_t i = number - 1; i < instances.size(); ++i) instances[i].revision = ++last_revision_;
}

void ParamStore::move_instance(const std::string& effect, size_t from, size_t to) {
  auto it = effects_.find(effect);
  if (it == effects_.end()) return;
  std::vector<Block>& instances = it->second.instances;
  if (from < 1 || from > instances.size() || to < 1 || to > instances.size() || from == to) return;
  Block moved = std::move(instances[from - 1]);
  instances.erase(instances.begin() + static_cast<long>(from - 1));
  instances.insert(instances.begin() + static_cast<long>(to - 1), std::move(moved));
  for (size_t i = std::min(from, to) - 1; i < std::max(from, to); ++i) instances[i].revision = ++last_revision_;
}

std::string ParamStore::instance_name(const std::string& effect, size_t number) {
  return number <= 1 ? effect : effect + "#" + std::to_string(number);
}

bool ParamStore::resolve(const std::string& instance, const std::string& key, const EffectParams** effect,
                         size_t* index, std::string* error) const {
  const size_t hash = instance.find('#');
  const std::string effect_id = instance.substr(0, hash);
  auto it = effects_.find(effect_id);
  if (it == effects_.end()) {
    *error = "unknown effect '" + effect_id + "' in '" + key + "'";
    return false;
  }
  const size_t count = it->second.instances.size();
  size_t number = 1;
  if (hash != std::string::npos) {
    const std::string digits = instance.substr(hash + 1);
    const std::string has = "effect '" + effect_id + "' has " + count_text(count);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
      *error = "'" + key + "': '" + digits + "' is not an instance number (" + has + ", " + effect_id + "#1 to " +
               effect_id + "#" + std::to_string(count) + ")";
      return false;
    }
    // More digits than any chain could hold instances: no such instance, without overflowing.
    number = digits.size() > 9 ? size_t(-1) : std::stoul(digits);
    if (number == 0) {
      *error = "'" + key + "': instances are numbered from 1 (" + has + ")";
      return false;
    }
    if (number > count) {
      *error = "'" + key + "': there is no " + effect_id + "#" + digits + ", " + has;
      return false;
    }
  }
  *effect = &it->second;
  *index = number - 1;
  return true;
}

bool ParamStore::find(const std::string& key, Slot* slot, std::string* error) {
  size_t dot = key.find('.');
  if (dot == std::string::npos) {
    *error = "'" + key + "' is not of the form effect.param";
    return false;
  }
  std::string instance = key.substr(0, dot), param_id = key.substr(dot + 1);
  const EffectParams* found = nullptr;
  size_t index = 0;
  if (!resolve(instance, key, &found, &index, error)) return false;
  EffectParams& params = effects_.at(found->desc->id);
  const pfx_effect_desc* desc = params.desc;
  for (uint32_t i = 0; i < desc->param_count; ++i)
    if (param_id == desc->params[i].id) {
      *slot = {&desc->params[i], &params.instances[index], i};
      return true;
    }
  std::string known;
  for (uint32_t i = 0; i < desc->param_count; ++i) known += (i ? ", " : "") + std::string(desc->params[i].id);
  *error = "effect '" + std::string(desc->id) + "' has no parameter '" + param_id + "'" +
           (known.empty() ? " (it has none)" : " (it has: " + known + ")");
  return false;
}

bool ParamStore::write(const std::string& key, const Slot& slot, pfx_value value, std::string* error,
                       std::string* note) {
  std::string message;
  if (!validate_param_value(*slot.desc, &value, &message, note)) return fail(error, key + ": " + message);
  store(slot, value);
  return true;
}

void ParamStore::store(const Slot& slot, const pfx_value& value) {
  slot.block->values[slot.index] = value;
  slot.block->revision = ++last_revision_;
}

bool ParamStore::set(const std::string& key, const std::string& text, std::string* error, std::string* note) {
  std::string message;
  Slot slot;
  if (!find(key, &slot, &message)) return fail(error, message);
  pfx_value value{};
  if (!parse_param_text(*slot.desc, text, &value, &message)) return fail(error, key + ": " + message);
  return write(key, slot, value, error, note);
}

bool ParamStore::set_assignment(const std::string& assignment, std::string* error, std::string* note) {
  size_t equals = assignment.find('=');
  if (equals == std::string::npos) return fail(error, "'" + assignment + "' is not of the form effect.param=value");
  std::string key = assignment.substr(0, equals);
  key.erase(std::remove_if(key.begin(), key.end(), [](char c) { return c == ' ' || c == '\t'; }), key.end());
  return set(key, assignment.substr(equals + 1), error, note);
}

bool ParamStore::set_value(const std::string& instance, const std::string& param, const pfx_value& value,
                           std::string* error, std::string* note) {
  const std::string key = instance + "." + param;
  std::string message;
  Slot slot;
  if (!find(key, &slot, &message)) return fail(error, message);
  return write(key, slot, value, error, note);
}

void ParamStore::reset(const std::string& instance, const std::string& param) {
  Slot slot;
  std::string ignored;
  if (find(instance + "." + param, &slot, &ignored)) store(slot, default_for(*slot.desc, default_set_));
}

const pfx_value* ParamStore::values(const std::string& effect, size_t number) const {
  auto it = effects_.find(effect);
  if (it == effects_.end() || number < 1 || number > it->second.instances.size()) return nullptr;
  // An effect without parameters still gets a valid (never dereferenced) pointer.
  static const pfx_value none{};
  const std::vector<pfx_value>& values = it->second.instances[number - 1].values;
  return values.empty() ? &none : values.data();
}

const pfx_value* ParamStore::values(const std::string& instance) const {
  const EffectParams* effect = nullptr;
  size_t index = 0;
  std::string ignored;
  if (!resolve(instance, instance, &effect, &index, &ignored)) return nullptr;
  return values(effect->desc->id, index + 1);
}

const pfx_param_desc* ParamStore::descriptor(const std::string& instance, const std::string& param) const {
  const EffectParams* effect = nullptr;
  size_t index = 0;
  std::string ignored;
  if (!resolve(instance, instance, &effect, &index, &ignored)) return nullptr;
  for (uint32_t i = 0; i < effect->desc->param_count; ++i)
    if (param == effect->desc->params[i].id) return &effect->desc->params[i];
  return nullptr;
}

uint64_t ParamStore::revision(const std::string& instance) const {
  const EffectParams* effect = nullptr;
  size_t index = 0;
  std::string ignored;
  return resolve(instance, instance, &effect, &index, &ignored) ? effect->instances[index].revision : 0;
}

std::string ParamStore::get_text(const std::string& key) const {
  size_t dot = key.find('.');
  if (dot == std::string::npos) return "";
  const EffectParams* effect = nullptr;
  size_t index = 0;
  std::string ignored;
  if (!resolve(key.substr(0, dot), key, &effect, &index, &ignored)) return "";
  const pfx_effect_desc* desc = effect->desc;
  for (uint32_t i = 0; i < desc->param_count; ++i)
    if (key.compare(dot + 1, std::string::npos, desc->params[i].id) == 0)
      return format_param_text(desc->params[i], effect->instances[index].values[i]);
  return "";
}

std::string ParamStore::to_text() const {
  std::string text;
  for (const auto& id : order_) {
    const EffectParams& effect = effects_.at(id);
    for (size_t n = 0; n < effect.instances.size(); ++n) {
      const std::string name = instance_name(id, n + 1);
      for (uint32_t i = 0; i < effect.desc->param_count; ++i)
        text += name + "." + effect.desc->params[i].id + "=" +
                format_param_text(effect.desc->params[i], effect.instances[n].values[i]) + "\n";
    }
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
    for (size_t n = 0; n < effect.instances.size(); ++n) {
      nlohmann::ordered_json params = nlohmann::ordered_json::object();
      for (uint32_t i = 0; i < effect.desc->param_count; ++i)
        params[effect.desc->params[i].id] = json_value(effect.desc->params[i], effect.instances[n].values[i]);
      root[instance_name(id, n + 1)] = params;
    }
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
  // "bloom" and "bloom#1" are one instance: a file naming it twice is ambiguous.
  std::map<std::pair<std::string, size_t>, std::string> named;
  for (const auto& [instance, params] : root.items()) {
    if (!params.is_object()) return fail("'" + instance + "' must map to an object of parameters");
    const EffectParams* effect = nullptr;
    size_t index = 0;
    std::string message;
    if (!resolve(instance, instance, &effect, &index, &message)) return fail(message);
    auto [other, fresh] = named.emplace(std::make_pair(std::string(effect->desc->id), index), instance);
    if (!fresh) return fail("'" + other->second + "' and '" + instance + "' name the same instance");
    for (const auto& [param_id, value] : params.items()) {
      std::string key = instance + "." + param_id;
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
      if (!copy.set(key, text, &message)) return fail(message);
    }
  }
  *this = std::move(copy);
  return true;
}

}  // namespace pfx::host
