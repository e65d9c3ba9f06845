// A slang pass compiled (compile/): SPIR-V from glslang, what it reads from SPIRV-Cross's
// reflection, and its GLSL for GL, which llvmpipe compiles and runs: the driver's own
// introspection and a drawn picture are the references.
#include <catch2/catch.hpp>

#include <glad/gl.h>

#include "headless_context.hpp"
#include "memory_files.hpp"
#include "slang_gl.hpp"
#include "slang_reflection.hpp"
#include "slang_source.hpp"
#include "slang_spirv.hpp"

using namespace pfx::libretro;
using pfx::test::MemoryFiles;

namespace {

// Darkens its source by the parameter `amount`; the sizes and frame count in push constants.
const char* const kPass =
    "#version 450\n"
    "#pragma parameter amount \"Darken by\" 0.25 0.0 1.0 0.05\n"
    "layout(std140, set = 0, binding = 0) uniform UBO { mat4 MVP; float amount; vec4 unused_but_named; } global;\n"
    "layout(push_constant) uniform Push { vec4 SourceSize; uint FrameCount; vec4 OutputSize; } params;\n"
    "#pragma stage vertex\n"
    "layout(location = 0) in vec4 Position;\n"
    "layout(location = 1) in vec2 TexCoord;\n"
    "layout(location = 0) out vec2 vTexCoord;\n"
    "void main() { gl_Position = global.MVP * Position; vTexCoord = TexCoord * params.SourceSize.xy * "
    "params.SourceSize.zw; }\n"
    "#pragma stage fragment\n"
    "layout(location = 0) in vec2 vTexCoord;\n"
    "layout(location = 0) out vec4 FragColor;\n"
    "layout(set = 0, binding = 2) uniform sampler2D Source;\n"
    "layout(set = 0, binding = 3) uniform sampler2D PassFeedback0;\n"
    "void main() {\n"
    "  vec4 c = texture(Source, vTexCoord) + 0.0 * texture(PassFeedback0, vTexCoord) * float(params.FrameCount);\n"
    "  FragColor = vec4(c.rgb * (1.0 - global.amount), c.a);\n"
    "}\n";

struct Compiled {
  std::vector<std::uint32_t> vertex, fragment;
  PassInterface pass;
};

SemanticContext one_pass(const std::vector<std::string>& parameters) {
  SemanticContext context;
  context.pass = 0;
  context.aliases = {""};
  context.parameters = parameters;
  return context;
}

// The pass's stages and interface; "" or the first error, as the runtime would report it.
std::string compile(const std::string& text, const SemanticContext& context, Compiled* out) {
  MemoryFiles files;
  files.texts["/s/pass.slang"] = text;
  SlangSource source;
  std::string error;
  if (!read_slang("/s/pass.slang", files.reader(), &source, &error)) return error;
  if (!compile_slang_stage(source.vertex, SlangStage::kVertex, &out->vertex, &error)) return error;
  if (!compile_slang_stage(source.fragment, SlangStage::kFragment, &out->fragment, &error)) return error;
  if (!reflect_slang_pass(out->vertex, out->fragment, context, &out->pass, &error)) return error;
  return "";
}

const ReflectedMember* member(const ReflectedBlock& block, const std::string& name) {
  for (const ReflectedMember& m : block.members)
    if (m.name == name) return &m;
  return nullptr;
}

GLuint gl_stage(GLenum kind, const std::string& code) {
  const GLuint shader = glCreateShader(kind);
  const char* text = code.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  char log[4096] = "";
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  INFO(code << "\n" << log);
  REQUIRE(ok);
  return shader;
}

}  // namespace

