#include "fx_gl_objects.hpp"

namespace pfx_fx {

using pfx::fx::TextureFormat;

GlFormat gl_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::kR8: return {GL_R8, 0};
    case TextureFormat::kR16: return {GL_R16, 0};
    case TextureFormat::kR16F: return {GL_R16F, 0};
    case TextureFormat::kR32F: return {GL_R32F, 0};
    case TextureFormat::kR32I: return {GL_R32I, 0};
    case TextureFormat::kR32U: return {GL_R32UI, 0};
    case TextureFormat::kRG8: return {GL_RG8, 0};
    case TextureFormat::kRG16: return {GL_RG16, 0};
    case TextureFormat::kRG16F: return {GL_RG16F, 0};
    case TextureFormat::kRG32F: return {GL_RG32F, 0};
    case TextureFormat::kRGBA8: return {GL_RGBA8, GL_SRGB8_ALPHA8};
    case TextureFormat::kRGBA16: return {GL_RGBA16, 0};
    case TextureFormat::kRGBA16F: return {GL_RGBA16F, 0};
    case TextureFormat::kRGBA32F: return {GL_RGBA32F, 0};
    case TextureFormat::kRGB10A2: return {GL_RGB10_A2, 0};
  }
  return {GL_RGBA8, GL_SRGB8_ALPHA8};
}

namespace {

bool finish(GlTexture& t, GLenum srgb_internal, std::string& error) {
  // Zero everywhere, as ReShade creates textures; an integer format is cleared with integers.
  bool integral = t.internal == GL_R32I || t.internal == GL_R32UI;
  const GLuint zeros[4] = {0, 0, 0, 0};
  for (int level = 0; level < t.levels; ++level)
    glClearTexImage(t.texture, level, integral ? GL_RED_INTEGER : GL_RGBA,
                    integral ? (t.internal == GL_R32I ? GL_INT : GL_UNSIGNED_INT) : GL_FLOAT, zeros);
  if (srgb_internal) {
    glGenTextures(1, &t.srgb_view);  // a view needs a name never bound: glGen, not glCreate
    glTextureView(t.srgb_view, t.target, t.texture, srgb_internal, 0, static_cast<GLuint>(t.levels), 0, 1);
  }
  GLenum status = glGetError();
  if (status != GL_NO_ERROR) {
    error = "GL error " + std::to_string(status) + " creating a texture";
    return false;
  }
  return true;
}

}  // namespace

bool create_texture(const pfx::fx::TextureInfo& info, GlTexture& out, std::string& error) {
  GlFormat f = gl_format(info.format);
  out.width = info.width, out.height = info.height, out.depth = info.depth, out.levels = info.mip_levels;
  out.internal = f.internal;
  out.target = info.dimension == 1 ? GL_TEXTURE_1D : info.dimension == 3 ? GL_TEXTURE_3D : GL_TEXTURE_2D;
  glCreateTextures(out.target, 1, &out.texture);
  if (info.dimension == 1) glTextureStorage1D(out.texture, out.levels, out.internal, out.width);
  else if (info.dimension == 3) glTextureStorage3D(out.texture, out.levels, out.internal, out.width, out.height, out.depth);
  else glTextureStorage2D(out.texture, out.levels, out.internal, out.width, out.height);
  return finish(out, info.dimension == 2 ? f.srgb_internal : 0, error);
}

bool create_texture_2d(int width, int height, GLenum internal, GLenum srgb_internal, GlTexture& out, std::string& error) {
  out.width = width, out.height = height, out.depth = 1, out.levels = 1, out.internal = internal, out.target = GL_TEXTURE_2D;
  glCreateTextures(GL_TEXTURE_2D, 1, &out.texture);
  glTextureStorage2D(out.texture, 1, internal, width, height);
  return finish(out, srgb_internal, error);
}

