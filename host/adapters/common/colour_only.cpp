#include "colour_only.hpp"

#include <algorithm>

#include <pfx/host/param_store.hpp>

#include "camera_options.hpp"
#include "frame_description.hpp"

namespace pfx::adapters {
namespace {

// The frame a renderer with every buffer would give (all inputs there, linear depth), and the one
// an application's picture or a video gives: colour alone.
pfx_frame full_frame() {
  return app::describe_frame(64, 48, app::kEveryInput, PFX_DEPTH_LINEAR, app::make_camera(app::CameraOptions{}, 64, 48));
}

pfx_frame colour_frame() {
  return app::describe_frame(64, 48, PFX_INPUT_COLOR, PFX_DEPTH_NONE, app::make_camera(app::CameraOptions{}, 64, 48));
}

void add_need(std::vector<std::string>* needs, const std::string& name) {
  if (std::find(needs->begin(), needs->end(), name) == needs->end()) needs->push_back(name);
}

// Declares the instance for `frame`; on success, the inputs other than colour (and the effect's own
// targets) that the declaration asks for go to `needs`.
bool declare_for(const host::EffectInfo& effect, void* instance, const std::vector<pfx_value>& values,
                 const pfx_frame& frame, std::vector<std::string>* needs) {
  pfx_declaration declaration{};
  declaration.struct_size = sizeof declaration;
  // An effect without parameters still gets a valid pointer, as libpfxhost hands it one.
  static const pfx_value none{};
  if (effect.desc->declare(instance, &frame, values.empty() ? &none : values.data(), &declaration) != PFX_OK) return false;
  std::vector<std::string> targets;
  for (uint32_t t = 0; t < declaration.target_count; ++t) targets.push_back(declaration.targets[t].name);
  for (uint32_t p = 0; p < declaration.pass_count; ++p)
    for (uint32_t i = 0; i < declaration.passes[p].input_count; ++i) {
      const std::string name = declaration.passes[p].inputs[i].name;
      if (name != PFX_INPUT_NAME_COLOR && std::find(targets.begin(), targets.end(), name) == targets.end())
        add_need(needs, name);
    }
  const struct {
    uint32_t bit;
    const char* name;
  } bits[] = {{PFX_INPUT_DEPTH, "depth"}, {PFX_INPUT_NORMAL, "normal"}, {PFX_INPUT_ALBEDO, "albedo"},
              {PFX_INPUT_EMISSIVE, "emissive"}, {PFX_INPUT_LIGHTS, "lights"}};
  for (const auto& bit : bits)
    if (declaration.inputs & bit.bit) add_need(needs, bit.name);
  return true;
}

// An effect runs on colour alone when, offered colour alone, it declares and asks for nothing
// more; one that reads depth only where a frame has it (a ReShade FX effect reads the far plane
// then) is one of them, as it runs the same in every host. The others are named by what they ask
// of a frame that offers everything.
EffectInputs classify(const host::EffectInfo& effect) {
  EffectInputs result;
  result.id = effect.desc->id;
  // The effect's promise (ABI 1.9) answers without an instance, whose create may compile programs;
  // the registry's copy of the descriptor has flags 0 for a plugin older than the field.
  if (effect.desc->flags & PFX_EFFECT_COLOR_ONLY) {
    result.colour_only = true;
    return result;
  }
  void* instance = nullptr;
  if (effect.desc->create(effect.plugin->host, &instance) != PFX_OK || !instance) {
    result.error = "create failed";
    return result;
  }
  std::vector<pfx_value> values;
  for (uint32_t i = 0; i < effect.desc->param_count; ++i)
    values.push_back(host::default_for(effect.desc->params[i], host::DefaultSet::DISPLAY_REFERRED));
  std::vector<std::string> colour_needs;
  if (declare_for(effect, instance, values, colour_frame(), &colour_needs) && colour_needs.empty()) {
    result.colour_only = true;
  } else if (!declare_for(effect, instance, values, full_frame(), &result.needs)) {
    result.error = "declare failed";
  } else {
    result.colour_only = result.needs.empty();
  }
  effect.desc->destroy(instance);
  return result;
}

}  // namespace

std::vector<EffectInputs> classify_effects(const host::PluginRegistry& registry) {
  std::vector<EffectInputs> results;
  for (const auto& effect : registry.effects()) results.push_back(classify(effect));
  return results;
}

}  // namespace pfx::adapters
