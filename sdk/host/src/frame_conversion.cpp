#include "frame_conversion.hpp"

#include <pfx/cpp/srgb_glsl.hpp>

namespace pfx::host {
namespace {

// Texel for texel: the target has the source's size, so gl_FragCoord names the source texel.
const char* const kVertexShader =
    "#version 450 core\n"
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
// What a draw does to each texel (Transfer): copies it; encodes linear light into sRGB codes as
// the hosts' transfer programs and FX's back buffer always have (clamped to [0, 1], NaN -> 0: the
// codes a display-referred effect would have seen); decodes codes into linear light.
const char* const kFragmentShaders[] = {
    "void main() { colour = texelFetch(source, ivec2(gl_FragCoord.xy), 0); }\n",
    "void main() {\n"
    "  vec4 v = texelFetch(source, ivec2(gl_FragCoord.xy), 0);\n"
    "  v = clamp(mix(v, vec4(0.0), isnan(v)), 0.0, 1.0);\n"
    "  colour = vec4(pfx_srgb_encode(v.rgb), v.a);\n"
    "}\n",
    "void main() {\n"
    "  vec4 v = texelFetch(source, ivec2(gl_FragCoord.xy), 0);\n"
    "  colour = vec4(pfx_srgb_decode(v.rgb), v.a);\n"
    "}\n"};

std::string fragment_shader(Transfer transfer) {
  return std::string("#version 450 core\n") + pfx::gl::srgb_glsl_functions() +
         "layout(binding = 0) uniform sampler2D source;\n"
         "layout(location = 0) out vec4 colour;\n" +
         kFragmentShaders[static_cast<int>(transfer)];
}

GLuint compile(GLenum stage, const char* source, std::string* log) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char text[512] = {};
    glGetShaderInfoLog(shader, sizeof text, nullptr, text);
    *log = text;
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

bool is_eight_bit_texture(GLuint texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format == GL_RGBA8 || format == GL_SRGB8_ALPHA8;
}

bool samples_as_stored(GLuint texture) {
  GLint swizzle[4] = {};
  glGetTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  return swizzle[0] == GL_RED && swizzle[1] == GL_GREEN && swizzle[2] == GL_BLUE && swizzle[3] == GL_ALPHA;
}

bool framebuffer_draws_srgb(GLuint framebuffer) {
  GLint bound = 0, buffer = GL_NONE;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(bound));
  // The default framebuffer names its buffers by side; an attachment query wants the left one.
  if (buffer == GL_BACK) buffer = GL_BACK_LEFT;
  else if (buffer == GL_FRONT || buffer == GL_FRONT_AND_BACK) buffer = GL_FRONT_LEFT;
  if (buffer == GL_NONE) return false;
  GLint encoding = GL_LINEAR;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, static_cast<GLenum>(buffer),
                                             GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
  return encoding == GL_SRGB;
}

FrameConversion::~FrameConversion() {
  for (Texture* t : {&color_, &output_, &codes_color_, &codes_output_}) release(t);
  for (GLuint program : programs_)
    if (program) glDeleteProgram(program);
  if (target_framebuffer_) glDeleteFramebuffers(1, &target_framebuffer_);
  if (vertex_array_) glDeleteVertexArrays(1, &vertex_array_);
}

void FrameConversion::fit(Texture* t, GLenum format, uint32_t width, uint32_t height) {
  if (t->texture && t->width == width && t->height == height) return;
  release(t);
  glCreateTextures(GL_TEXTURE_2D, 1, &t->texture);
  glTextureStorage2D(t->texture, 1, format, static_cast<GLsizei>(width), static_cast<GLsizei>(height));
  glCreateFramebuffers(1, &t->framebuffer);
  glNamedFramebufferTexture(t->framebuffer, GL_COLOR_ATTACHMENT0, t->texture, 0);
  t->width = width;
  t->height = height;
  t->bytes_per_texel = format == GL_RGBA8 ? 4 : 8;
}

void FrameConversion::release(Texture* t) {
  if (t->texture) glDeleteTextures(1, &t->texture);
  if (t->framebuffer) glDeleteFramebuffers(1, &t->framebuffer);
  *t = Texture{};
}

GLuint FrameConversion::program(Transfer transfer, std::string* error) {
  GLuint& program = programs_[static_cast<int>(transfer)];
  if (program) return program;
  std::string log;
  const std::string fragment_source = fragment_shader(transfer);
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader, &log);
  const GLuint fragment = vertex ? compile(GL_FRAGMENT_SHADER, fragment_source.c_str(), &log) : 0;
  if (!vertex || !fragment) {
    if (vertex) glDeleteShader(vertex);
    *error = "the chain's conversion program for 8-bit frames did not compile: " + log;
    return 0;
  }
  program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!linked) {
    glDeleteProgram(program);
    program = 0;
    *error = "the chain's conversion program for 8-bit frames did not link";
    return 0;
  }
  if (!target_framebuffer_) glCreateFramebuffers(1, &target_framebuffer_);
  if (!vertex_array_) glCreateVertexArrays(1, &vertex_array_);
  return program;
}

bool FrameConversion::widen_color(GLuint color, uint32_t width, uint32_t height, GLuint* wide, std::string* error) {
  fit(&color_, GL_RGBA16F, width, height);
  *wide = color_.texture;
  return draw_copy(color, color_.texture, width, height, error);
}

GLuint FrameConversion::wide_output(uint32_t width, uint32_t height) {
  fit(&output_, GL_RGBA16F, width, height);
  return output_.texture;
}

GLuint FrameConversion::codes_color(uint32_t width, uint32_t height) {
  fit(&codes_color_, GL_RGBA8, width, height);
  return codes_color_.texture;
}

GLuint FrameConversion::codes_output(uint32_t width, uint32_t height) {
  fit(&codes_output_, GL_RGBA8, width, height);
  return codes_output_.texture;
}

bool FrameConversion::draw_copy(GLuint from, GLuint to, uint32_t width, uint32_t height, std::string* error,
                                Transfer transfer) {
  if (!program(transfer, error)) return false;
  glNamedFramebufferTexture(target_framebuffer_, GL_COLOR_ATTACHMENT0, to, 0);
  const bool drawn = draw_into(from, target_framebuffer_, transfer != Transfer::ENCODE, width, height, error, transfer);
  // The texture is the host's or ours, kept attached to nothing.
  glNamedFramebufferTexture(target_framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
  return drawn;
}

bool FrameConversion::draw_into(GLuint from, GLuint framebuffer, bool srgb, uint32_t width, uint32_t height,
                                std::string* error, Transfer transfer) {
  const GLuint chosen = program(transfer, error);
  if (!chosen) return false;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height));
  glDisable(GL_BLEND);
  if (srgb) glEnable(GL_FRAMEBUFFER_SRGB);
  glUseProgram(chosen);
  glBindVertexArray(vertex_array_);
  glBindTextureUnit(0, from);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Back to the state every pass starts from.
  glBindTextureUnit(0, 0);
  glUseProgram(0);
  glDisable(GL_FRAMEBUFFER_SRGB);
  return true;
}

uint64_t FrameConversion::bytes() const {
  uint64_t total = 0;
  for (const Texture* t : {&color_, &output_, &codes_color_, &codes_output_})
    if (t->texture) total += uint64_t(t->width) * t->height * t->bytes_per_texel;
  return total;
}

}  // namespace pfx::host
