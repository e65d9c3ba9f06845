#include "dirty_gl_state.hpp"

#include <initializer_list>
#include <utility>
#include <vector>

#include "dirty_gl_read.hpp"

namespace pfx::app {

using namespace dirty_gl;

namespace {

GLuint compile_program() {
  const char* vertex = "#version 450 core\nvoid main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n";
  const char* fragment = "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(1.0, 0.0, 1.0, 1.0); }\n";
  const GLuint program = glCreateProgram();
  for (auto [type, source] : {std::pair{GL_VERTEX_SHADER, vertex}, std::pair{GL_FRAGMENT_SHADER, fragment}}) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glDeleteShader(shader);
  }
  glLinkProgram(program);
  return program;
}

// The values of several glGets, one after another.
std::vector<double> joined(std::initializer_list<std::vector<double>> parts) {
  std::vector<double> v;
  for (const std::vector<double>& part : parts) append(&v, part);
  return v;
}

// State kept per viewport or per draw buffer, read at every index.
std::vector<double> read_scissor_tests() {
  std::vector<double> v;
  for (GLuint i = 0; i < kViewports; ++i) v.push_back(glIsEnabledi(GL_SCISSOR_TEST, i));
  return v;
}

std::vector<double> read_colour_masks() {
  std::vector<double> v;
  for (GLuint i = 0; i < kDrawBuffers; ++i) {
    GLboolean m[4] = {};
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, m);
    v.insert(v.end(), {double(m[0]), double(m[1]), double(m[2]), double(m[3])});
  }
  return v;
}

std::vector<double> read_blending() {
  const std::initializer_list<GLenum> equations_and_factors = {GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA,
                                                               GL_BLEND_SRC_RGB,      GL_BLEND_DST_RGB,
                                                               GL_BLEND_SRC_ALPHA,    GL_BLEND_DST_ALPHA};
  std::vector<double> v = get_floats(GL_BLEND_COLOR, 4);
  for (GLuint i = 0; i < kDrawBuffers; ++i) {
    v.push_back(glIsEnabledi(GL_BLEND, i));
    append(&v, get_integers_at(equations_and_factors, i));
  }
  return v;
}

std::vector<double> read_viewports() {
  std::vector<double> v;
  for (GLuint i = 0; i < kViewports; ++i) {
    GLfloat box[4] = {};
    glGetFloati_v(GL_VIEWPORT, i, box);
    GLdouble range[2] = {};
    glGetDoublei_v(GL_DEPTH_RANGE, i, range);
    v.insert(v.end(), {box[0], box[1], box[2], box[3], range[0], range[1]});
  }
  return v;
}

// One item of rasteriser and fragment state. Most are capabilities an engine leaves on together
// with the values that go with them: the capabilities are switched before the values are set, and
// read before them.
struct FragmentItem {
  const char* name;
  GLenum caps[3];                 // on for the engine, off in a fresh context; 0: none
  void (*dirty)();                // the engine's leftover values
  void (*clean)();                // a fresh context's values
  std::vector<double> (*read)();  // the values dirty sets, as glGet reads them; null: the caps say it all
};

