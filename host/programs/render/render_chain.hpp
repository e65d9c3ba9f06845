// The chain pfx-render runs and the parameter store its instances read: the effects of --chain,
// else of the preset, else the default chain; then the preset's values, then each --set.
#pragma once

#include <string>

#include <pfx/host/chain.hpp>
#include <pfx/host/param_store.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "preset.hpp"
#include "render_options.hpp"

namespace pfx::app {

class RenderChain {
 public:
  // An empty chain, timed as --timing says. Values start from the display-referred defaults for
  // an 8-bit input (bloom's threshold below 1), the scene-referred ones otherwise (--defaults
  // decides when given).
  RenderChain(const host::PluginRegistry& registry, const RenderOptions& options, const std::string& gl_renderer);

  // Adds the effects and sets their values; what of the preset does not apply is left out with
  // one warning on stderr. kOk, or an exit code (exit_codes.hpp) with *message naming the effect,
  // the preset's definitions or the --set that failed.
  int build(const RenderOptions& options, Preset preset, std::string* message);

  host::Chain& chain() { return chain_; }

 private:
  const host::PluginRegistry& registry_;
  host::ParamStore params_;  // before the chain: its instances read the store
  host::Chain chain_;
};

}  // namespace pfx::app
