#include "render_chain.hpp"

#include <cstdio>

#include "chain_builder.hpp"
#include "default_chain.hpp"
#include "exit_codes.hpp"
#include "timing_choice.hpp"

namespace pfx::app {

RenderChain::RenderChain(const host::PluginRegistry& registry, const RenderOptions& options,
                         const std::string& gl_renderer)
    : registry_(registry),
      params_(uses_display_defaults(options) ? host::DefaultSet::DISPLAY_REFERRED : host::DefaultSet::SCENE_REFERRED),
      chain_(registry, params_) {
  for (const auto& effect : registry.effects()) params_.add_effect(effect.desc);
  host::Timing timing = host::Timing::OFF;
  parse_timing(options.timing, gl_renderer, &timing);  // the name was checked with the options
  chain_.set_timing(timing);
}

int RenderChain::build(const RenderOptions& options, Preset preset, std::string* message) {
  // The preset policy every host shares (chain_builder.hpp): what is not loaded or does not fit
  // is named in one warning, and the rest runs.
  const std::vector<std::string> unloaded = options.chain_given ? std::vector<std::string>{} : drop_unloaded_effects(preset, registry_);
  std::vector<PresetEffect> effects;
  if (options.chain_given || !preset.chain)
    for (const auto& id : options.chain_given ? options.chain : default_chain(registry_)) effects.push_back({id, true});
  else
    effects = *preset.chain;
  for (const auto& effect : effects) {
    if (!chain_.add(effect.id, message)) return exit_code::kEffectError;
    chain_.set_enabled(chain_.size() - 1, effect.enabled);
  }
  if (!chain_.set_source_definitions(preset.source_definitions, message)) {
    *message = options.preset + ": PreprocessorDefinitions: " + *message;
    return exit_code::kBadInput;
  }
  // Values after the chain: "bloom#2" exists once the chain holds a second bloom.
  const std::string warning = preset_left_out_warning(options.preset, unloaded, apply_preset_values(params_, preset));
  if (!warning.empty() && options.strict) {
    *message = warning + " (--strict)";
    return exit_code::kBadInput;
  }
  if (!warning.empty()) std::fprintf(stderr, "pfx-render: warning: %s\n", warning.c_str());
  for (const auto& note : preset.notes) std::fprintf(stderr, "pfx-render: note: %s: %s\n", options.preset.c_str(), note.c_str());
  for (const auto& assignment : options.sets) {
    std::string note;
    if (!params_.set_assignment(assignment, message, &note)) {
      *message = "--set " + *message;
      return exit_code::kUsage;
    }
    if (!note.empty()) std::fprintf(stderr, "pfx-render: warning: --set %s: %s\n", assignment.c_str(), note.c_str());
  }
  return exit_code::kOk;
}

}  // namespace pfx::app
