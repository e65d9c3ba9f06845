#include "chain_recipe.hpp"

namespace pfx::inject {

bool make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry, ChainRecipe* out,
                 std::string* error) {
  return app::make_chain_recipe(settings.preset, settings.chain, settings.sets, registry,
                                app::WithoutChain::DEFAULT_CHAIN, out, error);
}

}  // namespace pfx::inject
