// The parameter store: values per effect instance, validated against the plugins' descriptors,
// readable and writable as text ("bloom.threshold=1.5", "bloom#2.threshold=3") and JSON
// ({"bloom": {"threshold": 1.5}, "bloom#2": {"threshold": 3}}).
//
// The store owns the values and, per registered effect, the list of its instances, numbered from
// 1: "bloom#2" is the second, and plain "bloom" is the same as "bloom#1". A Chain holds instances
// of its store: its N-th bloom, in chain order, reads "bloom#N". As the chain adds, moves and
// removes instances the store's lists follow (values travel with an instance and leave with it),
// and the store never has fewer instances of an effect than its chain holds. Text and JSON
// written here name the first instance "bloom" and the others "bloom#2", "bloom#3", so with one
// instance per effect nothing changes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <pfx/params.h>
#include <pfx/effect.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

// Which of its defaults a parameter starts at. The frame decides: a renderer's HDR frame holds
// scene-linear light, where 1.0 is diffuse white and highlights go far above; a display-referred
// frame (8-bit video, an application's back buffer) holds nothing above 1.0, so thresholds made
// for highlights would never be reached there.
enum class DefaultSet {
  SCENE_REFERRED,   // default_value
  DISPLAY_REFERRED  // display_default where the descriptor has one (PFX_PARAM_HAS_DISPLAY_DEFAULT)
};

// The default `desc` gives for frames of that kind.
PFX_HOST_API pfx_value default_for(const pfx_param_desc& desc, DefaultSet set);

class PFX_HOST_API ParamStore {
 public:
  explicit ParamStore(DefaultSet defaults = DefaultSet::SCENE_REFERRED) : default_set_(defaults) {}
  // A copy has the values and no chain: the instances a chain holds are held in this store, not
  // in its values. Assigning replaces the values and keeps every instance this store's chain
  // holds (at the defaults where `other` has none of it), so the chain never loses its values.
  ParamStore(const ParamStore& other);
  ParamStore(ParamStore&& other) noexcept;
  ParamStore& operator=(const ParamStore& other);
  ParamStore& operator=(ParamStore&& other);
  ~ParamStore() = default;

  // The defaults new instances, reset() and a reloaded plugin's new parameters start from.
  DefaultSet default_set() const { return default_set_; }

  // Registers an effect's parameters at their defaults, with one instance. Registering an id
  // again (a reloaded plugin) keeps its instances and, in each, the value of every parameter whose
  // id and type are unchanged.
  void add_effect(const pfx_effect_desc* desc);
  bool has_effect(const std::string& effect) const { return effects_.count(effect) != 0; }
  // Forgets an effect and the values of all its instances (its plugin was reloaded without it).
  // False, and nothing forgotten, while a chain holds an instance of it.
  bool remove_effect(const std::string& effect);
  // The descriptor the effect's values were registered with; null for an unknown effect.
  const pfx_effect_desc* effect_descriptor(const std::string& effect) const;

  // Instances of a registered effect (0 for an unknown one); a chain's add, move and remove keep
  // them in step with the chain. set_instance_count gives values to instances a chain does not
  // hold yet: a preset applied before the chain that will hold "bloom#2", or a copy of the store
  // shaped like a chain to check values in. It grows with blocks at the defaults or drops the last
  // blocks. False, changing nothing, for an unknown effect, a count of 0, or fewer instances than
  // the store's chain holds.
  size_t instance_count(const std::string& effect) const;
  bool set_instance_count(const std::string& effect, size_t count);
  // "bloom" for number 1, "bloom#2" for number 2: the name text and JSON use.
  static std::string instance_name(const std::string& effect, size_t number);

  // In what follows, `instance` is an effect id ("bloom", its first instance) or an instance
  // name ("bloom#1", "bloom#2"), and a key is "instance.param". An instance that does not exist
  // is an error naming the key and how many instances the effect has.