void delete_texture(GlTexture& t) {
  if (t.srgb_view) glDeleteTextures(1, &t.srgb_view);
  if (t.texture) glDeleteTextures(1, &t.texture);
  t.texture = t.srgb_view = 0;
}

namespace {

GLenum gl_address(pfx::fx::AddressMode mode) {
  switch (mode) {
    case pfx::fx::AddressMode::kMirror: return GL_MIRRORED_REPEAT;
    case pfx::fx::AddressMode::kWrap: return GL_REPEAT;
    case pfx::fx::AddressMode::kBorder: return GL_CLAMP_TO_BORDER;
    case pfx::fx::AddressMode::kClamp: break;
  }
  return GL_CLAMP_TO_EDGE;
}

}  // namespace

GLuint create_sampler(const pfx::fx::SamplerInfo& info, int texture_levels, bool integer_texture) {
  using pfx::fx::FilterMode;
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl_address(info.address[0])));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl_address(info.address[1])));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_R, static_cast<GLint>(gl_address(info.address[2])));
  bool min_linear = !integer_texture && info.min_filter == FilterMode::kLinear;
  bool mip_linear = !integer_texture && info.mip_filter == FilterMode::kLinear;
  // A texture of one level samples it whatever the mip filter says, as in Direct3D.
  GLenum min = texture_levels <= 1 ? (min_linear ? GL_LINEAR : GL_NEAREST)
               : min_linear        ? (mip_linear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST)
                                   : (mip_linear ? GL_NEAREST_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, !integer_texture && info.mag_filter == FilterMode::kLinear ? GL_LINEAR : GL_NEAREST);
  glSamplerParameterf(sampler, GL_TEXTURE_MIN_LOD, info.min_lod);
  glSamplerParameterf(sampler, GL_TEXTURE_MAX_LOD, info.max_lod);
  glSamplerParameterf(sampler, GL_TEXTURE_LOD_BIAS, info.lod_bias);
  const float transparent_black[4] = {0, 0, 0, 0};
  glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, transparent_black);
  return sampler;
}

GLenum gl_blend_op(pfx::fx::BlendOp op) {
  switch (op) {
    case pfx::fx::BlendOp::kSubtract: return GL_FUNC_SUBTRACT;
    case pfx::fx::BlendOp::kRevSubtract: return GL_FUNC_REVERSE_SUBTRACT;
    case pfx::fx::BlendOp::kMin: return GL_MIN;
    case pfx::fx::BlendOp::kMax: return GL_MAX;
    case pfx::fx::BlendOp::kAdd: break;
  }
  return GL_FUNC_ADD;
}

GLenum gl_blend_factor(pfx::fx::BlendFactor factor) {
  using F = pfx::fx::BlendFactor;
  switch (factor) {
    case F::kZero: return GL_ZERO;
    case F::kOne: return GL_ONE;
    case F::kSrcColor: return GL_SRC_COLOR;
    case F::kSrcAlpha: return GL_SRC_ALPHA;
    case F::kInvSrcColor: return GL_ONE_MINUS_SRC_COLOR;
    case F::kInvSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
    case F::kDestColor: return GL_DST_COLOR;
    case F::kDestAlpha: return GL_DST_ALPHA;
    case F::kInvDestColor: return GL_ONE_MINUS_DST_COLOR;
    case F::kInvDestAlpha: return GL_ONE_MINUS_DST_ALPHA;
  }
  return GL_ONE;
}

GLenum gl_topology(pfx::fx::Topology topology) {
  switch (topology) {
    case pfx::fx::Topology::kPointList: return GL_POINTS;
    case pfx::fx::Topology::kLineList: return GL_LINES;
    case pfx::fx::Topology::kLineStrip: return GL_LINE_STRIP;
    case pfx::fx::Topology::kTriangleStrip: return GL_TRIANGLE_STRIP;
    case pfx::fx::Topology::kTriangleList: break;
  }
  return GL_TRIANGLES;
}

}  // namespace pfx_fx