constexpr FragmentItem kFragmentItems[] = {
    {"glPolygonMode(GL_LINE)",
     {},
     [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); },
     [] { glPolygonMode(GL_FRONT_AND_BACK, GL_FILL); },
     [] { return get_integers({GL_POLYGON_MODE}); }},
    {"GL_COLOR_LOGIC_OP with GL_XOR",
     {GL_COLOR_LOGIC_OP},
     [] { glLogicOp(GL_XOR); },
     [] { glLogicOp(GL_COPY); },
     [] { return get_integers({GL_LOGIC_OP_MODE}); }},
    {"glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE)",
     {},
     [] { glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); },
     [] { glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE); },
     [] {
       return get_integers({GL_CLIP_ORIGIN, GL_CLIP_DEPTH_MODE});
     }},
    {"GL_SAMPLE_COVERAGE 0.25 inverted",
     {GL_SAMPLE_COVERAGE},
     [] { glSampleCoverage(0.25f, GL_TRUE); },
     [] { glSampleCoverage(1.0f, GL_FALSE); },
     [] {
       return joined({get_floats(GL_SAMPLE_COVERAGE_VALUE, 1), get_integers({GL_SAMPLE_COVERAGE_INVERT})});
     }},
    {"GL_SAMPLE_MASK 0",
     {GL_SAMPLE_MASK},
     [] { glSampleMaski(0, 0); },
     [] { glSampleMaski(0, ~0u); },
     [] { return get_integers_at({GL_SAMPLE_MASK_VALUE}, 0); }},
    {"GL_SAMPLE_SHADING 1.0",
     {GL_SAMPLE_SHADING},
     [] { glMinSampleShading(1.0f); },
     [] { glMinSampleShading(0.0f); },
     [] { return get_floats(GL_MIN_SAMPLE_SHADING_VALUE, 1); }},
    {"GL_PRIMITIVE_RESTART at index 0",
     {GL_PRIMITIVE_RESTART},
     [] { glPrimitiveRestartIndex(0); },
     [] { glPrimitiveRestartIndex(0); },
     [] { return get_integers({GL_PRIMITIVE_RESTART_INDEX}); }},
    {"glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)",
     {},
     [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); },
     [] { glProvokingVertex(GL_LAST_VERTEX_CONVENTION); },
     [] { return get_integers({GL_PROVOKING_VERTEX}); }},
    {"point size 7, sprites from the lower left",
     {},
     [] {
       glPointSize(7.0f);
       glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
     },
     [] {
       glPointSize(1.0f);
       glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
     },
     [] {
       return joined({get_floats(GL_POINT_SIZE, 1), get_integers({GL_POINT_SPRITE_COORD_ORIGIN})});
     }},
    {"polygon offset 4, 4 on fill, line and point",
     {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT},
     [] { glPolygonOffset(4.0f, 4.0f); },
     [] { glPolygonOffset(0.0f, 0.0f); },
     nullptr},
    {"stencil test on, func GL_NEVER, ops GL_ZERO, masks 0",
     {GL_STENCIL_TEST},
     [] {
       glStencilFunc(GL_NEVER, 1, 0);
       glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
       glStencilMask(0);
     },
     [] {
       glStencilFunc(GL_ALWAYS, 0, ~0u);
       glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
       glStencilMask(~0u);
     },
     [] {
       return get_integers({GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
                            GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK,
                            GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_WRITEMASK});
     }},
    {"depth test on, func GL_NEVER, no depth writes",
     {GL_DEPTH_TEST},
     [] {
       glDepthFunc(GL_NEVER);
       glDepthMask(GL_FALSE);
     },
     [] {
       glDepthFunc(GL_LESS);
       glDepthMask(GL_TRUE);
     },
     [] {
       return get_integers({GL_DEPTH_FUNC, GL_DEPTH_WRITEMASK});
     }},
    // Switched with glEnable but read per viewport, so not one of the caps.
    {"scissor test on with a 1x1 box",
     {},
     [] {
       glEnable(GL_SCISSOR_TEST);
       glScissor(1, 1, 1, 1);
     },
     [] {
       glDisable(GL_SCISSOR_TEST);
       glScissor(0, 0, 0, 0);
     },
     read_scissor_tests},
    {"cull front and back faces, front face GL_CW",
     {GL_CULL_FACE},
     [] {
       glCullFace(GL_FRONT_AND_BACK);
       glFrontFace(GL_CW);
     },
     [] {
       glCullFace(GL_BACK);
       glFrontFace(GL_CCW);
     },
     [] {
       return get_integers({GL_CULL_FACE_MODE, GL_FRONT_FACE});
     }},
    {"colour mask off on every draw buffer",
     {},
     [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); },
     [] { glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); },
     read_colour_masks},
    // GL_BLEND is read per draw buffer, after the blend colour, so it is not one of the caps either.
    {"blending on: GL_FUNC_REVERSE_SUBTRACT/GL_MAX, GL_DST_COLOR/GL_ZERO, a blend colour",
     {},
     [] {
       glEnable(GL_BLEND);
       glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
       glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_CONSTANT_ALPHA, GL_SRC_ALPHA);
       glBlendFunci(3, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA_SATURATE);
       glBlendColor(0.5f, 0.25f, 0.125f, 0.75f);
     },
     [] {
       glDisable(GL_BLEND);
       glBlendEquation(GL_FUNC_ADD);
       glBlendFunc(GL_ONE, GL_ZERO);
       glBlendColor(0, 0, 0, 0);
     },
     read_blending},
    {"viewports (3, 5, 7, 9) and (1, 2, 3, 4) at index 2, depth range 0.25..0.5",
     {},
     [] {
       glViewport(3, 5, 7, 9);
       glViewportIndexedf(2, 1, 2, 3, 4);
       glDepthRange(0.25, 0.5);
     },
     [] {
       glViewport(0, 0, 1, 1);
       glDepthRange(0.0, 1.0);
     },
     read_viewports},
    {"clear colour (1, 0, 1, 0.5), depth 0.5, stencil 3",
     {},
     [] {
       glClearColor(1, 0, 1, 0.5f);
       glClearDepth(0.5);
       glClearStencil(3);
     },
     [] {
       glClearColor(0, 0, 0, 0);
       glClearDepth(1.0);
       glClearStencil(0);
     },
     [] {
       return joined({get_floats(GL_COLOR_CLEAR_VALUE, 4), get_floats(GL_DEPTH_CLEAR_VALUE, 1),
                      get_integers({GL_STENCIL_CLEAR_VALUE})});
     }},
    {"glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE)",
     {},
     [] { glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE); },
     [] { glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY); },
     [] { return get_integers({GL_CLAMP_READ_COLOR}); }},
    {"derivative hint GL_FASTEST",
     {},
     [] { glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST); },
     [] { glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE); },
     [] { return get_integers({GL_FRAGMENT_SHADER_DERIVATIVE_HINT}); }},
    {"patches of 4 vertices",
     {},
     [] { glPatchParameteri(GL_PATCH_VERTICES, 4); },
     [] { glPatchParameteri(GL_PATCH_VERTICES, 3); },
     [] { return get_integers({GL_PATCH_VERTICES}); }},
};

}  // namespace

