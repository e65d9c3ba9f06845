#include "transfer_programs.hpp"

#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/srgb_glsl.hpp>

namespace pfx::gl {
namespace {

// The exact piecewise sRGB curves (pfx/cpp/srgb_glsl.hpp), as host/lib/image/tonemap does on the
// CPU. In 32-bit float they put every 8-bit code back on itself through the RGBA16F texture between
// them: a half holds the decoded value to 1/2048 of itself, which moves the code by at most 0.05.
const char* kDecodeMain = R"(
layout(binding = 0) uniform sampler2D display_frame;
layout(location = 0) uniform int srgb;
layout(location = 1) uniform int flip_rows;  // the frame's height, or 0: no flip
layout(location = 0) out vec4 color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  if (flip_rows != 0) texel.y = flip_rows - 1 - texel.y;
  vec4 value = texelFetch(display_frame, texel, 0);
  color = vec4(srgb != 0 ? pfx_srgb_decode(value.rgb) : value.rgb, value.a);
}
)";

// Linear light to 8-bit: clamped to [0, 1] (what an 8-bit buffer can hold; the GL rounds to the
// nearest code). Not-a-number becomes 0, so a broken pixel shows black, not whatever the
// conversion makes of it.
const char* kEncodeMain = R"(
layout(binding = 0) uniform sampler2D chain_output;
layout(location = 0) uniform int srgb;
layout(location = 1) uniform int flip_rows;  // the frame's height, or 0: no flip
layout(location = 0) out vec4 color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  if (flip_rows != 0) texel.y = flip_rows - 1 - texel.y;
  vec4 value = texelFetch(chain_output, texel, 0);
  value = clamp(mix(value, vec4(0.0), isnan(value)), 0.0, 1.0);
  color = vec4(srgb != 0 ? pfx_srgb_encode(value.rgb) : value.rgb, value.a);
}
)";

void draw(GLuint program, GLuint vertex_array, GLuint source, app::Transfer transfer, int flip_rows) {
  glUseProgram(program);
  glUniform1i(0, transfer == app::Transfer::SRGB);
  glUniform1i(1, flip_rows);
  glBindVertexArray(vertex_array);
  glBindTextureUnit(0, source);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

std::string program_source(const char* main) { return std::string("#version 450 core\n") + srgb_glsl_functions() + main; }

}  // namespace

bool TransferPrograms::create(std::string* error) {
  std::string message;
  decode_program_ = build_fullscreen_program(program_source(kDecodeMain).c_str(), &message);
  if (decode_program_) encode_program_ = build_fullscreen_program(program_source(kEncodeMain).c_str(), &message);
  if (!encode_program_) {
    *error = "the colour transfer programs did not build: " + message;
    return false;
  }
  glCreateVertexArrays(1, &vertex_array_);
  return true;
}

TransferPrograms::~TransferPrograms() {
  // Never created (or failed): there may be no GL to call.
  if (decode_program_) glDeleteProgram(decode_program_);
  if (encode_program_) glDeleteProgram(encode_program_);
  if (vertex_array_) glDeleteVertexArrays(1, &vertex_array_);
}

void TransferPrograms::decode(GLuint source, app::Transfer transfer, int flip_rows) const {
  draw(decode_program_, vertex_array_, source, transfer, flip_rows);
}

void TransferPrograms::encode(GLuint source, app::Transfer transfer, int flip_rows) const {
  draw(encode_program_, vertex_array_, source, transfer, flip_rows);
}

}  // namespace pfx::gl