  // Parses and sets one value. Text forms: float/int "1.5" "3"; bool true/false/1/0/on/off/yes/no;
  // enum: the item id (or its index); colour and vectors: "r,g,b". NaN is always refused; a value
  // outside the hard range is clamped (and *note says so) unless the descriptor asks for rejection.
  // On error returns false, sets *error to a sentence naming the key, and changes nothing.
  bool set(const std::string& key, const std::string& text, std::string* error, std::string* note = nullptr);
  // "instance.param=value", as given to --set.
  bool set_assignment(const std::string& assignment, std::string* error, std::string* note = nullptr);
  // set() with the value itself instead of its text.
  bool set_value(const std::string& instance, const std::string& param, const pfx_value& value,
                 std::string* error, std::string* note = nullptr);
  void reset(const std::string& instance, const std::string& param);

  // One value per descriptor of the effect, in descriptor order; null for an unknown instance.
  const pfx_value* values(const std::string& instance) const;
  const pfx_value* values(const std::string& effect, size_t number) const;
  const pfx_param_desc* descriptor(const std::string& instance, const std::string& param) const;
  // Changes whenever the instance's values do (a set, a reset, a reload, a move or removal that
  // gives its number other values), to a number it never had before.
  uint64_t revision(const std::string& instance) const;

  // The text form of one value ("chain13", "1.5", "1,0.5,0.25"); empty for an unknown key.
  std::string get_text(const std::string& key) const;
  // Every value as "instance.param=value" lines: effects in registration order, each effect's
  // instances in order, parameters in descriptor order.
  std::string to_text() const;
  // Lines of "instance.param=value"; blank lines and '#' comments ignored. All or nothing.
  bool from_text(const std::string& text, std::string* error);
  std::string to_json() const;
  // {"instance": {"param": value}}; numbers, booleans, enum item ids, arrays for vectors. Effects
  // or instances not registered here are an error. All or nothing.
  bool from_json(const std::string& json, std::string* error);

 private:
  // The chain holds instances through hold_instance, drop_instance, move_instance and
  // release_instance, and nothing else changes what it holds.
  friend class Chain;

  struct Block {
    std::vector<pfx_value> values;
    uint64_t revision = 0;
  };
  struct EffectParams {
    const pfx_effect_desc* desc = nullptr;
    std::vector<Block> instances;  // at least one
  };
  // One parameter of one instance, found by its key.
  struct Slot {
    const pfx_param_desc* desc = nullptr;
    Block* block = nullptr;
    uint32_t index = 0;  // into block->values
  };

  // A chain's new instance of `desc`, the last of its effect in chain order: registers the effect
  // when it is new and makes sure the store has a block for every instance the chain holds.
  void hold_instance(const pfx_effect_desc* desc);
  // The chain removed its instance `number`: its values go and later instances move down one
  // number, except when it is the effect's only block, whose values stay the effect's so that a
  // chain rebuilt from scratch finds them again.
  void drop_instance(const std::string& effect, size_t number);
  // The chain's instance `from` is now its number `to`: its values go with it, the others
  // shifting as in a list.
  void move_instance(const std::string& effect, size_t from, size_t to);
  // The chain let go of an instance without removing it (the chain itself is going): the values
  // stay.
  void release_instance(const std::string& effect);

  Block defaults(const pfx_effect_desc* desc);
  // After the values were replaced (`previous` were the old ones): a block for every instance the
  // chain holds.
  void keep_held(const std::map<std::string, EffectParams>& previous);
  // Resolves "bloom" / "bloom#N"; `key` is what error messages name.
  bool resolve(const std::string& instance, const std::string& key, const EffectParams** effect, size_t* index,
               std::string* error) const;
  bool find(const std::string& key, Slot* slot, std::string* error);
  // Validates `value` for the slot's parameter and writes it; *error names `key`.
  bool write(const std::string& key, const Slot& slot, pfx_value value, std::string* error, std::string* note);
  void store(const Slot& slot, const pfx_value& value);

  // The values: what a copy copies.
  std::map<std::string, EffectParams> effects_;
  std::vector<std::string> order_;
  uint64_t last_revision_ = 0;
  DefaultSet default_set_;
  // Per effect, how many of its instances the chain holds: the store's own, never copied.
  std::map<std::string, size_t> held_;
};

}  // namespace pfx::host