DirtyGlState::DirtyGlState() {
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, 4096, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
  glTextureStorage2D(texture_, 1, GL_RGBA8, 4, 4);
  const GLubyte orange[4] = {255, 128, 0, 255};
  glClearTexImage(texture_, 0, GL_RGBA, GL_UNSIGNED_BYTE, orange);
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &cube_texture_);
  glTextureStorage2D(cube_texture_, 1, GL_RGBA8, 4, 4);
  glCreateSamplers(1, &sampler_);
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glSamplerParameterf(sampler_, GL_TEXTURE_LOD_BIAS, 3.0f);
  glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  program_ = compile_program();
  glCreateProgramPipelines(1, &pipeline_);
  glCreateVertexArrays(1, &vertex_array_);
  glVertexArrayElementBuffer(vertex_array_, buffer_);
  glVertexArrayVertexBuffer(vertex_array_, 0, buffer_, 0, 16);
  glEnableVertexArrayAttrib(vertex_array_, 0);
  glCreateRenderbuffers(1, &renderbuffer_);
  glNamedRenderbufferStorage(renderbuffer_, GL_RGBA8, 8, 8);
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferRenderbuffer(framebuffer_, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer_);
  glCreateTransformFeedbacks(1, &feedback_);
  add_capabilities();
  add_fragment_state();
  add_pixel_store();
  add_bindings();
}

