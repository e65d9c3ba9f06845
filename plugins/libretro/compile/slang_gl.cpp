#include "slang_gl.hpp"

#include <spirv_cross/spirv_cross_c.h>

namespace pfx::libretro {
namespace {

void on_error(void* error, const char* message) {
  *static_cast<std::string*>(error) = std::string("SPIRV-Cross: ") + message;
}

bool stage_for_gl(const std::vector<std::uint32_t>& words, std::uint32_t push_binding, std::string* code,
                  std::string* error) {
  spvc_context context = nullptr;
  if (spvc_context_create(&context) != SPVC_SUCCESS) return *error = "SPIRV-Cross: no context", false;
  spvc_context_set_error_callback(context, on_error, error);
  spvc_parsed_ir ir = nullptr;
  spvc_compiler compiler = nullptr;
  spvc_compiler_options options = nullptr;
  const char* text = nullptr;
  bool made = spvc_context_parse_spirv(context, words.data(), words.size(), &ir) == SPVC_SUCCESS &&
              spvc_context_create_compiler(context, SPVC_BACKEND_GLSL, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                           &compiler) == SPVC_SUCCESS &&
              spvc_compiler_create_compiler_options(compiler, &options) == SPVC_SUCCESS;
  if (made) {
    spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_GLSL_VERSION, 450);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_ES, SPVC_FALSE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_VULKAN_SEMANTICS, SPVC_FALSE);
    spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_GLSL_EMIT_PUSH_CONSTANT_AS_UNIFORM_BUFFER, SPVC_TRUE);
    spvc_resources resources = nullptr;
    const spvc_reflected_resource* push = nullptr;
    std::size_t push_count = 0;
    made = spvc_compiler_install_compiler_options(compiler, options) == SPVC_SUCCESS &&
           spvc_compiler_create_shader_resources(compiler, &resources) == SPVC_SUCCESS &&
           spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &push, &push_count) ==
               SPVC_SUCCESS;
    for (std::size_t i = 0; made && i < push_count; ++i)
      spvc_compiler_set_decoration(compiler, push[i].id, SpvDecorationBinding, push_binding);
    made = made && spvc_compiler_compile(compiler, &text) == SPVC_SUCCESS;
  }
  if (made) *code = text;
  spvc_context_destroy(context);
  return made;
}

}  // namespace

bool slang_pass_for_gl(const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& fragment,
                       const PassInterface& pass, GlPassCode* out, std::string* error) {
  // The first binding the uniform block leaves free.
  out->push_binding = pass.uniforms.present && pass.uniforms.binding == 0 ? 1 : 0;
  return stage_for_gl(vertex, out->push_binding, &out->vertex, error) &&
         stage_for_gl(fragment, out->push_binding, &out->fragment, error);
}

}  // namespace pfx::libretro
