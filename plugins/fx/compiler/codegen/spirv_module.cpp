#include "spirv_module.hpp"

#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace pfx::fx {

bool compile_spirv(const std::string& vulkan_glsl, SpirvStage stage, std::vector<std::uint32_t>& words, std::string& log) {
  // glslang's process-wide tables, set up once and kept: finalising them would break any other
  // user of glslang in the host's process.
  static std::once_flag initialised;
  std::call_once(initialised, [] { glslang::InitializeProcess(); });
  const EShLanguage language = stage == SpirvStage::kVertex ? EShLangVertex : stage == SpirvStage::kFragment ? EShLangFragment : EShLangCompute;
  glslang::TShader shader(language);
  const char* text = vulkan_glsl.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
    log = shader.getInfoLog();
    return false;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    log = program.getInfoLog();
    return false;
  }
  words.clear();
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.validate = false;  // spirv-val judges the modules in the tests
  glslang::GlslangToSpv(*program.getIntermediate(language), words, &logger, &options);
  log = logger.getAllMessages();
  return !words.empty();
}

}  // namespace pfx::fx
