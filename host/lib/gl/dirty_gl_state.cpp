#include "dirty_gl_state.hpp"

#include <utility>

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
  items_.push_back({"glPolygonMode(GL_LINE)", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); },
                    [] { glPolygonMode(GL_FRONT_AND_BACK, GL_FILL); }, [] { return get_integers({GL_POLYGON_MODE}); }});
  items_.push_back({"GL_COLOR_LOGIC_OP with GL_XOR",
                    [] {
                      glEnable(GL_COLOR_LOGIC_OP);
                      glLogicOp(GL_XOR);
                    },
                    [] {
                      glDisable(GL_COLOR_LOGIC_OP);
                      glLogicOp(GL_COPY);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_COLOR_LOGIC_OP});
                      append(&v, get_integers({GL_LOGIC_OP_MODE}));
                      return v;
                    }});
  items_.push_back({"glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE)", [] { glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); },
                    [] { glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE); },
                    [] { return get_integers({GL_CLIP_ORIGIN, GL_CLIP_DEPTH_MODE}); }});
  items_.push_back({"GL_SAMPLE_COVERAGE 0.25 inverted",
                    [] {
                      glEnable(GL_SAMPLE_COVERAGE);
                      glSampleCoverage(0.25f, GL_TRUE);
                    },
                    [] {
                      glDisable(GL_SAMPLE_COVERAGE);
                      glSampleCoverage(1.0f, GL_FALSE);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_SAMPLE_COVERAGE});
                      append(&v, get_floats(GL_SAMPLE_COVERAGE_VALUE, 1));
                      append(&v, get_integers({GL_SAMPLE_COVERAGE_INVERT}));
                      return v;
                    }});
  items_.push_back({"GL_SAMPLE_MASK 0",
                    [] {
                      glEnable(GL_SAMPLE_MASK);
                      glSampleMaski(0, 0);
                    },
                    [] {
                      glDisable(GL_SAMPLE_MASK);
                      glSampleMaski(0, ~0u);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_SAMPLE_MASK});
                      GLint mask = 0;
                      glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
                      v.push_back(mask);
                      return v;
                    }});
  items_.push_back({"GL_SAMPLE_SHADING 1.0",
                    [] {
                      glEnable(GL_SAMPLE_SHADING);
                      glMinSampleShading(1.0f);
                    },
                    [] {
                      glDisable(GL_SAMPLE_SHADING);
                      glMinSampleShading(0.0f);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_SAMPLE_SHADING});
                      append(&v, get_floats(GL_MIN_SAMPLE_SHADING_VALUE, 1));
                      return v;
                    }});
  items_.push_back({"GL_PRIMITIVE_RESTART at index 0",
                    [] {
                      glEnable(GL_PRIMITIVE_RESTART);
                      glPrimitiveRestartIndex(0);
                    },
                    [] {
                      glDisable(GL_PRIMITIVE_RESTART);
                      glPrimitiveRestartIndex(0);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_PRIMITIVE_RESTART});
                      append(&v, get_integers({GL_PRIMITIVE_RESTART_INDEX}));
                      return v;
                    }});
  items_.push_back({"glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)", [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); },
                    [] { glProvokingVertex(GL_LAST_VERTEX_CONVENTION); }, [] { return get_integers({GL_PROVOKING_VERTEX}); }});
  items_.push_back({"point size 7, sprites from the lower left",
                    [] {
                      glPointSize(7.0f);
                      glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
                    },
                    [] {
                      glPointSize(1.0f);
                      glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
                    },
                    [] {
                      std::vector<double> v = get_floats(GL_POINT_SIZE, 1);
                      append(&v, get_integers({GL_POINT_SPRITE_COORD_ORIGIN}));
                      return v;
                    }});
  items_.push_back({"polygon offset 4, 4 on fill, line and point",
                    [] {
                      for (GLenum cap : {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}) glEnable(cap);
                      glPolygonOffset(4.0f, 4.0f);
                    },
                    [] {
                      for (GLenum cap : {GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}) glDisable(cap);
                      glPolygonOffset(0.0f, 0.0f);
                    },
                    [] { return get_enabled({GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT}); }});
  items_.push_back({"stencil test on, func GL_NEVER, ops GL_ZERO, masks 0",
                    [] {
                      glEnable(GL_STENCIL_TEST);
                      glStencilFunc(GL_NEVER, 1, 0);
                      glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
                      glStencilMask(0);
                    },
                    [] {
                      glDisable(GL_STENCIL_TEST);
                      glStencilFunc(GL_ALWAYS, 0, ~0u);
                      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
                      glStencilMask(~0u);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_STENCIL_TEST});
                      append(&v, get_integers({GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
                                               GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK,
                                               GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_WRITEMASK}));
                      return v;
                    }});
  items_.push_back({"depth test on, func GL_NEVER, no depth writes",
                    [] {
                      glEnable(GL_DEPTH_TEST);
                      glDepthFunc(GL_NEVER);
                      glDepthMask(GL_FALSE);
                    },
                    [] {
                      glDisable(GL_DEPTH_TEST);
                      glDepthFunc(GL_LESS);
                      glDepthMask(GL_TRUE);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_DEPTH_TEST});
                      append(&v, get_integers({GL_DEPTH_FUNC, GL_DEPTH_WRITEMASK}));
                      return v;
                    }});
  items_.push_back({"scissor test on with a 1x1 box",
                    [] {
                      glEnable(GL_SCISSOR_TEST);
                      glScissor(1, 1, 1, 1);
                    },
                    [] {
                      glDisable(GL_SCISSOR_TEST);
                      glScissor(0, 0, 0, 0);
                    },
                    [] {
                      std::vector<double> v;
                      for (GLuint i = 0; i < kViewports; ++i) v.push_back(glIsEnabledi(GL_SCISSOR_TEST, i));
                      return v;
                    }});
  items_.push_back({"cull front and back faces, front face GL_CW",
                    [] {
                      glEnable(GL_CULL_FACE);
                      glCullFace(GL_FRONT_AND_BACK);
                      glFrontFace(GL_CW);
                    },
                    [] {
                      glDisable(GL_CULL_FACE);
                      glCullFace(GL_BACK);
                      glFrontFace(GL_CCW);
                    },
                    [] {
                      std::vector<double> v = get_enabled({GL_CULL_FACE});
                      append(&v, get_integers({GL_CULL_FACE_MODE, GL_FRONT_FACE}));
                      return v;
                    }});
  items_.push_back({"colour mask off on every draw buffer", [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); },
                    [] { glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); },
                    [] {
                      std::vector<double> v;
                      for (GLuint i = 0; i < kDrawBuffers; ++i) {
                        GLboolean m[4] = {};
                        glGetBooleani_v(GL_COLOR_WRITEMASK, i, m);
                        v.insert(v.end(), {double(m[0]), double(m[1]), double(m[2]), double(m[3])});
                      }
                      return v;
                    }});
  items_.push_back({"blending on: GL_FUNC_REVERSE_SUBTRACT/GL_MAX, GL_DST_COLOR/GL_ZERO, a blend colour",
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
                    [] {
                      std::vector<double> v = get_floats(GL_BLEND_COLOR, 4);
                      for (GLuint i = 0; i < kDrawBuffers; ++i) {
                        v.push_back(glIsEnabledi(GL_BLEND, i));
                        for (GLenum pname : {GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA, GL_BLEND_SRC_RGB,
                                             GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA}) {
                          GLint value = 0;
                          glGetIntegeri_v(pname, i, &value);
                          v.push_back(value);
                        }
                      }
                      return v;
                    }});
  items_.push_back({"viewports (3, 5, 7, 9) and (1, 2, 3, 4) at index 2, depth range 0.25..0.5",
                    [] {
                      glViewport(3, 5, 7, 9);
                      glViewportIndexedf(2, 1, 2, 3, 4);
                      glDepthRange(0.25, 0.5);
                    },
                    [] {
                      glViewport(0, 0, 1, 1);
                      glDepthRange(0.0, 1.0);
                    },
                    [] {
                      std::vector<double> v;
                      for (GLuint i = 0; i < kViewports; ++i) {
                        GLfloat box[4] = {};
                        glGetFloati_v(GL_VIEWPORT, i, box);
                        GLdouble range[2] = {};
                        glGetDoublei_v(GL_DEPTH_RANGE, i, range);
                        v.insert(v.end(), {box[0], box[1], box[2], box[3], range[0], range[1]});
                      }
                      return v;
                    }});
  items_.push_back({"clear colour (1, 0, 1, 0.5), depth 0.5, stencil 3",
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
                      std::vector<double> v = get_floats(GL_COLOR_CLEAR_VALUE, 4);
                      append(&v, get_floats(GL_DEPTH_CLEAR_VALUE, 1));
                      append(&v, get_integers({GL_STENCIL_CLEAR_VALUE}));
                      return v;
                    }});
  items_.push_back({"glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE)", [] { glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE); },
                    [] { glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY); },
                    [] { return get_integers({GL_CLAMP_READ_COLOR}); }});
  items_.push_back({"derivative hint GL_FASTEST", [] { glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST); },
                    [] { glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE); },
                    [] { return get_integers({GL_FRAGMENT_SHADER_DERIVATIVE_HINT}); }});
  items_.push_back({"patches of 4 vertices", [] { glPatchParameteri(GL_PATCH_VERTICES, 4); },
                    [] { glPatchParameteri(GL_PATCH_VERTICES, 3); }, [] { return get_integers({GL_PATCH_VERTICES}); }});
}

}  // namespace pfx::app
