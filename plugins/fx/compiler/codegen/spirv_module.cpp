#include "spirv_module.hpp"

#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace pfx::fx {

namespace {

// glslang's tables (its built-in symbols, some 12 MB), made at the first compile. They live in the
// library glslang is linked into (a plugin exports none of glslang's symbols, so no other user of
// glslang in the process shares them), and release_spirv_compiler frees them before it unloads.
std::mutex glslang_mutex;
bool glslang_ready = false;

}  // namespace

void release_spirv_compiler() {
  std::lock_guard<std::mutex> lock(glslang_mutex);
  if (!glslang_ready) return;
  glslang::FinalizeProcess();
  glslang_ready = false;
}

bool compile_spirv(const std::string& vulkan_glsl, SpirvStage stage, std::vector<std::uint32_t>& words, std::string& log) {
  {
    std::lock_guard<std::mutex> lock(glslang_mutex);
    if (!glslang_ready) glslang_ready = glslang::InitializeProcess();
  }
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
