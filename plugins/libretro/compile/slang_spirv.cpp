#include "slang_spirv.hpp"

#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace pfx::libretro {
namespace {

// glslang's built-in symbol tables, made once per library that links it (no symbol of glslang is
// exported, so another user of glslang in the process keeps its own).
std::mutex tables_mutex;
bool tables_ready = false;

}  // namespace

void release_slang_compiler() {
  std::lock_guard<std::mutex> lock(tables_mutex);
  if (tables_ready) glslang::FinalizeProcess();
  tables_ready = false;
}

bool compile_slang_stage(const std::string& code, SlangStage stage, std::vector<std::uint32_t>* words,
                         std::string* log) {
  {
    std::lock_guard<std::mutex> lock(tables_mutex);
    if (!tables_ready) tables_ready = glslang::InitializeProcess();
  }
  const EShLanguage language = stage == SlangStage::kVertex ? EShLangVertex : EShLangFragment;
  glslang::TShader shader(language);
  const char* text = code.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) return *log = shader.getInfoLog(), false;
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return *log = program.getInfoLog(), false;
  words->clear();
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(language), *words, &logger);
  *log = logger.getAllMessages();
  return !words->empty();
}

}  // namespace pfx::libretro
