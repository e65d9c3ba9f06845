// The offsets the compiler gives an effect's uniform block (uniform_block.hpp), which the runtimes
// fill byte by byte, against the offsets a GL driver reports for the generated GLSL: std140 is
// the driver's to apply, so its answer is an independent reference. The uniforms below take the
// shapes whose std140 rules differ (a scalar after a three-vector, vectors of two, matrices of
// every size, integer matrices as arrays of rows, arrays of scalars, vectors and matrices).
#include <catch2/catch.hpp>

#include <glad/gl.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "codegen/uniform_block.hpp"
#include "effect_compiler.hpp"
#include "fx_test_support.hpp"
#include "headless_context.hpp"

namespace {

const char* const kEffect = R"(
uniform float A;
uniform float3 B;
uniform float C;
uniform bool3 D;
uniform int E;
uniform float2 F;
uniform float2 G;
uniform float4x4 H;
uniform float2x3 I;
uniform float3x2 J;
uniform int2x2 K;
uniform float L[3];
uniform float3 M[2];
uniform float3x3 N[2];
uniform uint4 O;
uniform bool P;
uniform float Q;
uniform float2 R;

void VS(uint id : SV_VertexID, out float4 position : SV_Position)
{
  position = float4(id == 2 ? 3.0 : -1.0, id == 1 ? 3.0 : -1.0, 0.0, 1.0);
}

float4 PS(float4 position : SV_Position) : SV_Target
{
  float s = A + B.x + C + (D.y ? 1.0 : 0.0) + E + F.y + G.x + H[3][2] + I[1][2] + J[2][1] + K[1][0]
          + L[2] + M[1].z + N[1][2][1] + O.w + (P ? 1.0 : 0.0) + Q + R.y;
  return s;
}

technique T { pass { VertexShader = VS; PixelShader = PS; } }
)";

// The member names of the block, in order, as the generated GLSL declares them.
std::vector<std::string> block_members(const std::string& glsl) {
  std::vector<std::string> names;
  std::istringstream lines(glsl.substr(glsl.find("uniform pfx_uniforms {")));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line) && line != "};") {
    std::string name = line.substr(line.rfind(' ') + 1);
    name = name.substr(0, name.find_first_of("[;"));
    names.push_back(name);
  }
  return names;
}

GLuint compile_stage(GLenum stage, const std::string& source) {
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  char log[2048] = "";
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  INFO(log << "\n" << source);
  REQUIRE(ok);
  return shader;
}

struct Reported {
  GLint offset = -1, array_stride = -1, matrix_stride = -1;
};

Reported reported(GLuint program, const std::string& name, bool array) {
  Reported r;
  const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, (array ? name + "[0]" : name).c_str());
  if (index == GL_INVALID_INDEX) return r;
  const GLenum properties[3] = {GL_OFFSET, GL_ARRAY_STRIDE, GL_MATRIX_STRIDE};
  GLint values[3] = {-1, -1, -1};
  glGetProgramResourceiv(program, GL_UNIFORM, index, 3, properties, 3, nullptr, values);
  r.offset = values[0], r.array_stride = values[1], r.matrix_stride = values[2];
  return r;
}

}  // namespace

TEST_CASE("the compiler's uniform block offsets are the ones GL's std140 gives the generated GLSL",
          "[fx][gl][uniforms]") {
  std::string error;
  auto context = pfx::app::HeadlessContext::create(&error);
  INFO(error);
  REQUIRE(context);

  pfx::fx::test::MemoryFiles files;
  files.files["block.fx"] = kEffect;
  auto compiled = pfx::fx::compile_effect("block.fx", {}, true, files.reader());
  INFO(compiled->errors());
  REQUIRE(compiled->ok());
  const pfx::fx::GeneratedPass& pass = compiled->passes.at(0).at(0);
  const pfx::fx::EffectModel& model = compiled->model;
  REQUIRE(pass.uniforms.size() == model.uniforms.size());  // every uniform is read, none compiled in

  GLuint program = glCreateProgram();
  GLuint vertex = compile_stage(GL_VERTEX_SHADER, pass.vertex),
         fragment = compile_stage(GL_FRAGMENT_SHADER, pass.fragment);
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  REQUIRE(linked);

  const pfx::fx::UniformBlockLayout layout = pfx::fx::layout_uniform_block(model);
  const std::vector<std::string> members = block_members(pass.fragment);
  REQUIRE(members.size() == model.uniforms.size());
  for (std::size_t i = 0; i < model.uniforms.size(); ++i) {
    const pfx::fx::Type& type = model.uniforms[i].type;
    const bool matrix = type.shape == pfx::fx::Shape::kMatrix,
               float_matrix = matrix && type.base == pfx::fx::BaseType::kFloat;
    // An integer matrix is declared as an array of its rows (GLSL has no integer matrices).
    const bool array = type.is_array() || (matrix && !float_matrix);
    const Reported gl = reported(program, members[i], array);
    INFO(model.uniforms[i].name << " (" << members[i] << ")");
    REQUIRE(gl.offset >= 0);
    CHECK(static_cast<std::size_t>(gl.offset) == layout.offsets[i]);
    if (array) CHECK(gl.array_stride == (float_matrix ? 16 * type.rows : 16));
    if (float_matrix) CHECK(gl.matrix_stride == 16);
  }
  const GLuint block = glGetProgramResourceIndex(program, GL_UNIFORM_BLOCK, "pfx_uniforms");
  REQUIRE(block != GL_INVALID_INDEX);
  const GLenum size_property = GL_BUFFER_DATA_SIZE;
  GLint size = 0;
  glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, block, 1, &size_property, 1, nullptr, &size);
  CHECK(static_cast<std::size_t>(size) <= layout.size);  // the buffer the runtimes make holds the block
  CHECK(layout.size % 16 == 0);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  glDeleteProgram(program);
}
