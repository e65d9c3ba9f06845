#include "native_chain.hpp"

#include <algorithm>
#include <map>

#include <pfx/cpp/definitions_list.hpp>

#include "frame_chain.hpp"

namespace pfx::vk {
namespace {

// The plugin's Vulkan factory when it has a usable one and it runs `effect_id`; else null.
const pfx_vulkan_effect_factory* factory_for(const host::PluginRegistry& registry, const std::string& effect_id,
                                             const pfx_host** host) {
  const host::EffectInfo* effect = registry.find_effect(effect_id);
  if (!effect || !effect->plugin || !effect->plugin->get_factory) return nullptr;
  const auto* factory = static_cast<const pfx_vulkan_effect_factory*>(
      effect->plugin->get_factory(PFX_VULKAN_EFFECTS_FACTORY_ID));
  if (!factory || factory->struct_size < PFX_VULKAN_EFFECT_FACTORY_MIN_SIZE || !factory->supports || !factory->create ||
      !factory->record || !factory->destroy || factory->supports(effect_id.c_str()) != 1)
    return nullptr;
  if (host) *host = effect->plugin->host;
  return factory;
}

// Whether `factory` makes instances with preprocessor definitions (since ABI 1.8).
bool takes_definitions(const pfx_vulkan_effect_factory& factory) {
  return PFX_STRUCT_HAS(&factory, pfx_vulkan_effect_factory, create_with_definitions) &&
         factory.create_with_definitions != nullptr;
}

}  // namespace

bool NativeChain::takes(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, std::string* why) {
  for (const auto& effect : recipe.effects) {
    const pfx_vulkan_effect_factory* factory = factory_for(registry, effect.id, nullptr);
    if (!factory) {
      *why = effect.id + " runs on OpenGL only";
      return false;
    }
    if (!recipe.source_definitions.empty() && !takes_definitions(*factory)) {
      *why = "the preset sets preprocessor definitions, which " + effect.id + " takes on OpenGL only";
      return false;
    }
  }
  return true;
}

bool NativeChain::set_recipe(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                             const std::function<void()>& idle, std::string* error) {
  // A malformed list is refused here, as the GL path's chain refuses it.
  Definitions definitions;
  if (!parse_definitions(recipe.source_definitions, &definitions, error)) {
    *error = "preset PreprocessorDefinitions: " + *error;
    return false;
  }
  std::vector<Effect> fresh;
  if (!effects_of(registry, recipe, &fresh, error)) return false;
  bool same_effects = fresh.size() == effects_.size();
  for (size_t i = 0; same_effects && i < fresh.size(); ++i) same_effects = fresh[i].id == effects_[i].id;
  if (same_effects && recipe.source_definitions == definitions_) {
    effects_ = std::move(fresh);
    return true;
  }
  // Other effects, or other definitions (an instance keeps those it was made with): every
  // instance is made anew. For the sizes frames have run at, that happens now, so that an effect
  // that cannot be made (a file that does not compile with the new definitions) leaves the chain
  // running as it was, as the GL path keeps the last version that compiled.
  std::vector<Instances> made;
  for (const Instances& old : sizes_) {
    made.push_back({old.width, old.height, old.format, {}, old.last_used});
    if (!make_missing(fresh, recipe.source_definitions, made.back(), error)) {
      for (Instances& instances : made) destroy(fresh, instances);
      return false;
    }
  }
  idle();
  destroy_instances();
  effects_ = std::move(fresh);
  definitions_ = recipe.source_definitions;
  sizes_ = std::move(made);
  return true;
}

bool NativeChain::effects_of(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                             std::vector<Effect>* effects, std::string* error) {
  host::ParamStore store = app::store_for(recipe.effects, registry);
  if (!app::apply_recipe_values(recipe, &store, error, nullptr, "set")) return false;
  std::map<std::string, size_t> numbers;
  for (const auto& wanted : recipe.effects) {
    Effect effect;
    effect.id = wanted.id;
    const size_t number = ++numbers[wanted.id];
    effect.name = host::ParamStore::instance_name(wanted.id, number);
    effect.enabled = wanted.enabled;
    effect.factory = factory_for(registry, wanted.id, &effect.host);
    const pfx_effect_desc* desc = store.effect_descriptor(wanted.id);
    const pfx_value* values = store.values(wanted.id, number);
    if (!effect.factory || !desc || (desc->param_count && !values)) {
      *error = "effect '" + wanted.id + "' cannot run on Vulkan";
      return false;
    }
    if (values) effect.values.assign(values, values + desc->param_count);
    effects->push_back(std::move(effect));
  }
  return true;
}

std::string NativeChain::text() const {
  std::string text;
  for (const auto& effect : effects_)
    text += (text.empty() ? "" : ",") + effect.name + (effect.enabled ? "" : " (off)");
  return text.empty() ? "none" : text;
}

bool NativeChain::runs_effects() const {
  for (const auto& effect : effects_)
    if (effect.enabled) return true;
  return false;
}

void NativeChain::destroy(const std::vector<Effect>& effects, Instances& instances) {
  for (size_t i = 0; i < instances.of_effect.size(); ++i)
    if (instances.of_effect[i]) effects[i].factory->destroy(instances.of_effect[i]);
  instances.of_effect.clear();
}

void NativeChain::destroy_instances() {
  for (auto& instances : sizes_) destroy(effects_, instances);
  sizes_.clear();
  current_ = nullptr;
}

bool NativeChain::prepare(const pfx_vk_device& device, uint32_t width, uint32_t height, VkFormat format,
                          const std::function<void()>& idle, std::string* error) {
  device_ = device;
  current_ = nullptr;
  for (auto& instances : sizes_)
    if (instances.width == width && instances.height == height && instances.format == format) current_ = &instances;
  if (!current_) {
    if (sizes_.size() == kSizes) {
      auto oldest = std::min_element(sizes_.begin(), sizes_.end(),
                                     [](const Instances& a, const Instances& b) { return a.last_used < b.last_used; });
      idle();
      destroy(effects_, *oldest);
      sizes_.erase(oldest);
    }
    sizes_.push_back({width, height, format, {}, 0});
    current_ = &sizes_.back();
  }
  current_->last_used = ++uses_;
  return make_missing(effects_, definitions_, *current_, error);
}

bool NativeChain::make_missing(const std::vector<Effect>& effects, const std::string& definitions, Instances& instances,
                               std::string* error) const {
  instances.of_effect.resize(effects.size(), nullptr);
  for (size_t i = 0; i < effects.size(); ++i) {
    const Effect& effect = effects[i];
    if (!effect.enabled || instances.of_effect[i]) continue;
    char message[1024] = "";
    void* made = nullptr;
    const pfx_status status =
        definitions.empty()
            ? effect.factory->create(effect.host, effect.id.c_str(), &device_, instances.width, instances.height,
                                     instances.format, &made, message, sizeof message)
            : effect.factory->create_with_definitions(effect.host, effect.id.c_str(), &device_, instances.width,
                                                      instances.height, instances.format, definitions.c_str(), &made,
                                                      message, sizeof message);
    if (status != PFX_OK) {
      *error = "effect '" + effect.id + "' could not be made on Vulkan: " + (*message ? message : "no reason given");
      return false;
    }
    instances.of_effect[i] = made;
  }
  return true;
}

bool NativeChain::record(VkCommandBuffer commands, VkImage image, VkImageLayout layout, bool alpha_unused,
                         double time_seconds, uint64_t frame_index, std::string* error) {
  const pfx_frame frame = adapters::describe_video_frame(int(current_->width), int(current_->height), time_seconds,
                                                         frame_index);
  pfx_vk_frame_image target{};
  target.struct_size = sizeof target;
  target.image = image;
  target.layout = layout;
  target.final_layout = layout;
  target.flags = alpha_unused ? uint32_t(PFX_VK_FRAME_ALPHA_UNUSED) : 0u;
  for (size_t i = 0; i < effects_.size(); ++i) {
    const Effect& effect = effects_[i];
    if (!effect.enabled) continue;
    const pfx_value* values = effect.values.empty() ? nullptr : effect.values.data();
    const pfx_status status = effect.factory->record(current_->of_effect[i], commands, &target, &frame, values);
    if (status != PFX_OK) {
      *error = "effect '" + effect.id + "' failed to record its passes (status " + std::to_string(int(status)) + ")";
      return false;
    }
  }
  return true;
}

}  // namespace pfx::vk