TEST_CASE("slang passes: the reflection finds each member the pass reads, its offset and what it stands for",
          "[compile]") {
  Compiled compiled;
  REQUIRE(compile(kPass, one_pass({"amount"}), &compiled).empty());
  const PassInterface& pass = compiled.pass;
  REQUIRE(pass.uniforms.present);
  CHECK(pass.uniforms.binding == 0);
  CHECK(pass.uniforms.size == 96);  // std140: mat4 64, float at 64, vec4 at 80
  const ReflectedMember* mvp = member(pass.uniforms, "MVP");
  const ReflectedMember* amount = member(pass.uniforms, "amount");
  REQUIRE(mvp);
  REQUIRE(amount);
  CHECK(mvp->offset == 0);
  CHECK(mvp->semantic.kind == SemanticKind::kMvp);
  CHECK(amount->offset == 64);
  CHECK(amount->semantic.kind == SemanticKind::kParameter);
  CHECK(amount->semantic.index == 0);
  // Not read by the pass: not looked up, as RetroArch looks up only what a pass reads.
  CHECK_FALSE(member(pass.uniforms, "unused_but_named"));
  REQUIRE(pass.push.present);
  CHECK(member(pass.push, "SourceSize")->offset == 0);
  CHECK(member(pass.push, "FrameCount")->offset == 16);
  CHECK(member(pass.push, "FrameCount")->semantic.kind == SemanticKind::kFrameCount);
  CHECK_FALSE(member(pass.push, "OutputSize"));
  REQUIRE(pass.samplers.size() == 2);
  for (const ReflectedSampler& sampler : pass.samplers) {
    if (sampler.name == "Source") {
      CHECK(sampler.binding == 2);
      CHECK(sampler.semantic.kind == SemanticKind::kSource);
    } else {
      CHECK(sampler.name == "PassFeedback0");
      CHECK(sampler.binding == 3);
      CHECK(sampler.semantic.kind == SemanticKind::kPassFeedback);
      CHECK(sampler.semantic.index == 0);
    }
  }
}

TEST_CASE(
    "slang passes: names the format does not know, values of the wrong type and reads of later passes are refused",
    "[compile][bad]") {
  Compiled compiled;
  CHECK(compile(kPass, one_pass({}), &compiled) ==
        "uniform block member 'amount' is not a name the slang format gives a value (a built-in, a parameter, a pass's "
        "alias or a "
        "lookup texture)");
  std::string text = kPass;
  text.replace(text.find("uint FrameCount"), 15, "float FrameCount");
  CHECK(compile(text, one_pass({"amount"}), &compiled) == "push constant block member 'FrameCount' must be a uint");
  text = kPass;
  text.replace(text.find("PassFeedback0;"), 14, "PassOutput0;");
  text.replace(text.find("texture(PassFeedback0"), 21, "texture(PassOutput0");
  CHECK(compile(text, one_pass({"amount"}), &compiled) ==
        "sampler 'PassOutput0' reads pass 0, which has not run when pass 0 runs (PassFeedback0 is its last frame's "
        "output)");
  text = kPass;
  text.replace(text.find("1.0 - global.amount"), 19, "1.0 - global.amount + nothing_here");
  const std::string error = compile(text, one_pass({"amount"}), &compiled);
  INFO(error);
  CHECK(error.find("/s/pass.slang:17") != std::string::npos);
  CHECK(error.find("nothing_here") != std::string::npos);
}

