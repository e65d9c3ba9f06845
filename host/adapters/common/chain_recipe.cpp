#include "chain_recipe.hpp"

namespace pfx::inject {

ChainRecipe make_recipe(const InjectSettings& settings, const host::PluginRegistry& registry,
                        std::vector<RecipeProblem>* problems, std::vector<std::string>* notes) {
  return app::make_chain_recipe(settings.preset, settings.chain, settings.sets, registry,
                                app::WithoutChain::DEFAULT_CHAIN, problems, notes);
}

}  // namespace pfx::inject