DirtyGlState::~DirtyGlState() {
  glDeleteTransformFeedbacks(1, &feedback_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteRenderbuffers(1, &renderbuffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgramPipelines(1, &pipeline_);
  glDeleteProgram(program_);
  glDeleteSamplers(1, &sampler_);
  glDeleteTextures(1, &cube_texture_);
  glDeleteTextures(1, &texture_);
  glDeleteBuffers(1, &buffer_);
}

void DirtyGlState::make_all_dirty() const {
  for (const DirtyGlItem& item : items_) item.make_dirty();
}

void DirtyGlState::make_all_clean() const {
  for (const DirtyGlItem& item : items_) item.make_clean();
}

std::vector<std::vector<double>> DirtyGlState::read_all() const {
  std::vector<std::vector<double>> values;
  for (const DirtyGlItem& item : items_) values.push_back(item.read());
  return values;
}

void DirtyGlState::add_capabilities() {
  // Capabilities an engine may leave switched the other way from a fresh context.
  const std::pair<GLenum, const char*> on[] = {
      {GL_RASTERIZER_DISCARD, "GL_RASTERIZER_DISCARD"},
      {GL_FRAMEBUFFER_SRGB, "GL_FRAMEBUFFER_SRGB"},
      {GL_SAMPLE_ALPHA_TO_COVERAGE, "GL_SAMPLE_ALPHA_TO_COVERAGE"},
      {GL_SAMPLE_ALPHA_TO_ONE, "GL_SAMPLE_ALPHA_TO_ONE"},
      {GL_PRIMITIVE_RESTART_FIXED_INDEX, "GL_PRIMITIVE_RESTART_FIXED_INDEX"},
      {GL_DEPTH_CLAMP, "GL_DEPTH_CLAMP"},
      {GL_POLYGON_SMOOTH, "GL_POLYGON_SMOOTH"},
      {GL_LINE_SMOOTH, "GL_LINE_SMOOTH"},
      {GL_PROGRAM_POINT_SIZE, "GL_PROGRAM_POINT_SIZE"},
      {GL_TEXTURE_CUBE_MAP_SEAMLESS, "GL_TEXTURE_CUBE_MAP_SEAMLESS"},
  };
  for (const auto& [cap, name] : on)
    items_.push_back({std::string(name) + " on", [cap = cap] { glEnable(cap); }, [cap = cap] { glDisable(cap); },
                      [cap = cap] { return get_enabled({cap}); }});
  const std::pair<GLenum, const char*> off[] = {{GL_MULTISAMPLE, "GL_MULTISAMPLE"}, {GL_DITHER, "GL_DITHER"}};
  for (const auto& [cap, name] : off)
    items_.push_back({std::string(name) + " off", [cap = cap] { glDisable(cap); }, [cap = cap] { glEnable(cap); },
                      [cap = cap] { return get_enabled({cap}); }});
  items_.push_back({"GL_CLIP_DISTANCE0..7 on",
                    [] {
                      for (GLuint i = 0; i < kClipDistances; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
                    },
                    [] {
                      for (GLuint i = 0; i < kClipDistances; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
                    },
                    [] {
                      std::vector<double> v;
                      for (GLuint i = 0; i < kClipDistances; ++i) v.push_back(glIsEnabled(GL_CLIP_DISTANCE0 + i));
                      return v;
                    }});
}

void DirtyGlState::add_fragment_state() {
  for (const FragmentItem& entry : kFragmentItems) {
    const FragmentItem* f = &entry;  // the table outlives every item
    items_.push_back({f->name,
                      [f] {
                        for (GLenum cap : f->caps)
                          if (cap) glEnable(cap);
                        f->dirty();
                      },
                      [f] {
                        for (GLenum cap : f->caps)
                          if (cap) glDisable(cap);
                        f->clean();
                      },
                      [f] {
                        std::vector<double> v;
                        for (GLenum cap : f->caps)
                          if (cap) v.push_back(glIsEnabled(cap));
                        if (f->read) append(&v, f->read());
                        return v;
                      }});
  }
}

}  // namespace pfx::app
