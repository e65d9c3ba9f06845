#include "lr_glsl_pass.hpp"

#include <string>

#include <pfx/cpp/gl_program.hpp>

#include "glsl_names.hpp"

namespace pfx_libretro {

using namespace pfx::libretro;

namespace {

constexpr int kFloatsPerVertex = 8;  // x, y, u, v, r, g, b, a

// Mesa's "0:12(5): error: ..." as "file:12:5: error: ...", so a message names the line written.
std::string with_file_lines(const std::string& log, const std::string& file) {
  std::string out;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(start, end - start);
    std::size_t open = line.find('('), close = line.find("):");
    if (line.compare(0, 2, "0:") == 0 && open != std::string::npos && close != std::string::npos && open < close)
      line = file + ":" + line.substr(2, open - 2) + ":" + line.substr(open + 1, close - open - 1) +
             line.substr(close + 1);
    out += line + "\n";
    start = end + 1;
  }
  return out;
}

// The GL type a value of this meaning has in the GLSL form.
GLenum value_type(SemanticKind kind) {
  switch (kind) {
    case SemanticKind::kMvp:
      return GL_FLOAT_MAT4;
    case SemanticKind::kFrameCount:
    case SemanticKind::kFrameDirection:
      return GL_INT;
    case SemanticKind::kParameter:
      return GL_FLOAT;
    default:
      return GL_FLOAT_VEC2;  // the sizes
  }
}

bool ends_with(const std::string& text, const char* end) {
  const std::size_t n = std::char_traits<char>::length(end);
  return text.size() >= n && text.compare(text.size() - n, n, end) == 0;
}

void find_uniforms(LrPass& pass, const SemanticContext& context, int feedback_pass) {
  GLint count = 0;
  glGetProgramiv(pass.program, GL_ACTIVE_UNIFORMS, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256] = "";
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(pass.program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
    std::string id = name;
    if (ends_with(id, "[0]")) id.resize(id.size() - 3);
    auto meaning = find_glsl_name(id, context, feedback_pass);
    // A sampler RetroArch does not name keeps unit 0, where its gl driver binds the pass's input
    // (Texture's unit): crt-hyllian reads its input as `s_p`.
    if (!meaning && type == GL_SAMPLER_2D) meaning = find_glsl_name("Texture", context, feedback_pass);
    const GLint location = glGetUniformLocation(pass.program, name);
    if (!meaning || location < 0) continue;  // not one RetroArch sets: left at its initial value
    if (meaning->texture) {
      if (type != GL_SAMPLER_2D) continue;
      const auto unit = static_cast<std::uint32_t>(pass.reads.samplers.size());
      glProgramUniform1i(pass.program, location, static_cast<GLint>(unit));
      pass.reads.samplers.push_back(ReflectedSampler{id, meaning->semantic, unit});
    } else if (type == value_type(meaning->semantic.kind)) {  // another type: RetroArch's glUniform fails too
      pass.glsl_values.push_back(GlslValue{location, meaning->semantic});
    }
  }
}

// A vertex array over `vertices` giving each active attribute the data its name asks for.
GLuint attribute_array(GLuint program, GLuint vertices) {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glVertexArrayVertexBuffer(vao, 0, vertices, 0, kFloatsPerVertex * sizeof(float));
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256] = "";
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
    const GLint location = glGetAttribLocation(program, name);
    const std::string id = name;
    GLuint offset = 0, components = 0;
    if (id == "VertexCoord")
      offset = 0, components = 2;
    else if (ends_with(id, "TexCoord"))
      offset = 2, components = 2;
    else if (id == "Color" || id == "COLOR")
      offset = 4, components = 4;
    if (location < 0 || components == 0) continue;  // a built-in or a name RetroArch does not feed
    const auto at = static_cast<GLuint>(location);
    glEnableVertexArrayAttrib(vao, at);
    glVertexArrayAttribFormat(vao, at, static_cast<GLint>(components), GL_FLOAT, GL_FALSE, offset * sizeof(float));
    glVertexArrayAttribBinding(vao, at, 0);
  }
  return vao;
}

}  // namespace

const std::vector<float>& glsl_vertex_data() {
  // Two strips. TexCoord (0, 0) is always the picture's first row (its top), so the picture keeps
  // its way up from pass to pass. VertexCoord is as RetroArch's gl driver gives it: for a pass into
  // a texture (0, 0) is the target's first row, the picture's top; for the pass onto the screen it
  // is turned over, y = 1 at the picture's top. A shader that makes its texture coordinates from
  // VertexCoord (cocktail-cabinet does) sees the picture the right way up only so.
  static const std::vector<float> data = {
      // into a texture of the chain
      0, 0, 0, 0, 1, 1, 1, 1, 1, 0, 1, 0, 1, 1, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
      // into the output
      0, 1, 0, 0, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1,
  };
  return data;
}

bool link_glsl_passes(const LrEffectEntry& entry, std::vector<LrPass>& passes, GLuint vertices,
                      const pfx::gl::ProgramCache& cache, int* from_cache, std::string* error) {
  const Preset& preset = entry.preset;
  SemanticContext context;
  for (const PresetPass& pass : preset.passes) context.aliases.push_back(pass.alias);
  for (const LookupTexture& texture : preset.textures) context.textures.push_back(texture.id);
  context.parameters = entry.params.shader_ids;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    LrPass& pass = passes[i];
    if (!pass.glsl) continue;
    const GLenum stages[] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    const char* sources[] = {pass.code.vertex.c_str(), pass.code.fragment.c_str()};
    std::string log;
    bool cached = false;
    pass.program = cache.build(stages, sources, 2, &log, &cached);
    *from_cache += cached ? 1 : 0;
    if (!pass.program) {
      *error = "pass " + std::to_string(i) + " (" + preset.passes[i].shader + ") does not compile:\n" +
               with_file_lines(log, preset.passes[i].shader);
      return false;
    }
    context.pass = static_cast<int>(i);
    find_uniforms(pass, context, preset.feedback_pass);
    pass.glsl_vao = attribute_array(pass.program, vertices);
  }
  return true;
}

void set_glsl_values(const LrPass& pass, const PassValues& values) {
  for (const GlslValue& value : pass.glsl_values) {
    switch (value.semantic.kind) {
      case SemanticKind::kMvp:
        glProgramUniformMatrix4fv(pass.program, value.location, 1, GL_FALSE, values.mvp);
        break;
      case SemanticKind::kFrameCount:
        glProgramUniform1i(pass.program, value.location, static_cast<GLint>(values.frame_count));
        break;
      case SemanticKind::kFrameDirection:
        glProgramUniform1i(pass.program, value.location, values.frame_direction);
        break;
      case SemanticKind::kParameter: {
        const auto k = static_cast<std::size_t>(value.semantic.index);
        const double v = values.parameters && k < values.parameters->size() ? (*values.parameters)[k] : 0.0;
        glProgramUniform1f(pass.program, value.location, static_cast<float>(v));
        break;
      }
      default: {
        const PixelSize size = semantic_size(value.semantic, values);
        glProgramUniform2f(pass.program, value.location, static_cast<float>(size.width),
                           static_cast<float>(size.height));
        break;
      }
    }
  }
}

}  // namespace pfx_libretro
