// An application's frame is colour alone (no depth, normals or lights come with a VkImage), so the
// chain is fitted to it as pfx-inject fits its chain to a frame without usable depth: the default
// chain leaves out the effects that need more, a chosen chain switches them off, each time with
// one line naming what they need.
#include "bridge.hpp"
#include "colour_only.hpp"

namespace pfx::vk {
namespace {

std::string needs_text(const adapters::EffectInputs& input) {
  if (input.needs.empty()) return input.error;
  std::string text;
  for (const auto& need : input.needs) text += (text.empty() ? "" : ", ") + need;
  return text;
}

}  // namespace

bool fit_recipe_to_colour(pfx_vk_bridge* bridge, app::ChainRecipe* recipe, std::string* error) {
  if (recipe->effects.empty()) return true;
  // Each effect is made once and asked what it reads: a GL job.
  std::vector<adapters::EffectInputs> inputs;
  if (!bridge->worker->run([&] { inputs = adapters::classify_effects(*bridge->registry); }, error)) return false;
  std::string left_out;
  std::vector<app::PresetEffect> kept;
  for (auto effect : recipe->effects) {
    for (const auto& input : inputs) {
      if (input.id != effect.id) continue;
      if (!input.colour_only && !recipe->chosen) {
        left_out += (left_out.empty() ? "" : ", ") + effect.id + " (needs " + needs_text(input) + ")";
        continue;
      }
      if (!input.colour_only && effect.enabled) {
        bridge->say(0, effect.id + " off: needs " + needs_text(input) + ", which an application's frame cannot give");
        effect.enabled = false;
      }
      kept.push_back(effect);
    }
  }
  recipe->effects = kept;
  if (!left_out.empty())
    bridge->say(0, "left out of the default chain, as an application's frame cannot give what they need: " + left_out);
  return true;
}

}  // namespace pfx::vk