TEST_CASE(
    "slang passes: the GLSL made for GL has the blocks and samplers where the reflection says, and draws the pass",
    "[compile][gl]") {
  std::string error;
  auto context = pfx::app::HeadlessContext::create(&error);
  INFO(error);
  REQUIRE(context);
  Compiled compiled;
  REQUIRE(compile(kPass, one_pass({"amount"}), &compiled).empty());
  GlPassCode code;
  REQUIRE(slang_pass_for_gl(compiled.vertex, compiled.fragment, compiled.pass, &code, &error));
  CHECK(code.push_binding == 1);
  const GLuint program = glCreateProgram();
  glAttachShader(program, gl_stage(GL_VERTEX_SHADER, code.vertex));
  glAttachShader(program, gl_stage(GL_FRAGMENT_SHADER, code.fragment));
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  REQUIRE(linked);
  // The driver's view of the two blocks: bindings, and where `amount` and FrameCount are.
  GLint blocks = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
  REQUIRE(blocks == 2);
  std::vector<GLint> bindings;
  for (GLint b = 0; b < blocks; ++b) {
    const GLenum property = GL_BUFFER_BINDING;
    GLint binding = -1;
    glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, GLuint(b), 1, &property, 1, nullptr, &binding);
    bindings.push_back(binding);
  }
  std::sort(bindings.begin(), bindings.end());
  CHECK(bindings == std::vector<GLint>{0, 1});

  // Draw: a 4x4 texture of one colour darkened by amount = 0.25.
  const int size = 4;
  const std::vector<unsigned char> texels(size * size * 4, 200);
  GLuint textures[2], framebuffer_texture, framebuffer, buffers[2], vertex_array;
  glGenTextures(2, textures);
  for (GLuint t : textures) {
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glBindTextureUnit(2, textures[0]);
  glBindTextureUnit(3, textures[1]);
  glCreateTextures(GL_TEXTURE_2D, 1, &framebuffer_texture);
  glTextureStorage2D(framebuffer_texture, 1, GL_RGBA8, size, size);
  glCreateFramebuffers(1, &framebuffer);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, framebuffer_texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size, size);
  // The blocks' bytes at the reflected offsets.
  std::vector<float> ubo(compiled.pass.uniforms.size / 4, 0.0f), push(compiled.pass.push.size / 4, 0.0f);
  for (int i = 0; i < 4; ++i) ubo[i * 5] = 1.0f;  // MVP: identity
  ubo[member(compiled.pass.uniforms, "amount")->offset / 4] = 0.25f;
  const float source_size[4] = {float(size), float(size), 1.0f / size, 1.0f / size};
  std::copy(source_size, source_size + 4, push.begin() + member(compiled.pass.push, "SourceSize")->offset / 4);
  glCreateBuffers(2, buffers);
  glNamedBufferData(buffers[0], GLsizeiptr(ubo.size() * 4), ubo.data(), GL_STATIC_DRAW);
  glNamedBufferData(buffers[1], GLsizeiptr(push.size() * 4), push.data(), GL_STATIC_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, compiled.pass.uniforms.binding, buffers[0]);
  glBindBufferBase(GL_UNIFORM_BUFFER, code.push_binding, buffers[1]);
  // The quad: Position at location 0, TexCoord at 1.
  const float quad[] = {-1, -1, 0, 1, 0, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 1, 0, 1, 1, 1, 0, 1, 1, 1};
  GLuint vertices;
  glCreateBuffers(1, &vertices);
  glNamedBufferData(vertices, sizeof quad, quad, GL_STATIC_DRAW);
  glCreateVertexArrays(1, &vertex_array);
  glVertexArrayVertexBuffer(vertex_array, 0, vertices, 0, 6 * sizeof(float));
  glEnableVertexArrayAttrib(vertex_array, 0);
  glEnableVertexArrayAttrib(vertex_array, 1);
  glVertexArrayAttribFormat(vertex_array, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribFormat(vertex_array, 1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float));
  glVertexArrayAttribBinding(vertex_array, 0, 0);
  glVertexArrayAttribBinding(vertex_array, 1, 0);
  glBindVertexArray(vertex_array);
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  std::vector<unsigned char> drawn(size * size * 4);
  glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, drawn.data());
  CHECK(glGetError() == GL_NO_ERROR);
  // 200 * 0.75 = 150 in colour; alpha as it was.
  for (std::size_t i = 0; i < drawn.size(); i += 4) {
    INFO("pixel " << i / 4);
    CHECK(int(drawn[i]) == 150);
    CHECK(int(drawn[i + 1]) == 150);
    CHECK(int(drawn[i + 2]) == 150);
    CHECK(int(drawn[i + 3]) == 200);
  }
  glDeleteProgram(program);
}
