#include "lr_passes.hpp"

#include <pfx/cpp/gl_program.hpp>

#include "glsl_source.hpp"
#include "slang_spirv.hpp"

namespace pfx_libretro {

using namespace pfx::libretro;

bool compile_passes(const LrEffectEntry& entry, std::vector<LrPass>* passes, std::string* error) {
  const Preset& preset = entry.preset;
  if (preset.format == PresetFormat::kGlsl) {
    passes->assign(preset.passes.size(), LrPass{});
    for (std::size_t i = 0; i < preset.passes.size(); ++i) {
      SlangSource source;
      if (!read_glsl(preset.passes[i].shader, read_text_file, &source, error)) return false;
      LrPass& pass = (*passes)[i];
      pass.glsl = true;
      pass.code.vertex = std::move(source.vertex);
      pass.code.fragment = std::move(source.fragment);
    }
    return true;
  }
  std::vector<SlangSource> sources(preset.passes.size());
  SemanticContext context;
  for (std::size_t i = 0; i < preset.passes.size(); ++i) {
    if (!read_slang(preset.passes[i].shader, read_text_file, &sources[i], error)) return false;
    context.aliases.push_back(preset.passes[i].alias.empty() ? sources[i].name : preset.passes[i].alias);
  }
  for (const LookupTexture& texture : preset.textures) context.textures.push_back(texture.id);
  context.parameters = entry.params.shader_ids;
  passes->assign(preset.passes.size(), LrPass{});
  for (std::size_t i = 0; i < preset.passes.size(); ++i) {
    LrPass& pass = (*passes)[i];
    pass.name = sources[i].name;
    pass.format = sources[i].format;
    std::vector<std::uint32_t> vertex, fragment;
    std::string log;
    if (!compile_slang_stage(sources[i].vertex, SlangStage::kVertex, &vertex, &log) ||
        !compile_slang_stage(sources[i].fragment, SlangStage::kFragment, &fragment, &log)) {
      *error = "pass " + std::to_string(i) + " (" + preset.passes[i].shader + ") does not compile:\n" + log;
      return false;
    }
    context.pass = static_cast<int>(i);
    if (!reflect_slang_pass(vertex, fragment, context, &pass.reads, error) ||
        !slang_pass_for_gl(vertex, fragment, pass.reads, &pass.code, error)) {
      *error = "pass " + std::to_string(i) + " (" + preset.passes[i].shader + "): " + *error;
      return false;
    }
  }
  return true;
}

namespace {

// After the `#version` line: gl_FragCoord counted from the top, as in Vulkan.
std::string with_upper_left_origin(const std::string& code) {
  const std::size_t end = code.find('\n');
  if (end == std::string::npos) return code;
  return code.substr(0, end + 1) + "layout(origin_upper_left) in vec4 gl_FragCoord;\n" + code.substr(end + 1);
}

GLuint block_buffer(const ReflectedBlock& block, std::vector<unsigned char>* bytes) {
  if (!block.present || block.size == 0) return 0;
  bytes->assign(block.size, 0);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, block.size, bytes->data(), GL_DYNAMIC_STORAGE_BIT);
  return buffer;
}

}  // namespace

pfx::gl::ProgramCache libretro_program_cache() {
  // The version is the plugin's: a program's GLSL is what SPIRV-Cross wrote or the shader's own,
  // so the key changes with it; the version guards what the plugin adds around it.
  return pfx::gl::ProgramCache("libretro-programs", "PFX_LIBRETRO_CACHE", "0.1.0", 256ull << 20);
}

bool build_pass_programs(std::vector<LrPass>& passes, bool last_to_output, const pfx::gl::ProgramCache& cache,
                         int* from_cache, std::string* error) {
  for (std::size_t i = 0; i < passes.size(); ++i) {
    LrPass& pass = passes[i];
    if (pass.glsl) continue;  // linked by link_glsl_passes
    const std::string fragment = last_to_output && i + 1 == passes.size() ? with_upper_left_origin(pass.code.fragment)
                                                                          : pass.code.fragment;
    const GLenum stages[] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    const char* sources[] = {pass.code.vertex.c_str(), fragment.c_str()};
    bool cached = false;
    pass.program = cache.build(stages, sources, 2, error, &cached);
    *from_cache += cached ? 1 : 0;
    if (!pass.program) {
      *error = "pass " + std::to_string(i) + ": the GL code SPIRV-Cross wrote does not build: " + *error;
      return false;
    }
    pass.uniform_buffer = block_buffer(pass.reads.uniforms, &pass.uniform_bytes);
    pass.push_buffer = block_buffer(pass.reads.push, &pass.push_bytes);
  }
  return true;
}

void release_pass_programs(std::vector<LrPass>& passes) {
  for (LrPass& pass : passes) {
    if (pass.program) glDeleteProgram(pass.program);
    if (pass.uniform_buffer) glDeleteBuffers(1, &pass.uniform_buffer);
    if (pass.push_buffer) glDeleteBuffers(1, &pass.push_buffer);
    if (pass.glsl_vao) glDeleteVertexArrays(1, &pass.glsl_vao);
    pass = LrPass{};
  }
}

}  // namespace pfx_libretro
