// The bridge's native path: a chain whose every effect runs on Vulkan (pfx/vulkan_effects.h).
// Each effect's instance records its passes over the caller's image, one after the other, into a
// command buffer the bridge submits on the caller's queue: no GL context, no copy of the frame,
// no wait of the CPU for the device. The values are the recipe's (the preset's, then the
// assignments) over the display-referred defaults, as the GL path's FrameChain gives them, taken
// when the recipe is set.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <pfx/host/plugin_registry.hpp>
#include <pfx/vulkan_effects.h>

#include "chain_builder.hpp"

namespace pfx::vk {

class NativeChain {
 public:
  NativeChain() = default;
  ~NativeChain() { destroy_instances(); }  // after the work they recorded completed
  NativeChain(const NativeChain&) = delete;
  NativeChain& operator=(const NativeChain&) = delete;

  // Whether the recipe can run here: every effect of it (on or off, as a later update may switch
  // it on) comes from a plugin whose Vulkan factory runs it, and makes instances with
  // preprocessor definitions (ABI 1.8) when the recipe sets some. Else false with *why naming
  // what does not.
  static bool takes(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, std::string* why);

  // A recipe takes() accepts. When it names the same effects in the same order and the same
  // preprocessor definitions, only values and on/off flags change; otherwise the instances go
  // (after `idle`, which waits for the work that used them) and the new ones are made at the next
  // prepare(), except at the sizes frames already ran at, made here so that one that cannot be
  // made refuses the recipe. All or nothing: false with *error naming the assignment, definition
  // or effect that does not apply, and the chain as it was.
  bool set_recipe(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                  const std::function<void()>& idle, std::string* error);
  // "fx_a,fx_b (off)" as FrameChain::text; "none" for no effect.
  std::string text() const;
  bool runs_effects() const;

  // The instances of the effects that are on, for frames of that size and format: made when
  // missing. Each size and format has instances of its own (two windows of other sizes presented
  // in turn, each keeping what its effects keep across frames), up to kSizes; a new one beyond
  // that replaces the one least recently used, after `idle`. False with *error naming the effect
  // that could not be made.
  bool prepare(const pfx_vk_device& device, uint32_t width, uint32_t height, VkFormat format,
               const std::function<void()>& idle, std::string* error);
  // Records every effect that is on over `image` (of the size and format prepare() was last given;
  // in `layout` before and after), in chain order.
  // False with *error naming the effect that failed; the commands recorded until then must not be
  // submitted.
  bool record(VkCommandBuffer commands, VkImage image, VkImageLayout layout, bool alpha_unused, double time_seconds,
              uint64_t frame_index, std::string* error);

 private:
  static constexpr size_t kSizes = 4;
  struct Effect {
    std::string id, name;  // name: "fx_a#2" for the second fx_a
    bool enabled = true;
    const pfx_vulkan_effect_factory* factory = nullptr;
    const pfx_host* host = nullptr;
    std::vector<pfx_value> values;  // one per parameter, in descriptor order
  };
  // The instances for one size and format, one per effect (null where not made: an effect off).
  struct Instances {
    uint32_t width = 0, height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::vector<void*> of_effect;
    uint64_t last_used = 0;
  };
  // The effects of `recipe` with their values; false with *error naming one that cannot run.
  static bool effects_of(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                         std::vector<Effect>* effects, std::string* error);
  // Makes the instances `instances` lacks of the effects that are on, on device_; false with
  // *error naming the effect that could not be made (those made stay in `instances`).
  bool make_missing(const std::vector<Effect>& effects, const std::string& definitions, Instances& instances,
                    std::string* error) const;
  void destroy(const std::vector<Effect>& effects, Instances& instances);
  void destroy_instances();

  std::vector<Effect> effects_;
  std::string definitions_;  // the recipe's preprocessor definitions, which every instance was made with
  std::vector<Instances> sizes_;
  Instances* current_ = nullptr;  // prepare()'s, for record()
  pfx_vk_device device_{};        // the device of the last prepare(), where instances are made
  uint64_t uses_ = 0;
};

}  // namespace pfx::vk
