// The parameter store: values keyed "effect.param", validated against the plugins' descriptors,
// readable and writable as text ("bloom.threshold=1.5") and JSON ({"bloom": {"threshold": 1.5}}).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <pfx/params.h>
#include <pfx/effect.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

class PFX_HOST_API ParamStore {
 public:
  // Registers an effect's parameters at their defaults. Registering an id again (a reloaded
  // plugin) keeps the value of every parameter whose id and type are unchanged.
  void add_effect(const pfx_effect_desc* desc);
  bool has_effect(const std::string& effect) const { return effects_.count(effect) != 0; }
  // Forgets an effect and its values (its plugin was reloaded without it).
  void remove_effect(const std::string& effect);
  // The descriptor the effect's values were registered with; null for an unknown effect.
  const pfx_effect_desc* effect_descriptor(const std::string& effect) const;

  // Parses and sets one value. Text forms: float/int "1.5" "3"; bool true/false/1/0/on/off/yes/no;
  // enum: the item id (or its index); colour and vectors: "r,g,b". NaN is always refused; a value
  // outside the hard range is clamped (and *note says so) unless the descriptor asks for rejection.
  // On error returns false, sets *error to a sentence naming the key, and changes nothing.
  bool set(const std::string& key, const std::string& text, std::string* error, std::string* note = nullptr);
  // "effect.param=value", as given to --set.
  bool set_assignment(const std::string& assignment, std::string* error, std::string* note = nullptr);
  bool set_value(const std::string& effect, const std::string& param, const pfx_value& value,
                 std::string* error, std::string* note = nullptr);
  void reset(const std::string& effect, const std::string& param);

  // One value per descriptor of the effect, in descriptor order; null for an unknown effect.
  const pfx_value* values(const std::string& effect) const;
  const pfx_param_desc* descriptor(const std::string& effect, const std::string& param) const;
  // Bumped by every change to the effect's values: the chain re-declares when it moves.
  uint64_t revision(const std::string& effect) const;

  // The text form of one value ("chain13", "1.5", "1,0.5,0.25"); empty for an unknown key.
  std::string get_text(const std::string& key) const;
  // Every value as "effect.param=value" lines, effects and parameters in registration order.
  std::string to_text() const;
  // Lines of "effect.param=value"; blank lines and '#' comments ignored. All or nothing.
  bool from_text(const std::string& text, std::string* error);
  std::string to_json() const;
  // {"effect": {"param": value}}; numbers, booleans, enum item ids, arrays for vectors. Effects
  // not registered here are an error. All or nothing.
  bool from_json(const std::string& json, std::string* error);

 private:
  struct EffectParams {
    const pfx_effect_desc* desc = nullptr;
    std::vector<pfx_value> values;
    uint64_t revision = 0;
  };
  bool find(const std::string& key, EffectParams** effect, uint32_t* index, std::string* error);
  std::map<std::string, EffectParams> effects_;
  std::vector<std::string> order_;
};

}  // namespace pfx::host
