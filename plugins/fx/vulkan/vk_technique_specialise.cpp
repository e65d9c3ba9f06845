// Technique::specialise: pipelines with settled uniform values compiled in (vk_technique.hpp).
#include "vk_technique.hpp"

namespace pfx::fx::vulkan {

const Technique::Specialised* Technique::specialised_for(const UniformConstants& constants) const {
  for (const Specialised& set : specialised_)
    if (set.constants == constants) return &set;
  return nullptr;
}

void Technique::destroy(Specialised& set) {
  for (VkPipeline pipeline : set.pipelines)
    if (pipeline) d_->vkDestroyPipeline(d_->device, pipeline, nullptr);
  for (VkShaderModule module : set.modules)
    if (module) d_->vkDestroyShaderModule(d_->device, module, nullptr);
  set = Specialised{};
}

bool Technique::specialise(const CompiledEffect& effect, const UniformConstants& constants, VkPipelineCache cache,
                           bool* built, std::string& message) {
  *built = false;
  if (specialised_for(constants)) return true;
  if (specialised_.size() >= kSpecialisedSets)
    return message = std::to_string(kSpecialisedSets) + " sets of values were compiled in already: new values run live",
           false;
  Specialised set;
  set.constants = constants;
  set.pipelines.assign(passes_.size(), VK_NULL_HANDLE);
  Diagnostics diagnostics(effect.front->names);
  for (std::size_t i = 0; message.empty() && i < passes_.size(); ++i) {
    const Pass& pass = passes_[i];
    const GeneratedPass generated = generate_pass(effect.front->unit, *model_, technique_->passes[i], diagnostics,
                                                  &constants, GlslDialect::kVulkan);
    if (diagnostics.has_errors()) {
      message = "the specialised code did not generate: " + diagnostics.format_all();
      break;
    }
    // The pass's descriptor set and copies were made for its live code: they must serve this too.
    if (generated.sampler_units != pass.sampler_units || generated.image_units != pass.image_units ||
        generated.may_discard != pass.may_discard)
      continue;
    const std::string* sources[2] = {pass.compute ? &generated.compute : &generated.vertex, &generated.fragment};
    const SpirvStage stages[2] = {pass.compute ? SpirvStage::kCompute : SpirvStage::kVertex, SpirvStage::kFragment};
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    for (int stage = 0; message.empty() && stage < (pass.compute ? 1 : 2); ++stage) {
      const std::string log = create_shader_module(*d_, *sources[stage], stages[stage], modules[stage]);
      if (!log.empty()) message = "glslang refused the specialised code: " + log;
      if (modules[stage]) set.modules.push_back(modules[stage]);
    }
    if (!message.empty()) break;
    if (pass.compute) {
      set.pipelines[i] = create_compute_pipeline(*d_, modules[0], pass.layout, cache);
    } else {
      GraphicsPlan plan = pass.plan;
      plan.vertex = modules[0], plan.fragment = modules[1];
      set.pipelines[i] = create_graphics_pipeline(*d_, plan, cache);
    }
    if (!set.pipelines[i]) message = "a specialised pipeline could not be made";
  }
  if (!message.empty()) {
    destroy(set);
    return false;
  }
  specialised_.push_back(std::move(set));
  *built = true;
  return true;
}

}  // namespace pfx::fx::vulkan
