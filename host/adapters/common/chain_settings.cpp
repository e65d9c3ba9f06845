#include "chain_settings.hpp"

#include <optional>

#include "cli_text.hpp"

namespace pfx::adapters {
namespace {

std::string trimmed(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

}  // namespace

std::vector<std::string> split_assignments(const std::string& text) {
  std::vector<std::string> items;
  for (const auto& item : app::split_list(text, ';')) {
    std::string assignment = trimmed(item);
    if (!assignment.empty()) items.push_back(assignment);
  }
  return items;
}

bool resolve_chain_settings(const ChainSettings& settings, const host::PluginRegistry& registry,
                            app::Transfer* transfer, app::ChainRecipe* recipe, std::string* error,
                            std::vector<app::RecipeProblem>* left_out) {
  // Empty is the default: ffmpeg's filter_params give every parameter before the last one named.
  const std::string transfer_text = trimmed(settings.transfer);
  if (!app::parse_transfer(transfer_text.empty() ? "srgb" : transfer_text, transfer, error)) return false;
  std::optional<std::vector<std::string>> chain;
  const std::string chain_text = trimmed(settings.chain);
  if (chain_text == "none") {
    chain.emplace();
  } else if (!chain_text.empty()) {
    chain.emplace();
    for (const auto& id : app::split_list(chain_text)) chain->push_back(trimmed(id));
  }
  // What a user typed into the chain or set field that does not apply is an error, and the filter
  // passes frames through saying why; what a preset holds that does not apply is left out with
  // one warning, as every host does.
  std::vector<app::RecipeProblem> problems;
  std::vector<std::string> notes;
  auto recipe_for = [&](const std::optional<std::vector<std::string>>& ids) {
    problems.clear();
    notes.clear();
    return app::make_chain_recipe(trimmed(settings.preset), ids, split_assignments(settings.set), registry,
                                  app::WithoutChain::NO_EFFECT, &problems, &notes);
  };
  *recipe = recipe_for(chain);
  // Neither the setting nor the preset names a chain: the adapter's default, with the assignments
  // checked against it.
  if (!chain && !recipe->chosen && registry.find_effect(kAdapterDefaultChain))
    *recipe = recipe_for(std::vector<std::string>{kAdapterDefaultChain});
  if (left_out) {
    left_out->insert(left_out->end(), problems.begin(), problems.end());
    return true;
  }
  if (problems.empty()) return true;
  error->clear();
  for (const auto& problem : describe_problems(problems)) *error += (error->empty() ? "" : "; ") + problem;
  return false;
}

std::vector<std::string> describe_problems(const std::vector<app::RecipeProblem>& problems) {
  std::vector<std::string> described;
  for (const auto& problem : problems) {
    const char* origin = problem.source == app::RecipeProblem::CHAIN ? "chain" :
                         problem.source == app::RecipeProblem::PRESET ? "preset" : "set";
    described.push_back(std::string(origin) + ": " + problem.message);
  }
  return described;
}

}  // namespace pfx::adapters
